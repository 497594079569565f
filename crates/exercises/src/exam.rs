//! Exams of several topics: `coons,revolution:1,interpolate:3` read as parts ([`ExamPart`]),
//! their problems drawn topic after topic and numbered as one exam (Problem 1 to N), each
//! problem from its own stream as in a set of one topic, so an exam is deterministic per seed
//! and its problems of a topic are those of `--topic TOPIC` alone.

use crate::sheet::{sheet_files, SetFigure};
use crate::{draw_set, topic, ExerciseError, Lang, Solved, MAX_COUNT};
use cagd_keys::SheetHeader;
use cagd_problem::Verdict;
use serde_json::Value;

/// A part of an exam: a topic and how many of its problems.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ExamPart {
    /// The topic's name ([`crate::topics`]).
    pub topic: String,
    /// How many problems of it.
    pub count: usize,
}

/// Reads `coons,revolution:1,interpolate:3`: topics separated by commas, each with its count
/// after a colon, or `count` problems when it has none. A topic unknown, named twice, or a
/// count that is not a whole number is an error; so is an exam of more than
/// [`MAX_COUNT`] problems.
pub fn exam_parts(spec: &str, count: usize) -> Result<Vec<ExamPart>, ExerciseError> {
    let mut parts: Vec<ExamPart> = Vec::new();
    for piece in spec.split(',').map(str::trim) {
        let (name, n) = match piece.split_once(':') {
            Some((name, n)) => {
                let n = n
                    .trim()
                    .parse::<usize>()
                    .map_err(|_| ExerciseError::BadCount {
                        part: piece.to_string(),
                    })?;
                (name.trim(), n)
            }
            None => (piece, count),
        };
        let t = topic(name)?;
        if parts.iter().any(|p| p.topic == t.name) {
            return Err(ExerciseError::RepeatedTopic {
                name: t.name.to_string(),
            });
        }
        parts.push(ExamPart {
            topic: t.name.to_string(),
            count: n,
        });
    }
    let total: usize = parts.iter().map(|p| p.count).sum();
    if total > MAX_COUNT {
        return Err(ExerciseError::TooMany { count: total });
    }
    Ok(parts)
}

/// The problems of an exam and their answers, topic after topic.
fn draw_exam(parts: &[ExamPart], seed: u64, lang: Lang) -> Result<Vec<Solved>, ExerciseError> {
    let mut out = Vec::new();
    for p in parts {
        out.extend(draw_set(&p.topic, p.count, seed, lang)?);
    }
    Ok(out)
}

/// The problems of an exam drawn from `seed`, titles in `lang`, in the order of its parts.
pub fn generate_exam(
    parts: &[ExamPart],
    seed: u64,
    lang: Lang,
) -> Result<Vec<Value>, ExerciseError> {
    Ok(draw_exam(parts, seed, lang)?
        .into_iter()
        .map(|(p, _)| p)
        .collect())
}

/// The verdicts of solved problems, numbered from 1 in order.
fn verdicts(set: &[Solved]) -> Vec<Verdict> {
    set.iter()
        .enumerate()
        .map(|(i, (p, a))| Verdict {
            problem: match a {
                Ok(a) => Some(a.problem.clone()),
                Err(_) => cagd_problem::Problem::read(p, &cagd_problem::Limits::DEFAULT)
                    .ok()
                    .map(std::sync::Arc::new),
            },
            answer: a.clone(),
            mismatches: vec![],
            errata: vec![],
            checked: false,
            assessment: None,
            index: Some(i),
        })
        .collect()
}

/// The files of an exam ([`sheet_files`]): its problems numbered as one exam, under `header`,
/// with figures from `figure`.
pub fn exam_files(
    parts: &[ExamPart],
    seed: u64,
    lang: Lang,
    header: &SheetHeader,
    figure: SetFigure<'_>,
) -> Result<Vec<(String, String)>, ExerciseError> {
    let set = draw_exam(parts, seed, lang)?;
    let problems: Vec<Value> = set.iter().map(|(p, _)| p.clone()).collect();
    Ok(sheet_files(
        &problems,
        &verdicts(&set),
        header,
        lang,
        figure,
    ))
}
