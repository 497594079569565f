//! Every kind of curve and surface, one type each: [`AnyCurve`] and [`AnySurface`], shared by
//! the problem layer (the validated arguments of an operation), the answer keys and the
//! figures (`cagd-render` draws them).

use cagd_bezier::{BezierCurve, RationalBezierCurve};
use cagd_bspline::{BSplineCurve, NurbsCurve};
use cagd_poly::VecPoly;
use cagd_scalar::Scalar;
use cagd_spline_surface::{BSplineSurface, NurbsSurface};
use cagd_surface::{BezierSurface, RationalBezierSurface};

/// A surface of any kind, validated.
#[derive(Clone, Debug, PartialEq)]
pub enum AnySurface<S: Scalar> {
    /// A Bézier patch (notes, chapter 5, eq. (1)).
    Bezier(BezierSurface<S>),
    /// A rational Bézier patch (eq. (5)).
    RationalBezier(RationalBezierSurface<S>),
    /// A B-spline surface (eq. (4)).
    BSpline(BSplineSurface<S>),
    /// A NURBS surface (eq. (6)).
    Nurbs(NurbsSurface<S>),
    /// A polynomial map in u and v on [0, 1] x [0, 1], e.g. a closed form `(u, v, u v)`.
    Map(VecPoly<S>),
}

/// A curve of any kind, validated.
#[derive(Clone, Debug, PartialEq)]
pub enum AnyCurve<S: Scalar> {
    /// A Bézier curve.
    Bezier(BezierCurve<S>),
    /// A rational Bézier curve.
    RationalBezier(RationalBezierCurve<S>),
    /// A B-spline curve.
    BSpline(BSplineCurve<S>),
    /// A NURBS curve.
    Nurbs(NurbsCurve<S>),
    /// A polynomial map in one variable on [0, 1], e.g. `(u, 0, u^2)`.
    Map(VecPoly<S>),
}

macro_rules! from {
    ($any:ident, $variant:ident, $t:ident) => {
        impl<S: Scalar> From<$t<S>> for $any<S> {
            fn from(x: $t<S>) -> Self {
                $any::$variant(x)
            }
        }
    };
}

from!(AnySurface, Bezier, BezierSurface);
from!(AnySurface, RationalBezier, RationalBezierSurface);
from!(AnySurface, BSpline, BSplineSurface);
from!(AnySurface, Nurbs, NurbsSurface);
from!(AnyCurve, Bezier, BezierCurve);
from!(AnyCurve, RationalBezier, RationalBezierCurve);
from!(AnyCurve, BSpline, BSplineCurve);
from!(AnyCurve, Nurbs, NurbsCurve);

impl<S: Scalar> AnySurface<S> {
    /// The parameter domain `([a, b], [c, d])` (a map's is the unit square).
    pub fn domain(&self) -> ((S, S), (S, S)) {
        let interval = |(a, b): (&S, &S)| (a.clone(), b.clone());
        match self {
            AnySurface::Bezier(s) => (
                interval(s.domain().u_interval()),
                interval(s.domain().v_interval()),
            ),
            AnySurface::RationalBezier(s) => (
                interval(s.domain().u_interval()),
                interval(s.domain().v_interval()),
            ),
            AnySurface::BSpline(s) => s.domain(),
            AnySurface::Nurbs(s) => s.domain(),
            AnySurface::Map(_) => ((S::zero(), S::one()), (S::zero(), S::one())),
        }
    }
}

impl<S: Scalar> AnyCurve<S> {
    /// The parameter interval `[a, b]` (a map's is [0, 1]).
    pub fn domain(&self) -> (S, S) {
        match self {
            AnyCurve::Bezier(c) => (c.domain().0.clone(), c.domain().1.clone()),
            AnyCurve::RationalBezier(c) => (c.domain().0.clone(), c.domain().1.clone()),
            AnyCurve::BSpline(c) => c.domain(),
            AnyCurve::Nurbs(c) => c.domain(),
            AnyCurve::Map(_) => (S::zero(), S::one()),
        }
    }
}
