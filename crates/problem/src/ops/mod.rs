//! The operations, grouped by the notes' chapters: curves, surfaces (chapter 5), generation
//! (chapter 6), triangles, fitting; the operations on the control points of any curve or
//! patch, and `reverse`. [`dispatch`] holds the one `match` on the typed operation; [`out`]
//! what an operation produces. A chapter uses the shared modules ([`out`], [`explain`],
//! [`pieces`], [`zeros`]) and earlier chapters, never a later one.

pub(crate) mod control_points;
pub(crate) mod curves;
pub(crate) mod dispatch;
pub(crate) mod explain;
pub(crate) mod fitting;
pub(crate) mod generation;
pub(crate) mod out;
pub(crate) mod pieces;
pub(crate) mod reverse;
pub(crate) mod surfaces;
pub(crate) mod triangles;
pub(crate) mod zeros;
