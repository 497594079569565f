use crate::limits::Limit;
use crate::Message;
use std::fmt;

/// A problem that cannot be answered: which problem (its index in a batch), which field, and why.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ProblemError {
    /// The problem's index in the batch (`None` for a single problem).
    pub index: Option<usize>,
    /// The field, as a path: `c1.bezier[2]`, `u`, `op`. Empty when the whole problem is at fault.
    pub field: String,
    /// What is wrong, typed (worded in each language by [`cagd_words::Message`]).
    pub message: Message,
    /// The limit the problem is past, when that is what is wrong: a front end says how to
    /// raise it (`cagd solve` names its flag).
    pub limit: Option<Limit>,
}

impl ProblemError {
    /// An error at `field`.
    pub fn at(field: impl Into<String>, message: impl Into<Message>) -> Self {
        ProblemError {
            index: None,
            field: field.into(),
            message: message.into(),
            limit: None,
        }
    }

    /// A refusal at `field` by `limit`.
    pub fn limit(field: impl Into<String>, message: impl Into<Message>, limit: Limit) -> Self {
        ProblemError {
            limit: Some(limit),
            ..ProblemError::at(field, message)
        }
    }

    /// The same error, for problem `index` of a batch.
    pub fn in_problem(mut self, index: usize) -> Self {
        self.index = Some(index);
        self
    }
}

impl fmt::Display for ProblemError {
    /// One line: `problem 3: field c1.bezier[2]: expected a point ...`, problems numbered from
    /// 1 (the index is counted from 0).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if let Some(i) = self.index {
            write!(f, "problem {}: ", i + 1)?;
        }
        if !self.field.is_empty() {
            write!(f, "field `{}`: ", self.field)?;
        }
        // Keep it on one line whatever the inner message says.
        write!(f, "{}", self.message.to_string().replace('\n', " "))
    }
}

impl std::error::Error for ProblemError {}

/// The error in words, as [`ProblemError`]'s `Display` writes it in English: the problem's
/// number (from 1), the field, the message on one line.
impl cagd_words::Message for ProblemError {
    fn phrase(&self, lang: cagd_words::Lang) -> cagd_words::Phrase {
        use cagd_words::said;
        let m = cagd_words::Message::phrase(&self.message, lang);
        match (self.index, self.field.is_empty()) {
            (Some(i), false) => said(
                lang,
                "problem ‹›: field `‹›`: «»",
                "problema ‹›: campo `‹›`: «»",
                [(&(i + 1)).into(), (&self.field).into(), m.into()],
            ),
            (Some(i), true) => said(
                lang,
                "problem ‹›: «»",
                "problema ‹›: «»",
                [(&(i + 1)).into(), m.into()],
            ),
            (None, false) => said(
                lang,
                "field `‹›`: «»",
                "campo `‹›`: «»",
                [(&self.field).into(), m.into()],
            ),
            (None, true) => m,
        }
    }
}
