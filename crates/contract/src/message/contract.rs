//! Reading a problem as a whole: its JSON (serde's own messages, read in one place:
//! [`crate::problem::serde_error`]), its keys, its operation, its number field, its values, a
//! batch.

use super::found::Found;
use cagd_words::{said, Lang, Message, Phrase};
use std::time::Duration;

mod syntax;
pub use syntax::Syntax;

/// Reading a problem as a whole: its JSON, its keys, its operation, its number field, its
/// values, a batch and the limits of a problem's run.
#[derive(Debug, Clone, PartialEq, Eq, Default, strum::EnumIter)]
pub enum Contract {
    /// Memory refused before the work: what it was for would take more than the limit.
    MemoryRefused {
        /// What the memory was for.
        what: cagd_scalar::cancel::Claimed,
        /// The megabytes it would take.
        needs: u64,
        /// The limit, in megabytes.
        limit: usize,
    },
    // --- the problem as a whole ---
    /// A problem that is no JSON object.
    NotAProblem {
        /// What was given.
        found: Found,
    },
    /// No `op`.
    MissingOperation,
    /// An `op` that is no string.
    OperationNotAString {
        /// What was given.
        found: Found,
    },
    /// An `op` that names no operation.
    UnknownOperation {
        /// The name given.
        found: String,
        /// The operation nearest to it, when near enough to be a misspelling.
        nearest: Option<String>,
    },
    /// A problem that is not JSON (serde's message, typed).
    CannotRead {
        /// Why.
        why: Box<Contract>,
    },

    // --- keys and values: serde's own messages, typed ---
    /// A key the operation needs, missing.
    #[default]
    Missing,
    /// A key no reader takes.
    UnknownKey {
        /// The valid key nearest to it, when near enough to be a misspelling.
        nearest: Option<String>,
        /// What takes the keys: the operation, or the path of the object.
        owner: String,
        /// The keys it takes.
        valid: Vec<String>,
    },
    /// A word that is none of the words a key takes (`"basis": "bezeir"`).
    UnknownWord {
        /// The words it takes.
        valid: Vec<String>,
        /// The word given.
        found: String,
    },
    /// A value of the wrong kind.
    InvalidType {
        /// What was given.
        found: Found,
        /// What was expected.
        expected: Expected,
    },
    /// A value of the right kind out of range (serde's words).
    InvalidValue {
        /// What was given, in serde's words.
        found: String,
        /// What was expected.
        expected: String,
    },
    /// A list of the wrong length (serde's words).
    InvalidLength {
        /// Its length.
        len: usize,
        /// What was expected.
        expected: String,
    },
    /// A key written twice in an object.
    DuplicateKey {
        /// The key.
        key: String,
    },
    /// A text that is not JSON, at a place of it (line 0: no place).
    Syntax {
        /// What is wrong.
        what: Syntax,
        /// The line, from 1.
        line: usize,
        /// The column, from 1.
        column: usize,
    },
    /// A message of serde's this reading does not word (serde's text as it is).
    Serde {
        /// serde's text.
        text: String,
    },

    // --- letters ---
    /// A parameter that is not one letter.
    NotOneLetter {
        /// The name given, as written.
        found: String,
    },
    /// A parameter declared twice.
    DeclaredTwice {
        /// The parameter.
        name: String,
    },
    /// A value given for a letter not declared.
    NotDeclared {
        /// The letter.
        name: String,
    },
    /// `functions` given to an operation other than `revolution`.
    FunctionsOnlyInRevolution {
        /// The operation.
        op: String,
    },
    /// A letter declared both as a parameter and as a function.
    DeclaredBoth {
        /// The letter.
        name: String,
    },

    // --- the number field ---
    /// A number that needs √d in a problem that runs in Q(√d0).
    RootConflict {
        /// The d of this number.
        root: u64,
        /// What needs the other root first.
        first: RootSource,
        /// The other root's d0.
        first_root: u64,
    },

    // --- values ---
    /// A number in letters where the problem declares none.
    InLetters {
        /// The number, as text.
        number: String,
    },
    /// A value whose denominator vanishes at the values put in.
    VanishingAtValues {
        /// The value, as text.
        value: String,
    },
    /// The remark of an answer solved with the values put in.
    SolvedWith {
        /// The values, as the key writes them (`k = 0, a = 1/2`).
        values: String,
    },
    /// A verdict that differs between the answer in letters and the one at the values.
    Differs {
        /// The letters given values (`k, a`).
        letters: String,
        /// The result's path (`developable`, `pieces[1].developable`).
        result: String,
        /// The verdict in letters.
        general: Decided,
        /// The values (`k = 0`).
        at: String,
        /// The verdict at the values.
        special: Decided,
    },
    /// The remark of a verdict decided by an equality in letters.
    LettersIdentity,

