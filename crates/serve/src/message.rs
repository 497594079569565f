//! Every sentence the server writes itself (an HTTP error, a summary of a check, the startup
//! report), English and Spanish by one exhaustive match ([`ServeMessage`]). The engine's own
//! messages (a grammar's error, a problem's) are the engine's, worded by their own types.

use cagd_words::{said, Lang, Message, Phrase};

/// A sentence of the server.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum ServeMessage {
    /// More work waiting than the queue holds, or a wait past its time.
    Busy,
    /// A request's body past the limit.
    BodyTooLarge {
        /// The limit, in KiB.
        kib: usize,
    },
    /// A request's body that is not the JSON (or form) expected.
    BadRequest {
        /// What the reader said (serde's words, data).
        error: String,
    },
    /// A problem index the server does not serve.
    NoSuchProblem {
        /// The index asked.
        index: usize,
        /// How many problems are served.
        count: usize,
    },
    /// Nothing at this address.
    NotFound,
    /// The teacher's pages without the right token.
    NeedsToken,
    /// A cell kind the server does not read.
    UnknownKind {
        /// The kind asked.
        kind: String,
    },
    /// An answer that is not an object of results by name.
    AnswerNotAnObject,
    /// A key of an answer that is not a result of the problem.
    NotAResult {
        /// The key.
        key: String,
    },
    /// An answer with every result left empty.
    NothingWritten,
    /// A cell that does not read: its result, its entry, and the grammar's message.
    CellUnread {
        /// The result's key.
        result: String,
        /// The cell's entry (`c_1,2`).
        cell: String,
        /// The grammar's message.
        inner: Phrase,
    },
    /// A cell left empty (or of another kind than its form's) beside written ones.
    CellEmpty,
    /// Every entry right.
    Correct {
        /// Entries right.
        right: usize,
        /// Entries in all.
        total: usize,
    },
    /// Some entry wrong.
    Wrong {
        /// Entries right.
        right: usize,
        /// Entries in all.
        total: usize,
    },
    /// The results the student left empty, not checked.
    LeftOut {
        /// Their keys, comma separated.
        results: String,
    },
    /// A result the engine could not read: its key and why.
    ResultUnread {
        /// The result's key.
        result: String,
        /// The reader's message.
        inner: Phrase,
    },
    /// The work stopped at its deadline.
    Deadline,
    /// The work ran past its memory budget.
    OverMemory,
    /// A bug of the engine, caught.
    Internal,
    /// The problem of this index has no answer (its key failed).
    NoKey,
    /// Nothing to draw for a problem.
    NoFigure {
        /// Why (the figure's message).
        inner: Phrase,
    },
    /// `what` of a download that is neither `key` nor `sheet`.
    UnknownDownload {
        /// What was asked.
        what: String,
    },
    /// Startup: a problem left out of the set, with its error.
    LeftOutAtStart {
        /// The problem's name.
        name: String,
        /// Its error.
        inner: Phrase,
    },
    /// Startup: how many problems are served.
    Serving {
        /// How many.
        count: usize,
    },
    /// Startup: the students' address.
    StudentsAt {
        /// The URL.
        url: String,
    },
    /// Startup: the teacher's address.
    TeacherAt {
        /// The URL.
        url: String,
    },
    /// Startup: the teacher's pages are off (bound beyond the loopback without a token).
    TeacherOff,
    /// Startup: no problem to serve.
    NoProblems,
    /// The server could not listen on the address.
    CannotBind {
        /// The address.
        addr: String,
        /// The system's words.
        error: String,
    },
    /// The server failed while serving (the system's words).
    Failed {
        /// The system's words.
        error: String,
    },
}

