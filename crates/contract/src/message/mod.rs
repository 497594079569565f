//! The door's sentences as values: every error, remark, mismatch and verdict sentence of a
//! problem is a [`Message`], worded in English and Spanish by the [`cagd_words::Message`]
//! impl beside each enum's definition. Keys, the CLI, the JSON writer and Python read them by
//! type and render them in their language; nothing reads a sentence back for its meaning.
//!
//! An engine crate's error is carried as it is (each has its own words); the door's own
//! sentences are grouped by subject: reading a problem as a whole ([`contract::Contract`])
//! and its leaves, numbers and shapes ([`read::Read`]), the curve operations
//! ([`curve::Curve`]), the surface operations of chapters 5 and 6 ([`surface::Surface`]),
//! triangles and fitting ([`fitting::Fitting`]), and checking an answer ([`check::Check`]).

pub mod check;
pub mod contract;
pub mod curve;
pub mod fitting;
pub mod found;
pub mod inner;
pub mod limited;
pub mod read;
pub mod surface;

use crate::limit::Limit;
use cagd_bezier::{BezierError, LengthError, LengthNotGiven, ReductionError};
use cagd_bspline::{ArcError, BSplineError, SplineReductionError, SplitError};
use cagd_fit::{FitError, ParameterError};
use cagd_generate::{GenerateError, Note};
use cagd_linalg::LinalgError;
use cagd_poly::{AreaError, PolyError, RootsError};
use cagd_scalar::ScalarError;
use cagd_spline_surface::{LinesError, SplineSurfaceError};
use cagd_surface::{ConditionFails, CurvatureError, DegenerateCorner, Smoothness, SurfaceError};
use cagd_triangle::TriangleError;
use cagd_words::{Lang, Phrase};
use inner::Inner;
use serde::{Serialize, Serializer};
use std::fmt;

/// A sentence of the engine about a problem: an error, a remark, a mismatch, a verdict. Each
/// payload is boxed, so that a message (and a `Result` of a `ProblemError`) stays small.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Message {
    /// An error of the numbers (cagd-scalar).
    Scalar(Box<ScalarError>),
    /// An error of linear algebra (cagd-linalg).
    Linalg(Box<LinalgError>),
    /// An error of polynomials (cagd-poly).
    Poly(Box<PolyError>),
    /// The exact roots of a polynomial (point inversion).
    Roots(Box<RootsError>),
    /// An error of Bézier curves (cagd-bezier).
    Bezier(Box<BezierError>),
    /// An error of B-spline curves (cagd-bspline).
    BSpline(Box<BSplineError>),
    /// Why a Bézier curve's degree is not reduced (cagd-bezier).
    Reduction(Box<ReductionError>),
    /// Why an arc length is not computed (cagd-bezier).
    Length(Box<LengthError>),
    /// Why an arc length is not given as a number (cagd-bezier; a result value).
    LengthNotGiven(Box<LengthNotGiven>),
    /// Why an area is not given (cagd-poly).
    Area(Box<AreaError>),
    /// Why an arc of exact angles is not built (cagd-bspline).
    Arc(Box<ArcError>),
    /// Why a B-spline curve is not split (cagd-bspline).
    Split(Box<SplitError>),
    /// Why a B-spline or NURBS curve's degree is not reduced exactly (cagd-bspline).
    SplineReduction(Box<SplineReductionError>),
    /// An error of Bézier patches (cagd-surface).
    Surface(Box<SurfaceError>),
    /// An error of B-spline surfaces (cagd-spline-surface).
    SplineSurface(Box<SplineSurfaceError>),
    /// Why a surface is not split, or a knot not removed, line by line (cagd-spline-surface).
    Lines(Box<LinesError>),
    /// Why the numerator of the Gaussian curvature is not computed (cagd-surface).
    Curvature(Box<CurvatureError>),
    /// The order of continuity of two patches across their border (cagd-surface; a result
    /// value).
    Smoothness(Box<Smoothness>),
    /// The first condition of (21)-(23) that fails across a border (cagd-surface; a result
    /// value).
    ConditionFails(Box<ConditionFails>),
    /// A corner where `c_u × c_v` vanishes, why, and the limit direction of the normal
    /// (cagd-surface; a result value).
    DegenerateCorner(Box<DegenerateCorner>),
    /// An error of chapter 6's constructions (cagd-generate).
    Generate(Box<GenerateError>),
    /// A remark of chapter 6's constructions (cagd-generate): a curve elevated, knots
    /// inserted, the knots of the surface built.
    GenerateNote(Box<Note>),
    /// An error of fitting (cagd-fit).
    Fit(Box<FitError>),
    /// Why the parameters of a fit's data are not exact (cagd-fit).
    Parameters(Box<ParameterError>),
    /// An error of triangular patches (cagd-triangle).
    Triangle(Box<TriangleError>),
    /// Reading a problem as a whole (its JSON, keys, operation, field, values, a batch).
    Contract(Box<contract::Contract>),
    /// Reading the leaves of a problem (numbers, points, shapes, their limits).
    Read(Box<read::Read>),
    /// The curve operations.
    Curve(Box<curve::Curve>),
    /// The surface operations (chapters 5 and 6).
    Patch(Box<surface::Surface>),
    /// Triangles and fitting.
    Fitting(Box<fitting::Fitting>),
    /// What a limit of the run refuses to build.
    Limited(Box<limited::Limited>),
    /// Checking an answer against what the problem expects.
    Check(Box<check::Check>),
}