    // --- a problem given as a host language's values (the Python module's dicts and lists) ---
    /// Lists and dicts nested deeper than the JSON reader reads.
    NestedTooDeep {
        /// The deepest nesting read.
        max: usize,
    },
    /// A floating-point number with a fraction part (or not finite).
    NotExact {
        /// The number, as the host prints it.
        value: String,
    },
    /// A key of a dict that is no string.
    KeyNotAString {
        /// The host's name of its type.
        found: String,
    },
    /// A value that is no number the reader knows.
    NotANumber {
        /// The host's name of its type.
        kind: String,
        /// The value, as the host shows it.
        shown: String,
    },
    /// A SymPy value with a `Float` in it.
    HoldsFloat {
        /// The value, as the host shows it.
        shown: String,
    },
    /// A string given as a problem that is not JSON.
    JsonStringNotJson {
        /// The line, from 1.
        line: usize,
        /// The column, from 1.
        column: usize,
        /// What serde_json says, typed ([`crate::problem::serde_error`]).
        why: Box<Contract>,
    },
    /// A string of the host that cannot be read (not valid Unicode).
    UnreadableString {
        /// What the host says.
        why: String,
    },
    /// An error the host raised while a value was read (its own words, as data).
    Host {
        /// What the host says.
        what: String,
    },

    // --- a batch and the limits of a run ---
    /// A problem of a batch whose bytes are not UTF-8 (the file they are in named by the
    /// batch), and what the file looks like.
    NotUtf8InBatch {
        /// The first byte that is not UTF-8 (`0xE9`), with its line and column (from 1) in the
        /// whole input; `None` for a wide encoding, seen from the start.
        at: Option<(String, usize, usize)>,
        /// The encoding it looks like (`Latin-1`).
        looks: String,
    },
    /// A problem past the batch's limit.
    BatchPastLimit {
        /// The problems of the batch.
        total: usize,
        /// The limit.
        limit: usize,
    },
    /// A solver thread that failed.
    SolverThreadFailed,
    /// A panic of the engine.
    InternalError {
        /// What the panic said.
        what: String,
    },
    /// A problem stopped at its deadline.
    Deadline {
        /// The deadline.
        seconds: Duration,
    },
    /// A problem stopped at its memory budget.
    MemoryStopped {
        /// The budget, in MB.
        limit: usize,
        /// What it held, in MB.
        held: u64,
    },
    /// A key whose writing was stopped at the deadline.
    WritingDeadline {
        /// The deadline.
        seconds: Duration,
    },
    /// A key whose writing was stopped at the memory budget.
    WritingMemory {
        /// The budget, in MB.
        limit: usize,
        /// What it held, in MB.
        held: u64,
    },
    /// The remark of an answer holding a number past the digit limit it was read under.
    DigitsPast {
        /// The digits of the longest number.
        most: usize,
        /// The digit limit.
        limit: usize,
    },
}

/// Backticks around a key: `` `key` `` (a key of the JSON stays as written in each language).
fn code(k: &str) -> String {
    format!("`{k}`")
}

/// Keys in backticks, separated by commas.
fn codes<S: AsRef<str>>(keys: &[S]) -> String {
    keys.iter()
        .map(|k| code(k.as_ref()))
        .collect::<Vec<_>>()
        .join(", ")
}

