//! Curves: evaluation, elevation, restriction, derivatives, knot insertion, circles and
//! arcs, the contact of two curves, arc lengths, degree reduction, splitting.

pub(crate) mod arc;
pub(crate) mod curve;
pub(crate) mod integral;
pub(crate) mod inversion;
pub(crate) mod join;
pub(crate) mod knots;
pub(crate) mod length;
pub(crate) mod length_answer;
pub(crate) mod length_rational;
pub(crate) mod reduce;
pub(crate) mod split;