impl cagd_words::Message for Message {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            Message::Scalar(e) => e.phrase(lang),
            Message::Linalg(e) => e.phrase(lang),
            Message::Poly(e) => e.phrase(lang),
            Message::Roots(e) => e.phrase(lang),
            Message::Bezier(e) => e.phrase(lang),
            Message::BSpline(e) => e.phrase(lang),
            Message::Reduction(e) => e.phrase(lang),
            Message::Length(e) => e.phrase(lang),
            Message::LengthNotGiven(e) => e.phrase(lang),
            Message::Area(e) => e.phrase(lang),
            Message::Arc(e) => e.phrase(lang),
            Message::Split(e) => e.phrase(lang),
            Message::SplineReduction(e) => e.phrase(lang),
            Message::Surface(e) => e.phrase(lang),
            Message::SplineSurface(e) => e.phrase(lang),
            Message::Lines(e) => e.phrase(lang),
            Message::Curvature(e) => e.phrase(lang),
            Message::Smoothness(s) => s.phrase(lang),
            Message::ConditionFails(c) => c.phrase(lang),
            Message::DegenerateCorner(d) => d.phrase(lang),
            Message::Generate(e) => e.phrase(lang),
            Message::GenerateNote(n) => n.phrase(lang),
            Message::Fit(e) => e.phrase(lang),
            Message::Parameters(e) => e.phrase(lang),
            Message::Triangle(e) => e.phrase(lang),
            Message::Read(m) => m.phrase(lang),
            Message::Contract(m) => m.phrase(lang),
            Message::Curve(m) => m.phrase(lang),
            Message::Patch(m) => m.phrase(lang),
            Message::Fitting(m) => m.phrase(lang),
            Message::Check(m) => m.phrase(lang),
            Message::Limited(m) => m.phrase(lang),
        }
    }
}

impl fmt::Display for Message {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&cagd_words::Message::english(self))
    }
}

impl Message {
    /// The limit of the run this message is a refusal by: a limit of the grammar (an
    /// exponent, a depth, digits) or of the expression reader (a power, a coefficient), or a
    /// reading refusal, read from the typed errors.
    pub fn limit(&self) -> Option<Limit> {
        match self {
            Message::Read(r) => r.limit(),
            Message::Scalar(e) => Limit::of_scalar(e),
            Message::Poly(e) => Limit::of_poly(e),
            _ => None,
        }
    }
}

/// A message held inside another (see [`inner`]).
impl inner::Sentence for Message {
    fn limit(&self) -> Option<Limit> {
        Message::limit(self)
    }

    fn same(&self, other: &dyn inner::Sentence) -> bool {
        other.as_any().downcast_ref::<Message>() == Some(self)
    }

    fn as_any(&self) -> &dyn std::any::Any {
        self
    }
}

impl Inner {
    /// The sentence `m`, held inside another.
    pub fn new(m: impl Into<Message>) -> Inner {
        Inner::hold(m.into())
    }
}

impl<M: Into<Message>> From<M> for Inner {
    fn from(m: M) -> Inner {
        Inner::new(m)
    }
}

/// A sentence of its own, for the tests that enumerate every message.
impl Default for Inner {
    fn default() -> Inner {
        Inner::new(contract::Contract::Missing)
    }
}

impl check::Check {
    /// A value that cannot be read, or an engine's error, as a mismatch.
    pub fn unread(m: impl Into<Message>) -> check::Check {
        check::Check::Unread {
            inner: Inner::new(m),
        }
    }
}

/// A message equals the text of its English (what the JSON writes).
impl PartialEq<str> for Message {
    fn eq(&self, other: &str) -> bool {
        cagd_words::Message::english(self) == other
    }
}

impl PartialEq<&str> for Message {
    fn eq(&self, other: &&str) -> bool {
        cagd_words::Message::english(self) == *other
    }
}

/// A message is written in JSON as its English text.
impl Serialize for Message {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.collect_str(self)
    }
}

macro_rules! from_error {
    ($($e:ty => $v:ident),+ $(,)?) => {$(
        impl From<$e> for Message {
            fn from(e: $e) -> Message {
                Message::$v(Box::new(e))
            }
        }
    )+};
}

from_error!(
    ScalarError => Scalar,
    LinalgError => Linalg,
    PolyError => Poly,
    RootsError => Roots,
    BezierError => Bezier,
    BSplineError => BSpline,
    ReductionError => Reduction,
    LengthError => Length,
    LengthNotGiven => LengthNotGiven,
    AreaError => Area,
    ArcError => Arc,
    SplitError => Split,
    SplineReductionError => SplineReduction,
    SurfaceError => Surface,
    SplineSurfaceError => SplineSurface,
    LinesError => Lines,
    CurvatureError => Curvature,
    Smoothness => Smoothness,
    ConditionFails => ConditionFails,
    DegenerateCorner => DegenerateCorner,
    GenerateError => Generate,
    Note => GenerateNote,
    FitError => Fit,
    ParameterError => Parameters,
    TriangleError => Triangle,
    read::Read => Read,
    contract::Contract => Contract,
    curve::Curve => Curve,
    surface::Surface => Patch,
    fitting::Fitting => Fitting,
    check::Check => Check,
    limited::Limited => Limited,
);