impl Message for Contract {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            Contract::MemoryRefused { what, needs, limit } => said(
                lang,
                "«» would take ‹› MB, more than the memory limit of ‹› MB: refused before the work",
                "«» ocuparían ‹› MB, más que el límite de memoria de ‹› MB: rechazado antes del cálculo",
                [what.phrase(lang).into(), needs.into(), limit.into()],
            ),
            Contract::NotAProblem { found } => said(
                lang,
                "expected a problem object ‹›, found «»",
                "se esperaba un objeto de problema ‹›, se encontró «»",
                [(&"{\"op\": ...}").into(), found.phrase(lang).into()],
            ),
            Contract::MissingOperation => said(
                lang,
                "missing: name the operation, one of ‹›",
                "falta: indique la operación, una de ‹›",
                [codes(crate::problem::NAMES).as_str().into()],
            ),
            Contract::OperationNotAString { found } => said(
                lang,
                "expected a string, found «»",
                "se esperaba una cadena, se encontró «»",
                [found.phrase(lang).into()],
            ),
            Contract::UnknownOperation { found, nearest } => {
                let operations = codes(crate::problem::NAMES);
                match nearest {
                    Some(k) => said(
                        lang,
                        "unknown operation ‹› (did you mean ‹›?); the operations are: ‹›",
                        "operación desconocida ‹› (¿quería decir ‹›?); las operaciones son: ‹›",
                        [
                            format!("{found:?}").as_str().into(),
                            format!("{k:?}").as_str().into(),
                            operations.as_str().into(),
                        ],
                    ),
                    None => said(
                        lang,
                        "unknown operation ‹›; the operations are: ‹›",
                        "operación desconocida ‹›; las operaciones son: ‹›",
                        [
                            format!("{found:?}").as_str().into(),
                            operations.as_str().into(),
                        ],
                    ),
                }
            }
            Contract::CannotRead { why } => said(
                lang,
                "cannot read the problem: «»",
                "no se puede leer el problema: «»",
                [why.phrase(lang).into()],
            ),
            Contract::Missing => said(
                lang,
                "missing (this operation needs it)",
                "falta (esta operación lo necesita)",
                [],
            ),
            Contract::UnknownKey {
                nearest,
                owner,
                valid,
            } => {
                let (owner, valid) = (code(owner), codes(valid));
                match nearest {
                    Some(k) => said(
                        lang,
                        "unknown key: did you mean ‹›? ‹› takes ‹›",
                        "clave desconocida: ¿quería decir ‹›? ‹› admite ‹›",
                        [
                            code(k).as_str().into(),
                            owner.as_str().into(),
                            valid.as_str().into(),
                        ],
                    ),
                    None => said(
                        lang,
                        "unknown key: ‹› takes ‹›",
                        "clave desconocida: ‹› admite ‹›",
                        [owner.as_str().into(), valid.as_str().into()],
                    ),
                }
            }
            Contract::UnknownWord { valid, found } => {
                let quoted: Vec<String> = valid.iter().map(|k| format!("{k:?}")).collect();
                let found = format!("{found:?}");
                match quoted.split_last() {
                    Some((last, rest)) if !rest.is_empty() => said(
                        lang,
                        "expected ‹› or ‹›, found ‹›",
                        "se esperaba ‹› o ‹›, se encontró ‹›",
                        [
                            rest.join(", ").as_str().into(),
                            last.as_str().into(),
                            found.as_str().into(),
                        ],
                    ),
                    _ => said(
                        lang,
                        "expected ‹›, found ‹›",
                        "se esperaba ‹›, se encontró ‹›",
                        [quoted.join("").as_str().into(), found.as_str().into()],
                    ),
                }
            }
            Contract::InvalidType { found, expected } => said(
                lang,
                "expected «», found «»",
                "se esperaba «», se encontró «»",
                [expected.phrase(lang).into(), found.phrase(lang).into()],
            ),
            Contract::InvalidValue { found, expected } => said(
                lang,
                "invalid value: ‹›, expected ‹›",
                "valor no válido: ‹›; se esperaba ‹›",
                [found.into(), expected.into()],
            ),
            Contract::InvalidLength { len, expected } => said(
                lang,
                "invalid length ‹›, expected ‹›",
                "longitud no válida: ‹›; se esperaba ‹›",
                [len.into(), expected.into()],
            ),
            Contract::DuplicateKey { key } => said(
                lang,
                "duplicate field ‹›",
                "clave repetida: ‹›",
                [code(key).as_str().into()],
            ),
            Contract::Syntax { what, line, column } => {
                if *line == 0 {
                    what.phrase(lang)
                } else {
                    said(
                        lang,
                        "«» at line ‹› column ‹›",
                        "«» en la línea ‹›, columna ‹›",
                        [what.phrase(lang).into(), line.into(), column.into()],
                    )
                }
            }
            Contract::Serde { text } => said(lang, "‹›", "‹›", [text.into()]),
            Contract::NotOneLetter { found } => said(
                lang,
                "expected a parameter of one letter (such as \"R\" or \"a\"), found ‹›",
                "se esperaba un parámetro de una letra (como \"R\" o \"a\"), se encontró ‹›",
                [format!("{found:?}").as_str().into()],
            ),
            Contract::DeclaredTwice { name } => said(
                lang,
                "the parameter ‹› is declared twice",
                "el parámetro ‹› se declara dos veces",
                [format!("{name:?}").as_str().into()],
            ),
            Contract::NotDeclared { name } => said(
                lang,
                "‹› is not a declared parameter (declare it in \"parameters\")",
                "‹› no es un parámetro declarado (declárelo en \"parameters\")",
                [format!("{name:?}").as_str().into()],
            ),
            Contract::FunctionsOnlyInRevolution { op } => said(
                lang,
                "‹› takes no functions of u: only ‹› does, for the parametrization \
                 $(f(u) cos v, f(u) sin v, g(u))$ of a profile $(f, 0, g)$",
                "‹› no admite funciones de u: solo las admite ‹›, para la \
                 parametrización $(f(u) cos v, f(u) sin v, g(u))$ de un perfil $(f, 0, g)$",
                [code(op).as_str().into(), code("revolution").as_str().into()],
            ),
            Contract::DeclaredBoth { name } => said(
                lang,
                "‹› is declared both as a parameter and as a function",
                "‹› se declara a la vez como parámetro y como función",
                [format!("{name:?}").as_str().into()],
            ),
            Contract::RootConflict {
                root,
                first,
                first_root,
            } => match first {
                RootSource::Operation => said(
                    lang,
                    "this number needs $√‹›$, but the operation needs $√‹›$: a problem runs in \
                     one field $a + b√d$",
                    "este número necesita $√‹›$, pero la operación necesita $√‹›$: un problema \
                     se resuelve en un solo cuerpo $a + b√d$",
                    [root.into(), first_root.into()],
                ),
                RootSource::Numbers => said(
                    lang,
                    "this number needs $√‹›$, but the problem's numbers need $√‹›$: a problem \
                     runs in one field $a + b√d$",
                    "este número necesita $√‹›$, pero los números del problema necesitan $√‹›$: \
                     un problema se resuelve en un solo cuerpo $a + b√d$",
                    [root.into(), first_root.into()],
                ),
                RootSource::At(path) => said(
                    lang,
                    "this number needs $√‹›$, but ‹› needs $√‹›$: a problem runs in one field \
                     $a + b√d$",
                    "este número necesita $√‹›$, pero ‹› necesita $√‹›$: un problema se \
                     resuelve en un solo cuerpo $a + b√d$",
                    [root.into(), path.into(), first_root.into()],
                ),
                RootSource::Unlocated => said(
                    lang,
                    "this number needs $√‹›$, but the first number that needs $√d$ needs \
                     $√‹›$: a problem runs in one field $a + b√d$",
                    "este número necesita $√‹›$, pero el primer número que necesita $√d$ \
                     necesita $√‹›$: un problema se resuelve en un solo cuerpo $a + b√d$",
                    [root.into(), first_root.into()],
                ),
            },
            Contract::InLetters { number } => said(
                lang,
                "‹› is in letters, but this problem declares no parameters",
                "‹› está en letras, pero este problema no declara parámetros",
                [number.into()],
            ),
            Contract::VanishingAtValues { value } => said(
                lang,
                "the value ‹› has a denominator that vanishes at these values",
                "el valor ‹› tiene un denominador que se anula en estos valores",
                [value.into()],
            ),
            Contract::SolvedWith { values } => said(
                lang,
                "the problem solved with ‹› put in",
                "el problema resuelto sustituyendo ‹›",
                [values.into()],
            ),
            Contract::Differs {
                letters,
                result,
                general,
                at,
                special,
            } => said(
                lang,
                "for general values of ‹›, ‹› is «»; at ‹› it is «»",
                "para valores generales de ‹›, ‹› es «»; para ‹› es «»",
                [
                    letters.into(),
                    code(result).as_str().into(),
                    general.phrase(lang).into(),
                    at.into(),
                    special.phrase(lang).into(),
                ],
            ),
            Contract::LettersIdentity => said(
                lang,
                "in letters, an equality that holds is an identity (it holds for all values of \
                 the letters), and one that fails, fails for general values (it may hold for \
                 special ones: put them in with \"values\")",
                "en letras, una igualdad que se cumple es una identidad (se cumple para todos \
                 los valores de las letras), y una que no se cumple falla para valores \
                 generales (puede cumplirse para valores particulares: sustitúyalos con \
                 \"values\")",
                [],
            ),
            Contract::NestedTooDeep { max } => said(
                lang,
                "lists and dicts nested deeper than ‹›",
                "listas y diccionarios anidados a más de ‹› niveles",
                [max.into()],
            ),
            Contract::NotExact { value } => said(
                lang,
                "‹› is not an exact number",
                "‹› no es un número exacto",
                [value.into()],
            ),
            Contract::KeyNotAString { found } => said(
                lang,
                "a key must be a string, found ‹›",
                "una clave ha de ser una cadena, se encontró ‹›",
                [found.into()],
            ),
            Contract::NotANumber { kind, shown } => said(
                lang,
                "cannot read ‹› (‹›) as a number: give an int, a fractions.Fraction, a SymPy \
                 number or a string of the grammar such as \"5/6\" or \"sqrt2/2\"",
                "no se puede leer ‹› (‹›) como número: dé un int, una fractions.Fraction, un \
                 número de SymPy o una cadena de la gramática como \"5/6\" o \"sqrt2/2\"",
                [kind.into(), shown.into()],
            ),
            Contract::HoldsFloat { shown } => said(
                lang,
                "‹› holds a SymPy Float, which is not exact: write sympy.Rational(1, 2) or \"1/2\"",
                "‹› contiene un Float de SymPy, que no es exacto: escriba sympy.Rational(1, 2) o \
                 \"1/2\"",
                [shown.into()],
            ),
            Contract::JsonStringNotJson { line, column, why } => said(
                lang,
                "the JSON string: not valid JSON at line ‹›, column ‹›: «»",
                "la cadena JSON: no es JSON válido en la línea ‹›, columna ‹›: «»",
                [line.into(), column.into(), why.phrase(lang).into()],
            ),
            Contract::UnreadableString { why } => said(
                lang,
                "cannot read the string: ‹›",
                "no se puede leer la cadena: ‹›",
                [why.into()],
            ),
            Contract::Host { what } => said(lang, "‹›", "‹›", [what.into()]),
            Contract::NotUtf8InBatch { at: None, looks } => said(
                lang,
                "the file is not UTF-8 (it looks like ‹›): save it as UTF-8",
                "el archivo no está en UTF-8 (parece ‹›): guárdelo en UTF-8",
                [looks.into()],
            ),
            Contract::NotUtf8InBatch {
                at: Some((byte, line, column)),
                looks,
            } => said(
                lang,
                "the file is not UTF-8: byte ‹› at line ‹›, column ‹› (it looks like ‹›): save it as UTF-8",
                "el archivo no está en UTF-8: byte ‹› en la línea ‹›, columna ‹› (parece ‹›): guárdelo en UTF-8",
                [byte.into(), line.into(), column.into(), looks.into()],
            ),
            Contract::BatchPastLimit { total, limit } => said(
                lang,
                "not solved: the batch holds ‹› problems, more than the limit of ‹›",
                "sin resolver: el lote tiene ‹› problemas, más que el límite de ‹›",
                [total.into(), limit.into()],
            ),
            Contract::SolverThreadFailed => said(
                lang,
                "the solver thread failed",
                "falló el hilo que resolvía el problema",
                [],
            ),
            Contract::InternalError { what } => said(
                lang,
                "internal error (a bug of cagd-exact, please report it with this problem): ‹›",
                "error interno (un fallo de cagd-exact; por favor, comuníquelo con este \
                 problema): ‹›",
                [what.into()],
            ),
            Contract::Deadline { seconds } => said(
                lang,
                "not answered within the limit of ‹› s: the work was stopped",
                "sin respuesta dentro del límite de ‹› s: se detuvo el cálculo",
                [seconds.as_secs_f64().to_string().as_str().into()],
            ),
            Contract::MemoryStopped { limit, held } => said(
                lang,
                "not answered within the memory limit of ‹› MB: the work was stopped holding \
                 ‹› MB",
                "sin respuesta dentro del límite de memoria de ‹› MB: se detuvo el cálculo \
                 con ‹› MB ocupados",
                [limit.into(), held.into()],
            ),
            Contract::WritingDeadline { seconds } => said(
                lang,
                "not written within the limit of ‹› s: the answer was found, and writing its \
                 key was stopped",
                "sin escribir dentro del límite de ‹› s: se halló la respuesta, y se detuvo al \
                 escribirla",
                [seconds.as_secs_f64().to_string().as_str().into()],
            ),
            Contract::WritingMemory { limit, held } => said(
                lang,
                "not written within the memory limit of ‹› MB: the answer was found, and \
                 writing its key was stopped holding ‹› MB",
                "sin escribir dentro del límite de memoria de ‹› MB: se halló la respuesta, y \
                 se detuvo al escribirla con ‹› MB ocupados",
                [limit.into(), held.into()],
            ),
            Contract::DigitsPast { most, limit } => said(
                lang,
                "a number of this answer has ‹› digits, more than the digit limit of ‹› it was \
                 read under: to feed the answer back as a problem, raise the digit limit to ‹› \
                 or more",
                "un número de esta respuesta tiene ‹› cifras, más que el límite de ‹› cifras \
                 con el que se leyó: para darla de nuevo como problema, suba el límite de \
                 cifras a ‹› o más",
                [most.into(), limit.into(), most.into()],
            ),
        }
    }
}

