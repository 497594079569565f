//! Formula fixtures: a general formula of the notes, derived by the engine on a generic mesh
//! and compared with the print.
//!
//! A fixture with `"formula"` runs its operation on a generic polygon or mesh (`{"generic":
//! "c", "degree": [2, 2]}`), so the answer is the general formula for that degree in the
//! letters c_{i,j}. The notes' printed formula, in the indices `i, j` and the degrees (`m, n`),
//! is then instantiated at every entry of the result (`c_{i-1,j}` at i = 1, j = 0 is c_{0,0};
//! a point outside the mesh, such as c_{-1,0}, is 0, as the notes' sums take it) and compared
//! exactly with what the engine derived. Every difference is an erratum found by computing;
//! the fixture's `errata` must record exactly those (a recorded one that the computation does
//! not find, or a found one not recorded, is a mismatch).

use schemars::JsonSchema;
use serde::Deserialize;
use std::collections::BTreeMap;

/// One formula, or several (the points and the weights of a result).
#[derive(Debug, Clone, PartialEq, Eq, Deserialize, JsonSchema)]
#[serde(untagged)]
pub enum Formulas {
    /// One formula.
    One(Formula),
    /// Several.
    Many(Vec<Formula>),
}

impl Formulas {
    /// The formulas.
    pub fn list(&self) -> &[Formula] {
        match self {
            Formulas::One(f) => std::slice::from_ref(f),
            Formulas::Many(fs) => fs,
        }
    }
}

/// The notes' general formula for the entries of a result.
#[derive(Debug, Clone, PartialEq, Eq, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Formula {
    /// The result whose entries it gives (`surface`, `curve`).
    pub result: String,
    /// The formula as the notes print it, in the indices `i` (and `j`) and the constants:
    /// `"(1 - i/(m+1)) c_{i,j} + i/(m+1) c_{i-1,j}"`; for points of several coordinates, one
    /// formula per coordinate.
    pub printed: Printed,
    /// The values of the other letters of the formula (`{"m": 2, "n": 2}`).
    #[serde(default)]
    pub constants: BTreeMap<String, i64>,
    /// What of the result is compared: `"points"` (default) or `"weights"`.
    #[serde(default)]
    pub part: Part,
    /// The dimensions of the generic input (`[m + 1, n + 1]` points, or `[n + 1]`): a point
    /// outside them is 0.
    pub input: Vec<usize>,
}

/// The part of a result a formula gives.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Deserialize, JsonSchema)]
#[serde(rename_all = "lowercase")]
pub enum Part {
    /// The points.
    #[default]
    Points,
    /// The weights.
    Weights,
}

/// A formula, or one per coordinate, or one per coordinate for each column j (the rows of a
/// surface of revolution: c_{i,0}, c_{i,1}, c_{i,2}).
#[derive(Debug, Clone, PartialEq, Eq, Deserialize, JsonSchema)]
#[serde(untagged)]
pub enum Printed {
    /// For one-dimensional points.
    One(String),
    /// One per coordinate.
    Coordinates(Vec<String>),
    /// For each column j, one per coordinate.
    Columns(Vec<Vec<String>>),
}

impl Printed {
    /// The formulas of the entry in column `j`.
    pub fn formulas(&self, j: Option<usize>) -> Vec<&str> {
        match self {
            Printed::One(f) => vec![f.as_str()],
            Printed::Coordinates(fs) => fs.iter().map(String::as_str).collect(),
            Printed::Columns(cols) => j
                .and_then(|j| cols.get(j))
                .map(|fs| fs.iter().map(String::as_str).collect())
                .unwrap_or_default(),
        }
    }

    /// All formulas, for the explanation of an erratum.
    pub fn all(&self) -> Vec<&str> {
        match self {
            Printed::One(f) => vec![f.as_str()],
            Printed::Coordinates(fs) => fs.iter().map(String::as_str).collect(),
            Printed::Columns(cols) => cols.iter().flatten().map(String::as_str).collect(),
        }
    }
}
