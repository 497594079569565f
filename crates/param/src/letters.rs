//! The names of parameters and the monomials built from them.

use cagd_poly::Term;
use std::cmp::Ordering;
use std::fmt;
use std::sync::Arc;

/// The name of a parameter: a letter (`R`, `a`), or a letter with a subscript (`c_{1,0}`,
/// `w_{2}`) for the points and weights of a generic mesh.
///
/// Names are ordered naturally (subscripts by their numbers: `c_{2,0}` before `c_{10,0}`),
/// which is the order of the letters in a printed term (`a b`, not `b a`).
///
/// A name may stand for a function of a curve's variable (`f` printed `f(u)`, as the notes
/// write the profile `(f(u), 0, g(u))` of a surface of revolution): its JSON form is the bare
/// letter, its text and LaTeX carry the argument.
#[derive(Clone)]
pub struct Name(Arc<str>, Option<Arc<str>>);

impl PartialEq for Name {
    fn eq(&self, other: &Self) -> bool {
        self.0 == other.0
    }
}

impl Eq for Name {}

impl std::hash::Hash for Name {
    fn hash<H: std::hash::Hasher>(&self, h: &mut H) {
        self.0.hash(h);
    }
}

impl Name {
    /// The name as written.
    pub fn new(name: &str) -> Name {
        Name(Arc::from(name), None)
    }

    /// A letter that stands for a function of `arg`: `Name::function("f", "u")` prints `f(u)`.
    pub fn function(name: &str, arg: &str) -> Name {
        Name(Arc::from(name), Some(Arc::from(arg)))
    }

    /// The name as written (without an argument).
    pub fn as_str(&self) -> &str {
        &self.0
    }

    /// The argument of a function's name (`u` for `f(u)`).
    pub fn argument(&self) -> Option<&str> {
        self.1.as_deref()
    }

    /// The name with its base letter and subscript split (`c_{1,0}` → `("c", Some("1,0"))`).
    fn parts(&self) -> (&str, Option<&str>) {
        match self.0.split_once('_') {
            Some((base, sub)) => (
                base,
                Some(sub.trim_start_matches('{').trim_end_matches('}')),
            ),
            None => (&self.0, None),
        }
    }

    /// The subscript's numbers (`c_{1,10}` → `[1, 10]`), for the natural order.
    fn subscript(&self) -> Vec<u64> {
        self.parts()
            .1
            .map(|s| {
                s.split(',')
                    .map(|n| n.trim().parse::<u64>().unwrap_or(u64::MAX))
                    .collect()
            })
            .unwrap_or_default()
    }

    /// LaTeX: `R`, `c_{1,0}`.
    pub fn to_latex(&self) -> String {
        let name = match self.parts() {
            (base, Some(sub)) => format!("{base}_{{{sub}}}"),
            (base, None) => base.to_string(),
        };
        match &self.1 {
            Some(arg) => format!("{name}({arg})"),
            None => name,
        }
    }
}

impl Ord for Name {
    fn cmp(&self, other: &Self) -> Ordering {
        self.parts()
            .0
            .cmp(other.parts().0)
            .then_with(|| self.subscript().cmp(&other.subscript()))
            .then_with(|| self.0.cmp(&other.0))
    }
}

impl PartialOrd for Name {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl fmt::Display for Name {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.1 {
            Some(arg) => write!(f, "{}({arg})", self.0),
            None => f.write_str(&self.0),
        }
    }
}

impl fmt::Debug for Name {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(self, f)
    }
}

/// A product of powers of parameters, `a^2 b c_{1,0}`: the monomial of the parameter field's
/// polynomials.
///
/// Stored as (name, exponent) pairs sorted by name, every exponent positive. Ordered
/// **graded lexicographically**, like the monomials in `u, v` ([`cagd_poly::Monomial`]): first
/// by total degree, then by the exponent of the first name in the natural order, so the
/// printers (largest term first) write `2 a + c`, `a^2 + a b + b^2`.
#[derive(Clone, PartialEq, Eq, Hash, Default)]
pub struct Letters(Vec<(Name, u32)>);

