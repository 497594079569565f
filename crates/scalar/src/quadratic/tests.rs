//! `Quadratic` on `Rat` parts against a + b√d computed on `BigRational`s, the reference: sums,
//! products, inverses, quotients, order and the three printers, on parts from tiny to past a
//! machine word (the `Rat` tests' strategy) and radicands from 2 to near `MAX_RADICAND`.

use super::*;
use crate::small::tests::rational;
use num_bigint::BigInt;
use num_traits::Signed;
use proptest::prelude::*;

/// a + b√d on big rationals: the old representation, written from the formulas.
#[derive(Clone, Debug, PartialEq)]
struct Reference {
    a: BigRational,
    b: BigRational,
    d: u64,
}

impl Reference {
    fn d(&self) -> BigRational {
        BigRational::from_integer(BigInt::from(self.d))
    }
    // (a + b√d) ± (c + e√d) = (a ± c) + (b ± e)√d
    fn add(&self, o: &Self) -> Self {
        Reference {
            a: &self.a + &o.a,
            b: &self.b + &o.b,
            d: self.d,
        }
    }
    fn sub(&self, o: &Self) -> Self {
        Reference {
            a: &self.a - &o.a,
            b: &self.b - &o.b,
            d: self.d,
        }
    }
    // (a + b√d)(c + e√d) = (ac + be d) + (ae + bc)√d
    fn mul(&self, o: &Self) -> Self {
        Reference {
            a: &self.a * &o.a + &self.b * &o.b * self.d(),
            b: &self.a * &o.b + &self.b * &o.a,
            d: self.d,
        }
    }
    // 1/(a + b√d) = (a - b√d)/(a² - b² d)
    fn inv(&self) -> Option<Self> {
        let n = &self.a * &self.a - &self.b * &self.b * self.d();
        (!n.is_zero()).then(|| Reference {
            a: &self.a / &n,
            b: -(&self.b / &n),
            d: self.d,
        })
    }
    /// The sign, from f64-free squares: a + b√d > 0 iff ...
    fn sign(&self) -> Ordering {
        let zero = BigRational::zero();
        let (sa, sb) = (self.a.cmp(&zero), self.b.cmp(&zero));
        if sb == Ordering::Equal || sa == sb {
            return if sa == Ordering::Equal { sb } else { sa };
        }
        if sa == Ordering::Equal {
            return sb;
        }
        // opposite signs: the sign of the larger of |a| and |b|√d
        match (&self.a * &self.a).cmp(&(&self.b * &self.b * self.d())) {
            Ordering::Greater => sa,
            Ordering::Less => sb,
            Ordering::Equal => Ordering::Equal,
        }
    }
    /// The text as the BigRational printers wrote it: `a`, or `[a ± ]k√d[/q]`.
    fn text(&self, sep: &str, root: &str) -> String {
        if self.b.is_zero() {
            return self.a.to_string();
        }
        let k = self.b.numer().abs();
        let coef = if k == BigInt::from(1) {
            String::new()
        } else {
            format!("{k}{sep}")
        };
        let den = if self.b.denom() == &BigInt::from(1) {
            String::new()
        } else {
            format!("/{}", self.b.denom())
        };
        let r = format!("{coef}{root}{}{den}", self.d);
        let minus = self.b.is_negative();
        match (self.a.is_zero(), minus) {
            (true, false) => r,
            (true, true) => format!("-{r}"),
            (false, _) => format!("{} {} {r}", self.a, if minus { "-" } else { "+" }),
        }
    }
    fn latex(&self) -> String {
        let frac = |q: &BigRational| {
            let sign = if q.is_negative() { "-" } else { "" };
            if q.denom() == &BigInt::from(1) {
                format!("{sign}{}", q.numer().abs())
            } else {
                format!("{sign}\\frac{{{}}}{{{}}}", q.numer().abs(), q.denom())
            }
        };
        if self.b.is_zero() {
            return frac(&self.a);
        }
        let k = self.b.numer().abs();
        let coef = if k == BigInt::from(1) {
            String::new()
        } else {
            k.to_string()
        };
        let r = format!("{coef}\\sqrt{{{}}}", self.d);
        let r = if self.b.denom() == &BigInt::from(1) {
            r
        } else {
            format!("\\frac{{{r}}}{{{}}}", self.b.denom())
        };
        let minus = self.b.is_negative();
        match (self.a.is_zero(), minus) {
            (true, false) => r,
            (true, true) => format!("-{r}"),
            (false, _) => format!("{} {} {r}", frac(&self.a), if minus { "-" } else { "+" }),
        }
    }
}

/// The value under test and its reference.
fn pair(a: BigRational, b: BigRational, d: u64) -> (Quadratic, Reference) {
    let x = Quadratic::new(a.clone(), b.clone(), d).unwrap_or_else(|e| panic!("{e}"));
    (x, Reference { a, b, d })
}

/// Whether a value equals its reference, part by part (and d = 0 exactly for a rational).
fn same(x: &Quadratic, r: &Reference) -> bool {
    x.rational_part().to_big() == r.a
        && x.root_part().to_big() == r.b
        && x.radicand() == if r.b.is_zero() { 0 } else { r.d }
}

/// Square-free radicands: small, and near the largest accepted.
fn radicand() -> impl Strategy<Value = u64> {
    prop_oneof![
        Just(2u64),
        Just(3),
        Just(5),
        Just(6),
        Just(7),
        Just(30),
        Just(999_999_999_989)
    ]
}

