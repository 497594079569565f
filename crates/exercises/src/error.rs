use std::fmt;

/// Why a problem set cannot be generated.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub enum ExerciseError {
    /// The topic is not one of [`crate::topics`].
    UnknownTopic {
        /// The name asked for.
        name: String,
    },
    /// More problems than [`crate::MAX_COUNT`] were asked for.
    TooMany {
        /// The count asked for.
        count: usize,
    },
    /// No problem with friendly numbers was found in [`crate::ATTEMPTS`] draws (a bug of the
    /// generator for this topic; another seed will do meanwhile).
    NoFriendlyProblem {
        /// The topic.
        topic: String,
        /// The problem's number (from 1).
        number: usize,
        /// The last reason a draw was refused.
        reason: String,
    },
}

impl fmt::Display for ExerciseError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ExerciseError::UnknownTopic { name } => write!(
                f,
                "unknown topic {name:?}; the topics are: {}",
                crate::topics()
                    .iter()
                    .map(|t| t.name)
                    .collect::<Vec<_>>()
                    .join(", ")
            ),
            ExerciseError::TooMany { count } => write!(
                f,
                "{count} problems asked for; a set has at most {} problems",
                crate::MAX_COUNT
            ),
            ExerciseError::NoFriendlyProblem {
                topic,
                number,
                reason,
            } => write!(
                f,
                "could not draw problem {number} of topic {topic:?} with friendly numbers in {} attempts (last: {reason}); try another seed",
                crate::ATTEMPTS
            ),
        }
    }
}

impl std::error::Error for ExerciseError {}
