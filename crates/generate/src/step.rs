//! The intermediate values the notes show, for answer keys: what a construction records into
//! the step recorder it is given (`rec: &mut impl Record<Step<S>>`, see [`cagd_record`]); its
//! remarks in words are [`crate::Note`]s, kept with or without steps.

use cagd_linalg::Point;
use cagd_poly::{Poly, RationalMap, VecPoly};
use cagd_scalar::Scalar;
use cagd_surface::{Grid, Mesh};
use std::fmt;

/// The value of a [`Step`]: whatever the notes print on the way to a result.
#[derive(Clone, PartialEq)]
#[non_exhaustive]
pub enum StepValue<S> {
    /// A number.
    Number(S),
    /// A point or vector, e.g. the corner `a = (1, 0, 0)`.
    Point(Point<S>),
    /// A scalar polynomial, e.g. `c_uv · (c_u × c_v) = -8 u^3 - 4 u^2 + 12 u`.
    Poly(Poly<S>),
    /// A polynomial map, e.g. `c_u(u, v)`.
    Map(VecPoly<S>),
    /// A rational map.
    Rational(RationalMap<S>),
    /// A control mesh, e.g. the ruled patch `c_c` elevated to bidegree (m, n).
    Mesh(Mesh<S>),
    /// A grid of weights.
    Weights(Grid<S>),
}

/// One named intermediate value of a construction: `c_c,1,1 = (1/2, 3/2, 5/2)`.
#[derive(Clone, PartialEq)]
pub struct Step<S: Scalar> {
    /// The name, as the notes write it (`a`, `c_u`, `c_cd`).
    pub name: String,
    /// The value.
    pub value: StepValue<S>,
}

impl<S: Scalar> StepValue<S> {
    /// Plain text, with the printers of each type.
    pub fn to_text(&self) -> String {
        match self {
            StepValue::Number(x) => x.to_text(),
            StepValue::Point(p) => p.to_text(),
            StepValue::Poly(p) => p.to_text(),
            StepValue::Map(c) => c.to_text(),
            StepValue::Rational(r) => r.to_text(),
            StepValue::Mesh(m) => m.to_text(),
            StepValue::Weights(w) => w.to_text_numbers(),
        }
    }

    /// LaTeX, with the printers of each type.
    pub fn to_latex(&self) -> String {
        match self {
            StepValue::Number(x) => x.to_latex(),
            StepValue::Point(p) => p.to_latex(),
            StepValue::Poly(p) => p.to_latex(),
            StepValue::Map(c) => c.to_latex(),
            StepValue::Rational(r) => r.to_latex(),
            StepValue::Mesh(m) => m.to_latex(),
            StepValue::Weights(w) => w.to_latex_numbers(),
        }
    }
}

impl<S: Scalar> Step<S> {
    /// The step `name = value`.
    pub fn new(name: impl Into<String>, value: StepValue<S>) -> Self {
        Step {
            name: name.into(),
            value,
        }
    }

    /// A point.
    pub fn point(name: impl Into<String>, p: &Point<S>) -> Self {
        Step::new(name, StepValue::Point(p.clone()))
    }

    /// A polynomial map.
    pub fn map(name: impl Into<String>, c: &VecPoly<S>) -> Self {
        Step::new(name, StepValue::Map(c.clone()))
    }

    /// A control mesh.
    pub fn mesh(name: impl Into<String>, m: &Mesh<S>) -> Self {
        Step::new(name, StepValue::Mesh(m.clone()))
    }

    /// A grid of weights.
    pub fn weights(name: impl Into<String>, w: &Grid<S>) -> Self {
        Step::new(name, StepValue::Weights(w.clone()))
    }

    /// Plain text: `name = value`.
    ///
    /// ```
    /// use cagd_generate::Step;
    /// use cagd_linalg::Point;
    /// use cagd_scalar::BigRational;
    /// let a = Step::<BigRational>::point("a", &Point::from_ints(&[1, 0, 0]));
    /// assert_eq!(a.to_text(), "a = (1, 0, 0)");
    /// ```
    pub fn to_text(&self) -> String {
        format!("{} = {}", self.name, self.value.to_text())
    }

    /// LaTeX: `name = value`.
    pub fn to_latex(&self) -> String {
        format!("{} = {}", self.name, self.value.to_latex())
    }
}

/// The steps as text, one per line.
pub fn steps_to_text<S: Scalar>(steps: &[Step<S>]) -> String {
    steps
        .iter()
        .map(Step::to_text)
        .collect::<Vec<_>>()
        .join("\n")
}

/// The step called `name`, if there is one.
pub fn find_step<'a, S: Scalar>(steps: &'a [Step<S>], name: &str) -> Option<&'a StepValue<S>> {
    steps.iter().find(|s| s.name == name).map(|s| &s.value)
}

impl<S: Scalar> fmt::Debug for StepValue<S> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.to_text())
    }
}

impl<S: Scalar> fmt::Debug for Step<S> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.to_text())
    }
}

impl<S: Scalar> fmt::Display for Step<S> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.to_text())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use cagd_poly::parse_vec_poly;
    use cagd_scalar::{parse_number, BigRational, FieldOps, Quadratic};

    #[test]
    fn text_and_latex_of_every_kind() {
        let map: VecPoly<BigRational> = parse_vec_poly("(u, v^2)").unwrap();
        let steps = vec![
            Step::map("c_u", &map),
            Step::new("w", StepValue::Number(cagd_scalar::q!(1 / 2))),
        ];
        assert_eq!(steps_to_text(&steps), "c_u = (u, v^2)\nw = 1/2");
        assert_eq!(steps[0].to_latex(), "c_u = \\left(u, v^{2}\\right)");
        assert_eq!(steps[1].to_latex(), "w = \\frac{1}{2}");
        assert_eq!(
            find_step(&steps, "w"),
            Some(&StepValue::Number(cagd_scalar::q!(1 / 2)))
        );
        assert!(find_step(&steps, "x").is_none());
        let h: Quadratic = parse_number("sqrt2/2").unwrap();
        let w = Grid::from_rows(vec![vec![Quadratic::from_i64(1), h]]).unwrap();
        let step = Step::weights("weights", &w);
        assert_eq!(step.to_text(), "weights = {1, √2/2}");
        assert_eq!(
            step.to_latex(),
            "weights = \\begin{Bmatrix} 1 & \\frac{\\sqrt{2}}{2} \\end{Bmatrix}"
        );
        assert_eq!(format!("{}", steps[1]), "w = 1/2");
    }
}
