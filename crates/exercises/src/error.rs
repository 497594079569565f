use cagd_words::{said, Lang, Message, Phrase};

/// Why a problem set cannot be generated.
#[derive(Debug, Clone, PartialEq, Eq, strum::EnumIter)]
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

// TODO: `reason` holds the English words of the draw refused (a hole of data until typed).
impl Message for ExerciseError {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            ExerciseError::UnknownTopic { name } => {
                let topics = crate::topics()
                    .iter()
                    .map(|t| t.name)
                    .collect::<Vec<_>>()
                    .join(", ");
                said(
                    lang,
                    "unknown topic ‹›; the topics are: ‹›",
                    "tema desconocido ‹›; los temas son: ‹›",
                    [(&format!("{name:?}")).into(), (&topics).into()],
                )
            }
            ExerciseError::TooMany { count } => said(
                lang,
                "‹› problems asked for; a set has at most ‹› problems",
                "se pidieron ‹› problemas; una hoja tiene a lo sumo ‹› problemas",
                [count.into(), (&crate::MAX_COUNT).into()],
            ),
            ExerciseError::NoFriendlyProblem {
                topic,
                number,
                reason,
            } => said(
                lang,
                "could not draw problem ‹› of topic ‹› with friendly numbers in ‹› attempts (last: ‹›); try another seed",
                "no se pudo sortear el problema ‹› del tema ‹› con números sencillos en ‹› intentos (el último: ‹›); pruebe otra semilla",
                [
                    number.into(),
                    (&format!("{topic:?}")).into(),
                    (&crate::ATTEMPTS).into(),
                    reason.into(),
                ],
            ),
        }
    }
}

cagd_words::display_english!(ExerciseError);

impl std::error::Error for ExerciseError {}

#[cfg(test)]
mod tests {
    use super::*;
    use strum::IntoEnumIterator;

    #[test]
    fn every_variant_in_both_languages() {
        for m in ExerciseError::iter() {
            assert_eq!(cagd_words::check_both(&m), Ok(()), "{m:?}");
        }
    }
}
