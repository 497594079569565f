use cagd_problem::ProblemError;
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
    /// A part of an exam whose count is not a whole number (`coons:two`).
    BadCount {
        /// The part as written.
        part: String,
    },
    /// A topic named twice in an exam.
    RepeatedTopic {
        /// The topic.
        name: String,
    },
    /// No problem with friendly numbers was found in [`crate::ATTEMPTS`] draws (a bug of the
    /// generator for this topic; another seed will do meanwhile).
    NoFriendlyProblem {
        /// The topic.
        topic: String,
        /// The problem's number (from 1).
        number: usize,
        /// The last reason a draw was refused.
        reason: Refused,
    },
}

/// Why a draw of a problem was refused ([`ExerciseError::NoFriendlyProblem`]).
#[derive(Debug, Clone, PartialEq, Eq, strum::EnumIter)]
#[non_exhaustive]
pub enum Refused {
    /// Its answer shows numbers that are not friendly.
    Unfriendly {
        /// The largest denominator shown.
        denominator: u64,
        /// The largest integer shown.
        integer: u64,
    },
    /// It could not be solved (enumerated with cagd-problem's messages).
    #[strum(disabled)]
    Unsolved(Box<ProblemError>),
}

impl Default for Refused {
    fn default() -> Self {
        Refused::Unfriendly {
            denominator: 0,
            integer: 0,
        }
    }
}

impl Message for Refused {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            Refused::Unfriendly {
                denominator,
                integer,
            } => said(
                lang,
                "the answer shows a denominator ‹› and an integer ‹›",
                "la respuesta muestra un denominador ‹› y un entero ‹›",
                [denominator.into(), integer.into()],
            ),
            Refused::Unsolved(e) => said(lang, "«»", "«»", [e.phrase(lang).into()]),
        }
    }
}

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
            ExerciseError::BadCount { part } => said(
                lang,
                "the count of ‹› is not a whole number (write TOPIC:N, as in coons:2)",
                "el número de problemas de ‹› no es un número entero (escriba TEMA:N, como en coons:2)",
                [(&format!("{part:?}")).into()],
            ),
            ExerciseError::RepeatedTopic { name } => said(
                lang,
                "the topic ‹› is named twice; give its count once (‹›:N)",
                "el tema ‹› aparece dos veces; indique su número de problemas una sola vez (‹›:N)",
                [(&format!("{name:?}")).into(), name.into()],
            ),
            ExerciseError::NoFriendlyProblem {
                topic,
                number,
                reason,
            } => said(
                lang,
                "could not draw problem ‹› of topic ‹› with friendly numbers in ‹› attempts (last: «»); try another seed",
                "no se pudo sortear el problema ‹› del tema ‹› con números sencillos en ‹› intentos (el último: «»); pruebe otra semilla",
                [
                    number.into(),
                    (&format!("{topic:?}")).into(),
                    (&crate::ATTEMPTS).into(),
                    reason.phrase(lang).into(),
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
        let unsolved = Refused::Unsolved(Box::new(ProblemError::at(
            "radius",
            cagd_problem::message::contract::Contract::Missing,
        )));
        for reason in Refused::iter().chain([unsolved]) {
            let m = ExerciseError::NoFriendlyProblem {
                topic: "bezier".into(),
                number: 1,
                reason,
            };
            assert_eq!(cagd_words::check_both(&m), Ok(()), "{m:?}");
        }
    }
}
