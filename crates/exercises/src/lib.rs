//! Random exercises for students, behind `cagd generate --topic TOPIC --count N --seed S`:
//! problems of chapters 5 and 6 of the notes with small, friendly numbers (small integers and
//! halves, meshes laid on grids, parameters from {0, 1/4, 1/3, 1/2, 2/3, 3/4, 1}), as JSON
//! problems of `docs/format.md` ready for `cagd solve`, and their answer keys.
//!
//! Friendly answers are checked, not hoped for: every problem drawn is solved with
//! [`cagd_problem::solve`], and a draw whose data exceed [`MAX_DATA_DENOMINATOR`] or
//! [`MAX_DATA_INTEGER`], or whose exact answer (steps included) has a denominator above
//! [`MAX_ANSWER_DENOMINATOR`] or an integer above [`MAX_ANSWER_INTEGER`], is drawn again; so
//! is a problem [`alike`] an earlier one of its set (the same data up to one coordinate).
//! Constructions that the notes teach are built in: two patches C^1 by the condition (22)
//! (and others that are not), cylinders and cones (developable) next to free ruled patches,
//! Coons boundaries that meet at the corners (13), interpolation and least-squares data
//! computed from a small answer. Each topic draws its variants (a quadrant, half or full
//! turn; Bézier, rational and B-spline curves and patches where the operation takes them):
//! `docs/exercises.md` lists them with the numbers and bounds of each topic.
//!
//! The same (topic, count, seed) gives the same bytes: the generator is a SplitMix64 of its
//! own, each problem has its own stream (so a longer set starts with the problems of a
//! shorter one), and nothing iterates a hash map. The library does no I/O: a problem set is
//! returned as file names and contents ([`problem_set_files`]).
//!
//! ```
//! let problems = cagd_exercises::generate("restrict", 2, 7).unwrap();
//! assert_eq!(problems.len(), 2);
//! assert_eq!(problems[0]["name"], "restrict-1");
//! assert_eq!(problems[0]["op"], "restrict");
//! let answer = cagd_problem::solve(&problems[0]).unwrap();
//! assert!(answer.get("surface").is_some());
//! // The same seed gives the same problems.
//! assert_eq!(problems, cagd_exercises::generate("restrict", 2, 7).unwrap());
//! ```

mod draw;
mod error;
mod exam;
mod num;
mod rng;
mod sheet;
mod topics;

pub use cagd_keys::Lang;
pub use cagd_keys::SheetHeader;
pub use draw::alike;
pub use error::{ExerciseError, Refused};
pub use exam::{exam_files, exam_parts, generate_exam, ExamPart};
pub use sheet::{sheet_files, SetFigure};

use cagd_problem::{Answer, ProblemError};
use draw::Draft;
use rng::Rng;
use serde_json::{Map, Value};

/// The most problems one set may hold.
pub const MAX_COUNT: usize = 1000;

/// The most draws tried for one problem before giving up.
pub const ATTEMPTS: usize = 200;

/// The first draws of a problem in which a set looks for a variant it does not hold yet (a
/// full turn after a quadrant, a B-spline after a Bézier curve, another bidegree).
pub const NEW_VARIANT_ATTEMPTS: usize = 20;

/// The largest denominator an answer (steps included) may show.
pub const MAX_ANSWER_DENOMINATOR: u64 = 36;

/// The largest integer (numerator, coefficient) an answer (steps included) may show.
pub const MAX_ANSWER_INTEGER: u64 = 100;

/// The largest denominator a problem's data may show (halves, thirds and quarters).
pub const MAX_DATA_DENOMINATOR: u64 = 4;

/// The largest integer a problem's data may show (coordinates, coefficients, weights; the
/// angle of a partial turn, in degrees, is a setting and is not counted).
pub const MAX_DATA_INTEGER: u64 = 9;

/// A topic of the notes: one construction, one operation of `cagd solve`.
#[derive(Debug, Clone)]
pub struct Topic {
    /// The name given to `--topic` (`restrict`).
    pub name: &'static str,
    /// The operation of the problems (`docs/format.md`).
    pub op: &'static str,
    /// One line in English.
    pub description: &'static str,
    /// One line in Spanish, with the notes' vocabulary.
    pub description_es: &'static str,
    /// Where the notes teach it (`002_20d988b092ff1833.txt §4`).
    pub source: &'static str,
    pub(crate) draw: fn(&mut Rng) -> Draft,
}

impl Topic {
    /// The one-line description in `lang`.
    pub fn describe(&self, lang: Lang) -> &'static str {
        match lang {
            Lang::En => self.description,
            Lang::Es => self.description_es,
        }
    }
}

/// Every topic, in the order of the notes (chapter 5, then chapter 6).
pub fn topics() -> &'static [Topic] {
    topics::TOPICS
}

/// The topic called `name`.
pub fn topic(name: &str) -> Result<&'static Topic, ExerciseError> {
    topics()
        .iter()
        .find(|t| t.name == name)
        .ok_or_else(|| ExerciseError::UnknownTopic {
            name: name.to_string(),
        })
}

