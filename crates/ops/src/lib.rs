//! The operations, grouped by the notes' chapters: curves, surfaces (chapter 5), generation
//! (chapter 6), triangles, fitting; the operations on the control points of any curve or
//! patch, and `reverse`. [`dispatch`] holds the one `match` on the typed operation; [`out`]
//! what an operation produces. A chapter uses the shared modules ([`out`], [`explain`],
//! [`pieces`], [`zeros`]) and earlier chapters, never a later one.

// The contract's modules and types, by the paths the operations name them by.
pub(crate) use cagd_contract::{
    any, any_curve, convert, field, input, limits, message, problem, spec, steps, triangle, value,
    Exact, Message, Named, ProblemError, Quantity,
};

pub(crate) mod control_points;
pub(crate) mod curves;
pub mod dispatch;
pub(crate) mod explain;
pub(crate) mod fitting;
pub(crate) mod generation;
pub mod out;
pub(crate) mod pieces;
pub(crate) mod reverse;
pub(crate) mod surfaces;
pub(crate) mod triangles;
pub(crate) mod zeros;
