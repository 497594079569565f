//! The contract of cagd-exact's door: the problem and answer format of `docs/format.md` as
//! inert types, and their readers. It solves nothing (the operations are cagd-ops'; solving,
//! checking and batches are cagd-problem's).
//!
//! A problem is an object `{"op": NAME, ...arguments}`, read once into a typed [`Problem`]
//! ([`problem`]: the operation and its arguments; [`spec`]: the leaf readers of numbers,
//! points and shapes, under the run's [`Limits`]), in the number field its numbers need
//! ([`field`]). An [`Answer`] holds the exact values computed ([`value`]) and is written as JSON
//! ([`answer`]); a [`Verdict`] says whether it matched what a fixture expects. Every error,
//! remark, mismatch and verdict sentence is a typed [`Message`] ([`message`]), worded in
//! English and Spanish beside its definition. [`schema`] is the JSON Schema of problems and
//! answers.

pub mod answer;
pub mod any;
pub mod any_curve;
pub mod any_surface;
pub mod convert;
pub mod diagnosis;
pub mod error;
pub mod expected_schema;
pub mod field;
pub mod formula;
pub mod input;
pub mod limit;
pub mod limits;
pub mod message;
pub mod pretty;
pub mod problem;
pub mod schema;
pub mod spec;
pub mod steps;
pub mod triangle;
pub mod value;
pub mod values;
pub mod verdict;

pub use answer::{error_json, Answer, AnswerJson, ErrorJson, Named};
pub use any::{AnyCurve, AnySurface};
pub use diagnosis::{Assessment, Catalogued, Mistake};
pub use error::ProblemError;
pub use field::NumberField;
pub use limits::{read_number, Limit, Limits};
pub use message::Message;
pub use pretty::Pretty;
pub use problem::{Argument, Erratum, ErratumKind, Meta, Op, Problem};
pub use value::{Exact, ExactScalar, Number, Quantity};
pub use verdict::{Verdict, VerdictJson};
