//! The typed operation ([`Op`], one variant per operation of [`super::names`]) and the typed problem
//! ([`Problem`]).

use super::args::*;
use super::meta::Meta;
use super::names::operations_table;
use crate::field::NumberField;
use crate::value::exact::Number;
use cagd_param::Name;
use schemars::JsonSchema;
use serde::de::Deserializer;
use serde::Deserialize;

macro_rules! operations {
    ($($name:literal => $variant:ident($args:ident),)*) => {
        /// An operation and its arguments.
        // One value per problem, read once and kept: the size of the largest variant is no
        // cost worth a box.
        #[allow(clippy::large_enum_variant)]
        #[derive(Debug, Clone, PartialEq)]
        pub enum Op {
            $(
                #[doc = concat!("`", $name, "`")]
                $variant($args),
            )*
        }

        impl Op {
            /// The operation's name (`"coons"`).
            pub fn name(&self) -> &'static str {
                match self {
                    $(Op::$variant(_) => $name,)*
                }
            }

            /// Reads the arguments of the operation `name` from `args`.
            pub(super) fn read<'de, D: Deserializer<'de>>(name: &str, args: D) -> Option<Result<Op, D::Error>> {
                match name {
                    $($name => Some($args::deserialize(args).map(Op::$variant)),)*
                    _ => None,
                }
            }
        }

        /// The schema of each operation's arguments (its struct's, as derived), by name, in
        /// the order of [`super::NAMES`].
        pub(crate) fn argument_schemas(
            generator: &mut schemars::SchemaGenerator,
        ) -> Vec<(&'static str, schemars::Schema)> {
            vec![$(($name, <$args as JsonSchema>::json_schema(generator)),)*]
        }
    };
}

operations_table!(operations);

/// A problem: the operation with its arguments, the fixture's block, and the field it runs
/// in.
#[derive(Debug, Clone, PartialEq)]
pub struct Problem {
    /// The operation and its arguments.
    pub op: Op,
    /// The fixture's fields.
    pub meta: Meta,
    /// The number field of the problem's numbers (and of the operation's).
    pub field: NumberField,
    /// The keys of the arguments, in the order written (the answer key lists them so).
    pub order: Vec<String>,
    /// The parameters its numbers may use (from `meta.parameters`); empty for numbers only.
    pub parameters: Vec<Name>,
    /// The values the problem is solved at (from `meta.values`): put into its numbers before
    /// the solve.
    pub values: Vec<(Name, Number)>,
    /// Remarks on the reading, for the answer: a decimal such as `"0.3333"` is read exactly
    /// as 3333/10000, and 1/3 may be what is meant.
    pub hints: Vec<crate::Message>,
    /// Whether the problem wrote control points homogeneous (`"homogeneous": true`): its JSON
    /// answers write the rational curves and surfaces so too.
    pub homogeneous: bool,
}