cagd_words::display_english!(Contract);

/// What a value of the wrong kind should have been.
#[derive(Debug, Clone, PartialEq, Eq, Default, strum::EnumIter)]
pub enum Expected {
    /// A string.
    #[default]
    String,
    /// `true` or `false`.
    Bool,
    /// A number.
    Number,
    /// A list.
    List,
    /// A list of points.
    ListOfPoints,
    /// A point.
    Point,
    /// A mesh.
    Mesh,
    /// A row of a mesh.
    Row,
    /// An expression.
    Expression,
    /// A parameter: t, or [u, v].
    NumberOrPair,
    /// A degree elevation: r, or [r, s].
    IntegerOrTwo,
    /// Two degrees.
    TwoDegrees,
    /// Something else, in the reader's words.
    Other(String),
}

impl Expected {
    /// What a reader said it expects (its `expecting`), typed where it is known.
    pub fn from_words(words: &str) -> Expected {
        match words {
            "a string" | "string" | "variant identifier" => Expected::String,
            "a boolean" | "boolean" => Expected::Bool,
            "a number" => Expected::Number,
            "a list" => Expected::List,
            "a list of points" => Expected::ListOfPoints,
            "a point" => Expected::Point,
            "a mesh" => Expected::Mesh,
            "a row" => Expected::Row,
            "an expression" => Expected::Expression,
            "a number t or a pair [u, v]" => Expected::NumberOrPair,
            "an integer or two [r, s]" => Expected::IntegerOrTwo,
            "two degrees" => Expected::TwoDegrees,
            other => Expected::Other(other.to_string()),
        }
    }
}