impl Letters {
    /// The monomial of one parameter.
    pub fn var(name: Name) -> Letters {
        Letters(vec![(name, 1)])
    }

    /// The parameters with their exponents, in natural order.
    pub fn powers(&self) -> impl Iterator<Item = (&Name, u32)> + '_ {
        self.0.iter().map(|(n, e)| (n, *e))
    }

    /// The greatest common divisor: each exponent the smaller of the two.
    pub fn gcd(&self, other: &Letters) -> Letters {
        Letters(
            self.0
                .iter()
                .filter_map(|(n, e)| {
                    other
                        .0
                        .iter()
                        .find(|(m, _)| m == n)
                        .map(|(_, f)| (n.clone(), (*e).min(*f)))
                })
                .collect(),
        )
    }
}

impl Term for Letters {
    fn one() -> Self {
        Letters(Vec::new())
    }

    fn is_one(&self) -> bool {
        self.0.is_empty()
    }

    fn mul(&self, other: &Self) -> Self {
        let mut out: Vec<(Name, u32)> = Vec::with_capacity(self.0.len() + other.0.len());
        let (mut a, mut b) = (self.0.iter().peekable(), other.0.iter().peekable());
        loop {
            match (a.peek(), b.peek()) {
                (Some((n, e)), Some((m, f))) => match n.cmp(m) {
                    Ordering::Less => {
                        out.push((n.clone(), *e));
                        a.next();
                    }
                    Ordering::Greater => {
                        out.push((m.clone(), *f));
                        b.next();
                    }
                    Ordering::Equal => {
                        out.push((n.clone(), e.saturating_add(*f)));
                        a.next();
                        b.next();
                    }
                },
                (Some((n, e)), None) => {
                    out.push((n.clone(), *e));
                    a.next();
                }
                (None, Some((m, f))) => {
                    out.push((m.clone(), *f));
                    b.next();
                }
                (None, None) => break,
            }
        }
        Letters(out)
    }

    fn checked_div(&self, other: &Self) -> Option<Self> {
        let mut out = self.0.clone();
        for (m, f) in &other.0 {
            let i = out.iter().position(|(n, _)| n == m)?;
            let e = out.get_mut(i)?;
            e.1 = e.1.checked_sub(*f)?;
            if e.1 == 0 {
                out.remove(i);
            }
        }
        Some(Letters(out))
    }

    fn degree(&self) -> u32 {
        self.0.iter().fold(0u32, |d, (_, e)| d.saturating_add(*e))
    }
}

impl Ord for Letters {
    fn cmp(&self, other: &Self) -> Ordering {
        self.degree().cmp(&other.degree()).then_with(|| {
            // the first name (in natural order) where the exponents differ decides: the larger
            // exponent is the larger monomial
            let (mut a, mut b) = (self.0.iter(), other.0.iter());
            loop {
                match (a.next(), b.next()) {
                    (Some((n, e)), Some((m, f))) => match n.cmp(m) {
                        Ordering::Equal => match e.cmp(f) {
                            Ordering::Equal => continue,
                            o => return o,
                        },
                        // `self` has the earlier name, where `other` has exponent 0
                        Ordering::Less => return Ordering::Greater,
                        Ordering::Greater => return Ordering::Less,
                    },
                    (Some(_), None) => return Ordering::Greater,
                    (None, Some(_)) => return Ordering::Less,
                    (None, None) => return Ordering::Equal,
                }
            }
        })
    }
}

impl PartialOrd for Letters {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl fmt::Debug for Letters {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let parts: Vec<String> = self
            .0
            .iter()
            .map(|(n, e)| {
                if *e == 1 {
                    n.to_string()
                } else {
                    format!("{n}^{e}")
                }
            })
            .collect();
        f.write_str(&parts.join(" "))
    }
}
