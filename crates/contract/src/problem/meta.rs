//! The fixture's block of a problem ([`Meta`]): its name, source, equation, expected answer and
//! errata.

use schemars::JsonSchema;
use serde::Deserialize;
use serde_json::Value;

/// What a fixture (or a teacher's problem for `cagd check`) says besides the problem.
#[derive(Debug, Clone, PartialEq, Default, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Meta {
    /// A short name (`ch6-coons-bezier`).
    pub name: Option<String>,
    /// A title in words.
    pub title: Option<String>,
    /// Where in the notes.
    pub source: Option<String>,
    /// The notes' equation numbers.
    pub equation: Option<String>,
    /// A remark about the example.
    pub note: Option<String>,
    /// The exact answer, in the shapes of the answers (`docs/format.md`), checked by name.
    // Present is `Some`, even as `null` (which the check then refuses): a key written is
    // never taken for a key left out.
    #[schemars(with = "Option<crate::expected_schema::Expected>")]
    #[serde(default, deserialize_with = "present")]
    pub expected: Option<Value>,
    /// What the notes print where they are wrong.
    #[serde(default)]
    pub errata: Vec<Erratum>,
    /// The letters the problem's numbers may use (`["R"]`, `["a", "b", "c", "d"]`): the
    /// problem then runs in the field of quotients of polynomials in them, and its answer is
    /// in letters. An undeclared letter is an error, so a typo is caught.
    #[serde(default)]
    pub parameters: Vec<String>,
    /// A general formula of the notes that the answer is compared with, entry by entry (see
    /// the module `formula`): the errata it finds are computed, and must be the ones
    /// recorded.
    #[serde(default)]
    pub formula: Option<crate::formula::Formulas>,
    /// Letters that stand for functions of u (`["f", "g"]`: the profile `(f, 0, g)` is the
    /// notes' `(f(u), 0, g(u))`); only `revolution` takes them, for its parametrization (21).
    #[serde(default)]
    pub functions: Vec<String>,
    /// Values of parameters (`{"R": 2}`): the problem is solved with them put into its numbers
    /// (each key a declared parameter, each value an exact number).
    #[serde(default)]
    pub values: serde_json::Map<String, Value>,
    /// The title and the note in Spanish, for the keys in Spanish (`--lang es`).
    #[serde(default)]
    pub es: Option<MetaEs>,
    /// The student whose answer `expected` is, when one file holds a class's answers
    /// (`cagd check`).
    pub student: Option<String>,
}

impl Meta {
    /// Whether the problem is an example of the notes: its `source` names one of their files
    /// (`002_20d988b092ff1833.txt §5`). Only then does a verdict say it matches *the notes*;
    /// any other problem matches its expected answer.
    pub fn from_notes(&self) -> bool {
        self.source.as_deref().is_some_and(|s| s.contains(".txt"))
    }
}

/// A fixture's words in Spanish: what the keys in Spanish print instead of `title` and `note`.
#[derive(Debug, Clone, PartialEq, Eq, Default, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct MetaEs {
    /// The title.
    pub title: Option<String>,
    /// The note.
    pub note: Option<String>,
}

/// A value that is present, `null` included.
fn present<'de, D: serde::Deserializer<'de>>(d: D) -> Result<Option<Value>, D::Error> {
    Value::deserialize(d).map(Some)
}

/// An erratum of the notes, as a fixture records it.
#[derive(Debug, Clone, PartialEq, Eq, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Erratum {
    /// Where in the notes (a step, an equation).
    #[serde(rename = "where", default)]
    pub place: String,
    /// What the notes print.
    #[serde(default)]
    pub printed: String,
    /// The exact value.
    #[serde(default)]
    pub exact: String,
    /// Why.
    #[serde(default)]
    pub why: String,
    /// What kind of erratum: a wrong value (the default), or a scale (what the notes print
    /// is the exact vector divided by `factor`: the direction is the same).
    #[serde(default)]
    pub kind: ErratumKind,
    /// For a [`ErratumKind::Scale`]: the factor, exact = factor × printed (`"4"`); the check
    /// of a formula fixture verifies it on the derived values, so that `printed` and `exact`
    /// can be the notes' factored formulas.
    #[serde(default)]
    pub factor: String,
    /// The same in Spanish (each field that has words), for the keys in Spanish.
    #[serde(default)]
    pub es: Option<ErratumEs>,
}

/// The kind of an erratum of the notes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Deserialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum ErratumKind {
    /// The notes print a wrong value.
    #[default]
    Value,
    /// The notes print a vector that is the exact one divided by a factor: a scale, the
    /// direction is the same (a missing factor mn in a normal vector, (25)).
    Scale,
}

impl ErratumKind {
    /// The words of a key before an erratum of this kind, what the notes print and the
    /// exact value, in `lang`: `(erratum, the notes print, the exact value is)`.
    pub fn words(self, lang: cagd_words::Lang) -> [&'static str; 3] {
        use cagd_words::Lang;
        match (self, lang) {
            (ErratumKind::Value, Lang::En) => ["erratum", "the notes print", "the exact value is"],
            (ErratumKind::Value, Lang::Es) => ["errata", "los apuntes dicen", "el valor exacto es"],
            (ErratumKind::Scale, Lang::En) => [
                "erratum of scale (the direction is the same)",
                "the notes print",
                "the exact vector is",
            ],
            (ErratumKind::Scale, Lang::Es) => [
                "errata de escala (la dirección es la misma)",
                "los apuntes imprimen",
                "el vector exacto es",
            ],
        }
    }
}

/// An erratum's words in Spanish; a field left out is printed as the English one (a formula).
#[derive(Debug, Clone, PartialEq, Eq, Default, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct ErratumEs {
    /// Where in the notes.
    #[serde(rename = "where")]
    pub place: Option<String>,
    /// What the notes print.
    pub printed: Option<String>,
    /// The exact value.
    pub exact: Option<String>,
    /// Why.
    pub why: Option<String>,
}