/// Parts of both kinds, a root part that is zero now and then.
fn parts() -> impl Strategy<Value = (BigRational, BigRational)> {
    (
        rational(),
        prop_oneof![4 => rational(), 1 => Just(BigRational::zero())],
    )
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1000))]

    #[test]
    fn arithmetic_equals_big_rational_reference(
        (a, b) in parts(), (c, e) in parts(), d in radicand()
    ) {
        let (x, rx) = pair(a, b, d);
        let (y, ry) = pair(c, e, d);
        prop_assert!(same(&(&x + &y), &rx.add(&ry)));
        prop_assert!(same(&(&x - &y), &rx.sub(&ry)));
        prop_assert!(same(&(&x * &y), &rx.mul(&ry)));
        prop_assert!(same(&x.add_ref(&y), &rx.add(&ry)));
        prop_assert!(same(&x.mul_ref(&y), &rx.mul(&ry)));
        let negated = Reference { a: -rx.a.clone(), b: -rx.b.clone(), d };
        prop_assert!(same(&-x.clone(), &negated));
        let conjugate = Reference { a: rx.a.clone(), b: -rx.b.clone(), d };
        prop_assert!(same(&x.conjugate(), &conjugate));
        prop_assert_eq!(x.norm().to_big(), &rx.a * &rx.a - &rx.b * &rx.b * rx.d());
        match ry.inv() {
            None => {
                prop_assert!(y.checked_inv().is_err());
                prop_assert!(x.checked_div(&y).is_none());
            }
            Some(inv) => {
                let got = y.checked_inv().unwrap_or_else(|e| panic!("{e}"));
                prop_assert!(same(&got, &inv));
                let q = x.checked_div(&y).unwrap_or_else(|| panic!("a zero divisor"));
                prop_assert!(same(&q, &rx.mul(&inv)));
                prop_assert_eq!(&q * &y, x.clone());
            }
        }
        // the order, exact
        prop_assert_eq!(x.signum(), rx.sign());
        prop_assert_eq!(x.compare(&y), Some(rx.sub(&ry).sign()));
        prop_assert_eq!(x == y, rx.sub(&ry).sign() == Ordering::Equal);
    }

    #[test]
    fn printers_equal_big_rational_reference((a, b) in parts(), d in radicand()) {
        let (x, r) = pair(a, b, d);
        prop_assert_eq!(x.to_text(), r.text("", "√"));
        prop_assert_eq!(x.to_string(), r.text("", "√"));
        prop_assert_eq!(x.to_json_string(), r.text("*", "sqrt"));
        prop_assert_eq!(x.to_latex(), r.latex());
        // the JSON form reads back to the same value
        let back = crate::parse_number_with(&x.to_json_string(), &crate::Limits::default());
        prop_assert_eq!(back.ok(), Some(x.clone()));
        prop_assert_eq!(x.to_rational(), r.b.is_zero().then(|| r.a.clone()));
        prop_assert_eq!(x.as_rational().map(Cow::into_owned), r.b.is_zero().then(|| r.a.clone()));
    }

    #[test]
    fn roots_of_rationals_equal_the_reduced_form(p in 0i64..2000, q in 1i64..2000) {
        // √(p/q) = √(p q)/q = k√m/q with p q = k² m
        let n = BigRational::new(BigInt::from(p), BigInt::from(q));
        let x = Quadratic::sqrt_of(&n).unwrap_or_else(|e| panic!("{e}"));
        prop_assert_eq!((&x * &x).to_rational(), Some(n.clone()));
        prop_assert!(x.signum() != Ordering::Less);
        let (k, m) = square_free_part((p * q) as u64);
        let coef = BigRational::new(BigInt::from(k), BigInt::from(q));
        if p == 0 {
            prop_assert!(x.is_zero());
        } else if m == 1 {
            let want = Reference { a: coef, b: BigRational::zero(), d: 0 };
            prop_assert!(same(&x, &want));
        } else {
            let want = Reference { a: BigRational::zero(), b: coef, d: m };
            prop_assert!(same(&x, &want));
        }
    }
}

#[test]
fn square_free_parts() {
    assert_eq!(square_free_part(8), (2, 2));
    assert_eq!(square_free_part(12), (2, 3));
    assert_eq!(square_free_part(49), (7, 1));
    assert_eq!(square_free_part(30), (1, 30));
    assert_eq!(square_free_part(1), (1, 1));
}

#[test]
fn parts_past_a_machine_word_print_and_spill_back() {
    let big = BigRational::new(BigInt::from(i64::MAX) * 3, BigInt::from(5));
    let x = Quadratic::new(big.clone(), -big.clone(), 2).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(x.rational_part().as_small(), None, "the part is stored big");
    assert_eq!(
        x.to_text(),
        "27670116110564327421/5 - 27670116110564327421√2/5"
    );
    // (a - a√2)(a + a√2) = -a²; divided by -a² it is 1 again, inline
    let y = &x * &x.conjugate();
    assert_eq!(y.to_rational(), Some(-(&big * &big)));
    let one = y.clone() / y;
    assert_eq!(one.rational_part().as_small(), Some((1, 1)));
    assert!(
        Quadratic::sqrt_of(&big).is_err(),
        "p q is past MAX_RADICAND"
    );
}