/// `count` problems of `topic` drawn from `seed`, titles in English: JSON objects
/// `{"name": "restrict-1", "title": ..., "source": ..., "op": ..., ...arguments}` with no
/// `expected` (the answer key comes from solving them).
pub fn generate(topic: &str, count: usize, seed: u64) -> Result<Vec<Value>, ExerciseError> {
    generate_in(topic, count, seed, Lang::En)
}

/// [`generate`] with the titles in `lang`: the same numbers in every language.
pub fn generate_in(
    topic: &str,
    count: usize,
    seed: u64,
    lang: Lang,
) -> Result<Vec<Value>, ExerciseError> {
    Ok(draw_set(topic, count, seed, lang)?
        .into_iter()
        .map(|(p, _)| p)
        .collect())
}

/// A problem and its answer (an error only for an operation this build cannot solve yet).
type Solved = (Value, Result<Answer, ProblemError>);

fn draw_set(
    topic: &str,
    count: usize,
    seed: u64,
    lang: Lang,
) -> Result<Vec<Solved>, ExerciseError> {
    let t = self::topic(topic)?;
    if count > MAX_COUNT {
        return Err(ExerciseError::TooMany { count });
    }
    let mut set: Vec<Solved> = Vec::with_capacity(count);
    for i in 0..count {
        let solved = draw_problem(t, seed, i, lang, &set)?;
        set.push(solved);
    }
    Ok(set)
}

/// Problem `index` of the set: the first draw of its own stream that is solved, friendly in
/// its data and its answer, and not alike an earlier problem of the set ([`draw::alike`]),
/// preferring in its first [`NEW_VARIANT_ATTEMPTS`] draws a variant the set does not hold;
/// when every draw is alike some earlier one (a set larger than the topic's variety), the
/// first friendly draw.
fn draw_problem(
    t: &Topic,
    seed: u64,
    index: usize,
    lang: Lang,
    earlier: &[Solved],
) -> Result<Solved, ExerciseError> {
    let mut rng = Rng::for_problem(seed, t.name, index);
    let mut reason = Refused::default();
    let mut fallback: Option<Solved> = None;
    for attempt in 0..ATTEMPTS {
        let draft = (t.draw)(&mut rng);
        let problem = to_problem(t, index, draft, lang);
        let repeated = earlier.iter().any(|(p, _)| draw::same_variant(p, &problem));
        if repeated && attempt < NEW_VARIANT_ATTEMPTS {
            continue;
        }
        let data = number_sizes(&draw::data(&problem));
        if !data.is_small_data() {
            reason = Refused::Unfriendly {
                denominator: data.largest_denominator,
                integer: data.largest_integer,
            };
            continue;
        }
        match cagd_problem::solve(&problem) {
            Ok(answer) => {
                let sizes = number_sizes(&answer.to_json(true));
                if sizes.is_friendly() {
                    if !earlier.iter().any(|(p, _)| draw::alike(p, &problem)) {
                        return Ok((problem, Ok(answer)));
                    }
                    fallback.get_or_insert((problem, Ok(answer)));
                    continue;
                }
                reason = Refused::Unfriendly {
                    denominator: sizes.largest_denominator,
                    integer: sizes.largest_integer,
                };
            }
            Err(e) => reason = Refused::Unsolved(Box::new(e)),
        }
    }
    if let Some(solved) = fallback {
        return Ok(solved);
    }
    Err(ExerciseError::NoFriendlyProblem {
        topic: t.name.to_string(),
        number: index + 1,
        reason,
    })
}

fn to_problem(t: &Topic, index: usize, draft: Draft, lang: Lang) -> Value {
    let mut m = Map::new();
    m.insert(
        "name".into(),
        Value::from(format!("{}-{}", t.name, index + 1)),
    );
    let title = match lang {
        Lang::En => draft.en,
        Lang::Es => draft.es,
    };
    m.insert("title".into(), Value::from(title));
    m.insert("source".into(), Value::from(t.source));
    m.insert("op".into(), Value::from(t.op));
    for (k, v) in draft.args {
        m.insert(k.into(), v);
    }
    Value::Object(m)
}

/// The sizes of the numbers written in a JSON value (a problem or an answer): the largest
/// denominator (a run of digits after `/`) and the largest other integer, in JSON numbers
/// and inside strings (`"27/2"`, `"(u, 3*v^2 - 1/4)"`, `"sqrt2/2"`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct NumberSizes {
    /// The largest denominator (1 when there is none).
    pub largest_denominator: u64,
    /// The largest integer or numerator, in absolute value (exponents and `sqrt2` count).
    pub largest_integer: u64,
}

impl NumberSizes {
    /// Within [`MAX_ANSWER_DENOMINATOR`] and [`MAX_ANSWER_INTEGER`].
    pub fn is_friendly(&self) -> bool {
        self.largest_denominator <= MAX_ANSWER_DENOMINATOR
            && self.largest_integer <= MAX_ANSWER_INTEGER
    }

