//! The typed shapes of a problem's values, read with serde: exact numbers, points, meshes,
//! expressions, curves and surfaces (`docs/format.md`, Shapes).
//!
//! Each value is read once, by the one grammar, under the [`Limits`] of the run, and checked
//! where it is read (a point's dimension, a mesh's rows, the count of weights), so that an
//! error carries the path of the value at fault (`c1.bezier[2]`). The limits and the choice of
//! the number field are a per-thread reading context ([`read_with`]): serde's `Deserialize`
//! has no argument for them.
//!
//! An error of the reading is typed ([`Typed`]: a [`Message`], its [`Limit`], the path below
//! the value serde was reading). serde's `Deserialize` can only return an error made from a
//! text, so a reader stashes its typed error on the thread ([`Typed::serde`]) and returns its
//! English text; the one place that reads serde's errors takes it back by that text
//! ([`take_typed`]).

mod context;
#[macro_use]
mod refuse;
mod curve;
mod expr;
mod number;
mod points;
mod shape;
mod surface;

pub(crate) use context::{
    limits, read_value_typed, read_with, take_hints, take_homogeneous, take_typed, Typed,
};
pub use context::{read_value, repeating_decimal};
pub use expr::ExprIn;
pub(crate) use number::json_number;
pub use number::{Degree, Int, Num};
pub use points::{GridIn, List, MeshIn, Orders, Pair, PointData, PointIn, Points};
pub use shape::MAX_GENERIC_DEGREE;
pub(crate) use shape::{from_text, member_value};