impl Message for ServeMessage {
    fn phrase(&self, lang: Lang) -> Phrase {
        use ServeMessage as M;
        match self {
            M::Busy => said(
                lang,
                "The server is busy: try again in a moment.",
                "El servidor está ocupado: inténtalo de nuevo en un momento.",
                [],
            ),
            M::BodyTooLarge { kib } => said(
                lang,
                "The request is too large (at most ‹› KiB).",
                "La petición es demasiado grande (como mucho ‹› KiB).",
                [kib.into()],
            ),
            M::BadRequest { error } => said(
                lang,
                "The request could not be read: ‹›",
                "No se pudo leer la petición: ‹›",
                [error.into()],
            ),
            M::NoSuchProblem { index, count } => said(
                lang,
                "There is no problem ‹› (the set has ‹›, counted from 0).",
                "No hay problema ‹› (la hoja tiene ‹›, contados desde 0).",
                [index.into(), count.into()],
            ),
            M::NotFound => said(lang, "Not found.", "No encontrado.", []),
            M::NeedsToken => said(
                lang,
                "The teacher's pages need the teacher's token.",
                "Las páginas del profesor necesitan la clave del profesor.",
                [],
            ),
            M::UnknownKind { kind } => said(
                lang,
                "Unknown kind of cell ‹› (one of ‹›).",
                "Tipo de casilla desconocido ‹› (uno de ‹›).",
                [kind.into(), "number, expression, bool, text".into()],
            ),
            M::AnswerNotAnObject => said(
                lang,
                "The answer must be an object of results by name.",
                "La respuesta debe ser un objeto de resultados por nombre.",
                [],
            ),
            M::NotAResult { key } => said(
                lang,
                "‹› is not a result of this problem.",
                "‹› no es un resultado de este problema.",
                [key.into()],
            ),
            M::NothingWritten => said(
                lang,
                "Nothing to check: every result is empty.",
                "Nada que comprobar: todos los resultados están vacíos.",
                [],
            ),
            M::CellUnread {
                result,
                cell,
                inner,
            } => said(
                lang,
                "‹›, ‹›: «»",
                "‹›, ‹›: «»",
                [result.into(), cell.into(), inner.clone().into()],
            ),
            M::CellEmpty => said(
                lang,
                "left empty (write every entry of a result, or none)",
                "sin escribir (escribe todos los elementos de un resultado, o ninguno)",
                [],
            ),
            M::Correct { right, total } => said(
                lang,
                "Correct: ‹›/‹› entries right.",
                "Correcto: ‹›/‹› elementos bien.",
                [right.into(), total.into()],
            ),
            M::Wrong { right, total } => said(
                lang,
                "Not correct: ‹›/‹› entries right.",
                "No es correcto: ‹›/‹› elementos bien.",
                [right.into(), total.into()],
            ),
            M::LeftOut { results } => said(
                lang,
                "Left empty, not checked: ‹›.",
                "Sin escribir, no comprobado: ‹›.",
                [results.into()],
            ),
            M::ResultUnread { result, inner } => said(
                lang,
                "‹› could not be read: «»",
                "‹› no se pudo leer: «»",
                [result.into(), inner.clone().into()],
            ),
            M::Deadline => said(
                lang,
                "The work stopped at its time limit.",
                "El cálculo se detuvo en su límite de tiempo.",
                [],
            ),
            M::OverMemory => said(
                lang,
                "The work ran past its memory limit.",
                "El cálculo superó su límite de memoria.",
                [],
            ),
            M::Internal => said(
                lang,
                "An internal error of the engine: please tell the teacher.",
                "Un error interno del programa: avisa al profesor.",
                [],
            ),
            M::NoKey => said(
                lang,
                "This problem has no answer key.",
                "Este problema no tiene solución.",
                [],
            ),
            M::NoFigure { inner } => said(
                lang,
                "No figure: «»",
                "Sin figura: «»",
                [inner.clone().into()],
            ),
            M::UnknownDownload { what } => said(
                lang,
                "Unknown download ‹› (one of ‹›).",
                "Descarga desconocida ‹› (una de ‹›).",
                [what.into(), "key, sheet".into()],
            ),
            M::LeftOutAtStart { name, inner } => said(
                lang,
                "Left out: ‹›: «»",
                "Se deja fuera: ‹›: «»",
                [name.into(), inner.clone().into()],
            ),
            M::Serving { count } => said(
                lang,
                "Serving ‹› problems.",
                "Se sirven ‹› problemas.",
                [count.into()],
            ),
            M::StudentsAt { url } => said(
                lang,
                "Students: ‹›",
                "Estudiantes: ‹›",
                [url.into()],
            ),
            M::TeacherAt { url } => said(
                lang,
                "Teacher: ‹›",
                "Profesor: ‹›",
                [url.into()],
            ),
            M::TeacherOff => said(
                lang,
                "The teacher's pages are off: the server listens beyond this computer and no ‹› was given.",
                "Las páginas del profesor están desactivadas: el servidor escucha fuera de este ordenador y no se dio ‹›.",
                ["--token".into()],
            ),
            M::NoProblems => said(
                lang,
                "No problem to serve.",
                "Ningún problema que servir.",
                [],
            ),
            M::CannotBind { addr, error } => said(
                lang,
                "Cannot listen on ‹›: ‹›",
                "No se puede escuchar en ‹›: ‹›",
                [addr.into(), error.into()],
            ),
            M::Failed { error } => said(
                lang,
                "The server stopped: ‹›",
                "El servidor se detuvo: ‹›",
                [error.into()],
            ),
        }
    }
}

cagd_words::display_english!(ServeMessage);

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_variant_in_both_languages() {
        let inner = || Phrase::data("x");
        let all = [
            ServeMessage::Busy,
            ServeMessage::BodyTooLarge { kib: 256 },
            ServeMessage::BadRequest { error: "e".into() },
            ServeMessage::NoSuchProblem { index: 3, count: 2 },
            ServeMessage::NotFound,
            ServeMessage::NeedsToken,
            ServeMessage::UnknownKind { kind: "k".into() },
            ServeMessage::AnswerNotAnObject,
            ServeMessage::NotAResult { key: "k".into() },
            ServeMessage::NothingWritten,
            ServeMessage::CellUnread {
                result: "surface".into(),
                cell: "c_1,2".into(),
                inner: inner(),
            },
            ServeMessage::CellEmpty,
            ServeMessage::Correct { right: 1, total: 1 },
            ServeMessage::Wrong { right: 0, total: 1 },
            ServeMessage::LeftOut {
                results: "surface".into(),
            },
            ServeMessage::ResultUnread {
                result: "surface".into(),
                inner: inner(),
            },
            ServeMessage::Deadline,
            ServeMessage::OverMemory,
            ServeMessage::Internal,
            ServeMessage::NoKey,
            ServeMessage::NoFigure { inner: inner() },
            ServeMessage::UnknownDownload { what: "w".into() },
            ServeMessage::LeftOutAtStart {
                name: "n".into(),
                inner: inner(),
            },
            ServeMessage::Serving { count: 2 },
            ServeMessage::StudentsAt { url: "u".into() },
            ServeMessage::TeacherAt { url: "u".into() },
            ServeMessage::TeacherOff,
            ServeMessage::NoProblems,
            ServeMessage::CannotBind {
                addr: "a".into(),
                error: "e".into(),
            },
            ServeMessage::Failed { error: "e".into() },
        ];
        for m in &all {
            assert_eq!(cagd_words::check_both(m), Ok(()), "{m:?}");
        }
    }
}
