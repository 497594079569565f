//! `Rat` against the reference `BigRational`: every operation, on small values, on values at
//! the edges of a machine word (i64::MIN, i64::MAX, products that overflow) and on big ones.

use super::*;
use proptest::prelude::*;

fn big(n: i128, d: i128) -> BigRational {
    BigRational::new(BigInt::from(n), BigInt::from(d))
}

/// The value through `BigRational`, the reference.
fn rat(q: &BigRational) -> Rat {
    Rat::from_big(q.clone())
}

/// Whether a value is stored as the invariants say: inline exactly when it fits.
fn canonical(x: &Rat) -> bool {
    let q = x.to_big();
    let fits = q.numer().to_i64().is_some_and(|n| n != i64::MIN) && q.denom().to_i64().is_some();
    fits == x.as_small().is_some()
}

/// Integers from every range that matters: tiny, near the word's edges, and beyond.
fn integer() -> impl Strategy<Value = i128> {
    prop_oneof![
        -20i128..20,
        any::<i32>().prop_map(i128::from),
        any::<i64>().prop_map(i128::from),
        Just(i128::from(i64::MIN)),
        Just(i128::from(i64::MAX)),
        Just(i128::from(i64::MIN) + 1),
        (-3i128..3).prop_map(|k| (1i128 << 63) + k),
        (-3i128..3).prop_map(|k| -(1i128 << 63) + k),
        any::<i128>().prop_map(|x| x >> 20),
    ]
}

fn nonzero() -> impl Strategy<Value = i128> {
    integer().prop_map(|d| if d == 0 { 1 } else { d })
}

