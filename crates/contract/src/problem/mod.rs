//! The typed problem: one variant per operation, read once from JSON with serde.
//!
//! A problem is an object `{"op": NAME, ...arguments}` (`docs/format.md`). Its arguments are
//! read into the operation's struct (unknown keys refused, with the nearest valid key named),
//! every number once, by the one grammar; the fixture fields (`name`, `title`, `source`,
//! `equation`, `note`, `expected`, `errata`) are a block of their own, [`Meta`]. The number
//! field (Q or Q(√d)) is the one the numbers were read in.

mod args;
mod argument;
mod inputs;
mod meta;
mod names;
pub(crate) mod op;
mod reading;

pub use args::*;
pub use argument::Argument;
pub use meta::{Erratum, ErratumEs, ErratumKind, Meta, MetaEs};
pub use names::NAMES;
pub(crate) use op::argument_schemas;
pub use op::{Op, Problem};
pub use reading::serde_error;