impl Message for Expected {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            Expected::String => said(lang, "a string", "una cadena", []),
            Expected::Bool => said(
                lang,
                "‹› or ‹›",
                "‹› o ‹›",
                [(&"true").into(), (&"false").into()],
            ),
            Expected::Number => said(lang, "a number", "un número", []),
            Expected::List => said(lang, "a list", "una lista", []),
            Expected::ListOfPoints => said(lang, "a list of points", "una lista de puntos", []),
            Expected::Point => said(lang, "a point", "un punto", []),
            Expected::Mesh => said(lang, "a mesh", "una malla de control", []),
            Expected::Row => said(lang, "a row", "una fila", []),
            Expected::Expression => said(lang, "an expression", "una expresión", []),
            Expected::NumberOrPair => said(
                lang,
                "a number t or a pair [u, v]",
                "un número t o un par [u, v]",
                [],
            ),
            Expected::IntegerOrTwo => said(
                lang,
                "an integer or two [r, s]",
                "un entero o dos [r, s]",
                [],
            ),
            Expected::TwoDegrees => said(lang, "two degrees", "dos grados", []),
            Expected::Other(s) => said(lang, "‹›", "‹›", [s.into()]),
        }
    }
}

/// What needed the other square root first, in a [`Contract::RootConflict`].
#[derive(Debug, Clone, PartialEq, Eq, Default, strum::EnumIter)]
pub enum RootSource {
    /// The operation itself (circles of quarter arcs need √2).
    #[default]
    Operation,
    /// The problem's numbers (a value given in `values` against them).
    Numbers,
    /// The number at this path.
    At(String),
    /// The first number that needs it, not located.
    Unlocated,
}

/// A verdict among the results (yes or no, an order), as a remark on values words it.
#[derive(Debug, Clone, PartialEq, Eq, Default, strum::EnumIter)]
pub enum Decided {
    /// Yes.
    #[default]
    Yes,
    /// No.
    No,
    /// An order, an integer.
    Order(i64),
    /// An infinite order.
    Infinite,
}

impl Message for Decided {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            Decided::Yes => said(lang, "yes", "sí", []),
            Decided::No => said(lang, "no", "no", []),
            Decided::Order(k) => said(lang, "‹›", "‹›", [k.into()]),
            Decided::Infinite => said(lang, "infinite", "infinito", []),
        }
    }
}

#[cfg(test)]
mod tests;