    /// Within [`MAX_DATA_DENOMINATOR`] and [`MAX_DATA_INTEGER`] (a problem's data).
    pub fn is_small_data(&self) -> bool {
        self.largest_denominator <= MAX_DATA_DENOMINATOR && self.largest_integer <= MAX_DATA_INTEGER
    }

    fn see(&mut self, n: u64, denominator: bool) {
        if denominator {
            self.largest_denominator = self.largest_denominator.max(n);
        } else {
            self.largest_integer = self.largest_integer.max(n);
        }
    }

    fn scan(&mut self, s: &str) {
        let mut after_slash = false;
        let mut digits: Option<u64> = None;
        for c in s.chars().chain(std::iter::once(' ')) {
            if let Some(d) = c.to_digit(10) {
                digits = Some(
                    digits
                        .unwrap_or(0)
                        .saturating_mul(10)
                        .saturating_add(u64::from(d)),
                );
                continue;
            }
            if let Some(n) = digits.take() {
                self.see(n, after_slash);
                after_slash = false;
            }
            match c {
                '/' => after_slash = true,
                ' ' | '(' => {}
                _ => after_slash = false,
            }
        }
    }
}

/// Measures the numbers of a JSON value (see [`NumberSizes`]).
pub fn number_sizes(v: &Value) -> NumberSizes {
    fn walk(v: &Value, out: &mut NumberSizes) {
        match v {
            Value::Number(n) => {
                let x = n
                    .as_i64()
                    .map(i64::unsigned_abs)
                    .or_else(|| n.as_u64())
                    .unwrap_or(u64::MAX);
                out.see(x, false);
            }
            Value::String(s) => out.scan(s),
            Value::Array(xs) => xs.iter().for_each(|x| walk(x, out)),
            Value::Object(m) => m.values().for_each(|x| walk(x, out)),
            Value::Null | Value::Bool(_) => {}
        }
    }
    let mut out = NumberSizes {
        largest_denominator: 1,
        largest_integer: 0,
    };
    walk(v, &mut out);
    out
}

/// The text of a problem file: the JSON array, pretty-printed, with a final newline (what
/// `cagd generate` prints and writes as `problems.json`).
pub fn problems_json(problems: &[Value]) -> String {
    serde_json::to_string_pretty(problems).unwrap_or_default() + "\n"
}

/// A problem set of one topic as files, without writing them ([`sheet_files`]):
/// `problems.json` (the problems, titles in `lang`), the statement sheet `statements.tex`
/// (under the default header) and the answer keys `key.txt`, `key.md`, `key.tex` and
/// `key.json`. Problems are numbered from 1.
pub fn problem_set_files(
    topic: &str,
    count: usize,
    seed: u64,
    lang: Lang,
) -> Result<Vec<(String, String)>, ExerciseError> {
    problem_set_files_with(topic, count, seed, lang, &|_, _| None)
}

/// [`problem_set_files`] with figures: `figure` gives the path of each problem's figure, for
/// the statement sheet and for the key, included after the problem.
pub fn problem_set_files_with(
    topic: &str,
    count: usize,
    seed: u64,
    lang: Lang,
    figure: SetFigure<'_>,
) -> Result<Vec<(String, String)>, ExerciseError> {
    let parts = [ExamPart {
        topic: self::topic(topic)?.name.to_string(),
        count,
    }];
    if count > MAX_COUNT {
        return Err(ExerciseError::TooMany { count });
    }
    exam_files(&parts, seed, lang, &SheetHeader::default(), figure)
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    #[test]
    fn number_sizes_reads_denominators_and_integers() {
        let v = json!({"a": ["27/2", 3, "-5/12"], "b": "(u, 3*v^2 - 1/4)", "w": "sqrt2/2"});
        let s = number_sizes(&v);
        assert_eq!(s.largest_denominator, 12);
        assert_eq!(s.largest_integer, 27);
        assert!(s.is_friendly());
        let s = number_sizes(&json!(["1/289"]));
        assert_eq!(s.largest_denominator, 289);
        assert!(!s.is_friendly());
        // A closed form whose numerator is a parenthesis: (…)/(…) reads the denominator's
        // first integer.
        let s = number_sizes(&json!("(u)/(7*u + 1)"));
        assert_eq!(s.largest_denominator, 7);
        assert_eq!(number_sizes(&json!(null)).largest_denominator, 1);
    }

    #[test]
    fn unknown_topic_lists_the_topics() {
        let e = generate("spheres", 3, 1).unwrap_err();
        let text = e.to_string();
        assert!(text.starts_with(
            "unknown topic \"spheres\"; the topics are: closed_form, graph, evaluate"
        ));
        assert!(text.contains("revolution"));
    }

    #[test]
    fn too_many_problems_is_an_error() {
        let e = generate("graph", MAX_COUNT + 1, 1).unwrap_err();
        assert_eq!(
            e,
            ExerciseError::TooMany {
                count: MAX_COUNT + 1
            }
        );
        assert!(e.to_string().contains("at most 1000 problems"));
    }
}
