//! Text and LaTeX output for answer keys: bidegree, knots (the notes' convention by default),
//! mesh and weights.

use crate::{BSplineSurface, NurbsSurface};
use cagd_bspline::KnotConvention;
use cagd_scalar::Scalar;
use std::fmt;

impl<S: Scalar> BSplineSurface<S> {
    /// The knots `(in u, in v)` as text in a convention: `("{0, 0, 1, 1}", "{0, 1, 2}")`.
    pub fn knots_text(&self, convention: KnotConvention) -> (String, String) {
        (
            self.knots_u().to_text_in(convention),
            self.knots_v().to_text_in(convention),
        )
    }

    /// Plain text in the notes' convention (see [`BSplineSurface::to_text_in`]).
    pub fn to_text(&self) -> String {
        self.to_text_in(KnotConvention::Notes)
    }

    /// Plain text, one item a line: bidegree, knots in u and in v in `convention`, the mesh
    /// (rows separated by `;`).
    ///
    /// ```
    /// use cagd_spline_surface::BSplineSurface;
    /// use cagd_bspline::KnotConvention;
    /// use cagd_surface::Mesh;
    /// use cagd_linalg::Point;
    /// use cagd_scalar::{q, BigRational};
    /// let p = |c: &[i64]| Point::<BigRational>::from_ints(c);
    /// let mesh = Mesh::mesh(vec![
    ///     vec![p(&[0, 0, 0]), p(&[0, 1, 0])],
    ///     vec![p(&[1, 0, 0]), p(&[1, 1, 1])],
    /// ]).unwrap();
    /// let (s, _) = BSplineSurface::read((1, 1), (vec![q!(0), q!(1)], vec![q!(0), q!(1)]), mesh).unwrap();
    /// assert_eq!(
    ///     s.to_text(),
    ///     "bidegree (1, 1)\nknots u {0, 1}\nknots v {0, 1}\nmesh {(0, 0, 0), (0, 1, 0); (1, 0, 0), (1, 1, 1)}"
    /// );
    /// assert!(s.to_text_in(KnotConvention::Full).contains("knots u {0, 0, 1, 1}"));
    /// ```
    pub fn to_text_in(&self, convention: KnotConvention) -> String {
        let (p, q) = self.bidegree();
        let (ku, kv) = self.knots_text(convention);
        format!(
            "bidegree ({p}, {q})\nknots u {ku}\nknots v {kv}\nmesh {}",
            self.mesh().to_text()
        )
    }

    /// LaTeX, one item a line: the knots as `\{...\}` in `convention` and the mesh as a
    /// matrix of points.
    pub fn to_latex_in(&self, convention: KnotConvention) -> String {
        let (p, q) = self.bidegree();
        format!(
            "(m, n) = ({p}, {q})\n\\{{u_i\\}} = {}\n\\{{v_j\\}} = {}\n\\{{d_{{i,j}}\\}} = {}",
            self.knots_u().to_latex_in(convention),
            self.knots_v().to_latex_in(convention),
            self.mesh().to_latex()
        )
    }
}

impl<S: Scalar> NurbsSurface<S> {
    /// Plain text in the notes' convention (see [`NurbsSurface::to_text_in`]).
    pub fn to_text(&self) -> String {
        self.to_text_in(KnotConvention::Notes)
    }

    /// Plain text, one item a line: bidegree, knots in `convention`, mesh, and the weights
    /// (rows separated by `;`), e.g. `weights {1, √2/2, 1; √2/2, 1/2, √2/2}`.
    pub fn to_text_in(&self, convention: KnotConvention) -> String {
        format!(
            "{}\nweights {}",
            self.control_surface().to_text_in(convention),
            self.weights().to_text_numbers()
        )
    }

    /// LaTeX: as [`BSplineSurface::to_latex_in`], then the weights as a matrix.
    pub fn to_latex_in(&self, convention: KnotConvention) -> String {
        format!(
            "{}\n\\{{w_{{i,j}}\\}} = {}",
            self.control_surface().to_latex_in(convention),
            self.weights().to_latex_numbers()
        )
    }
}

impl<S: Scalar> fmt::Display for BSplineSurface<S> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.to_text())
    }
}

impl<S: Scalar> fmt::Display for NurbsSurface<S> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.to_text())
    }
}