/// Rationals as pairs p/q of those integers, and sometimes a product of two (over 128 bits).
pub(crate) fn rational() -> impl Strategy<Value = BigRational> {
    prop_oneof![
        4 => (integer(), nonzero()).prop_map(|(n, d)| big(n, d)),
        1 => (integer(), nonzero(), integer(), nonzero())
            .prop_map(|(a, b, c, d)| big(a, b) * big(c, d) * big(i128::MAX, 7)),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    #[test]
    fn arithmetic_equals_big_rational(x in rational(), y in rational()) {
        let (a, b) = (rat(&x), rat(&y));
        prop_assert!(canonical(&a) && canonical(&b));
        for (got, want) in [
            (&a + &b, &x + &y),
            (&a - &b, &x - &y),
            (&a * &b, &x * &y),
            (-a.clone(), -x.clone()),
            (a.add_ref(&b), &x + &y),
            (a.sub_ref(&b), &x - &y),
            (a.mul_ref(&b), &x * &y),
        ] {
            prop_assert!(canonical(&got));
            prop_assert_eq!(got.to_big(), want.clone());
            prop_assert_eq!(got, rat(&want));
        }
        if y.is_zero() {
            prop_assert!(a.checked_div(&b).is_none());
        } else {
            let q = &a / &b;
            prop_assert!(canonical(&q));
            prop_assert_eq!(q.to_big(), &x / &y);
            prop_assert_eq!(a.checked_div(&b), Some(rat(&(&x / &y))));
            let mut c = a.clone();
            c /= &b;
            prop_assert_eq!(c.to_big(), &x / &y);
        }
        let mut c = a.clone();
        c += &b;
        c *= b.clone();
        c -= &a;
        prop_assert_eq!(c.to_big(), (&x + &y) * &y - &x);
        prop_assert_eq!(a.cmp(&b), x.cmp(&y));
        prop_assert_eq!(a.compare(&b), Some(x.cmp(&y)));
        prop_assert_eq!(a == b, x == y);
        prop_assert_eq!(a.is_zero(), x.is_zero());
        prop_assert_eq!(a.is_negative(), x.is_negative());
    }

    #[test]
    fn printers_and_conversions_equal_big_rational(x in rational()) {
        let a = rat(&x);
        prop_assert_eq!(a.to_text(), x.to_text());
        prop_assert_eq!(a.to_string(), x.to_string());
        prop_assert_eq!(a.to_latex(), x.to_latex());
        prop_assert_eq!(a.to_json_string(), x.to_json_string());
        prop_assert_eq!(a.with_text(str::to_owned), x.to_json_string());
        prop_assert_eq!(a.to_f64(), ExactRational::to_f64(&x));
        prop_assert_eq!(a.as_rational().map(|q| q.into_owned()), Some(x.clone()));
        prop_assert_eq!(a.to_number(), x.to_number());
        prop_assert_eq!(Rat::try_from_number(&Quadratic::from_rational(x.clone())).ok(), Some(a.clone()));
        prop_assert_eq!(a.sqrt_exact().map(|r| r.to_big()), x.sqrt_exact());
        let square = &a * &a;
        prop_assert_eq!(square.sqrt_exact(), Some(if a.is_negative() { -a.clone() } else { a.clone() }));
        prop_assert_eq!(a.checked_recip().map(|r| r.to_big()), (!x.is_zero()).then(|| x.recip()));
    }

    #[test]
    fn constructors_equal_big_rational(n in any::<i64>(), d in any::<i64>()) {
        prop_assert_eq!(Rat::from_i64(n).to_big(), <BigRational as FieldOps>::from_i64(n));
        if d != 0 {
            let r = Rat::from_ratio(n, d);
            prop_assert!(canonical(&r));
            prop_assert_eq!(r.to_big(), <BigRational as FieldOps>::from_ratio(n, d));
        }
    }

    #[test]
    fn small_ratio_equals_big_rational(n in prop_oneof![integer(), Just(i128::MIN), Just(i128::MAX)],
                                       d in prop_oneof![nonzero(), Just(i128::MIN), Just(-1i128)]) {
        let r = Rat::from_small_ratio(n, d);
        prop_assert!(canonical(&r));
        prop_assert_eq!(r.to_big(), big(n, d));
        prop_assert_eq!(Quadratic::from_small_ratio(n, d), Quadratic::from_rational(big(n, d)));
        prop_assert_eq!(<BigRational as ExactRational>::from_small_ratio(n, d), big(n, d));
    }

    #[test]
    fn ratios_with_common_factors_reduce(n in -999i64..1000, d in -999i64..1000, k in 1i64..100_000) {
        // common factors k (and those of n and d), either sign: reduced in machine words
        if d != 0 {
            let r = Rat::from_ratio(n * k, d * k);
            prop_assert!(canonical(&r));
            prop_assert_eq!(r.to_big(), <BigRational as FieldOps>::from_ratio(n, d));
        }
    }
}

#[test]
fn word_edges() {
    let min = Rat::from_i64(i64::MIN);
    assert!(
        min.as_small().is_none(),
        "i64::MIN is stored big (its negation overflows)"
    );
    assert_eq!(
        (-min.clone()).as_small(),
        None,
        "-i64::MIN = 2^63 does not fit"
    );
    let max = Rat::from_i64(i64::MAX);
    assert_eq!(
        (max.clone() + Rat::one()).to_big(),
        <BigRational as FieldOps>::from_i64(i64::MAX) + BigRational::one()
    );
    assert_eq!(
        &(&max + &Rat::one()) - &Rat::one(),
        max,
        "back inline after the spill"
    );
    assert_eq!(
        Rat::from_ratio(i64::MIN, -1).to_text(),
        "9223372036854775808"
    );
    assert_eq!(
        Rat::from_ratio(1, i64::MIN).to_text(),
        "-1/9223372036854775808"
    );
    assert_eq!(Rat::from_ratio(6, -4).to_text(), "-3/2");
    assert_eq!(
        (max.clone() * &max).to_text(),
        "85070591730234615847396907784232501249"
    );
    assert_eq!(
        Rat::from_ratio(1, i64::MAX) + Rat::from_ratio(1, i64::MAX - 1),
        rat(&(big(1, i128::from(i64::MAX)) + big(1, i128::from(i64::MAX) - 1)))
    );
    assert_eq!(Rat::from_ratio(-7, 3).to_latex(), "-\\frac{7}{3}");
    assert_eq!(Rat::sqrt_of(9), Some(Rat::from_i64(3)));
    assert_eq!(Rat::sqrt_of(8), None);
}
