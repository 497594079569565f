//! The words of the pages (buttons, headings, messages of the page itself), English and
//! Spanish by one exhaustive match; `/api/set` sends them all to the page as `words`.

use cagd_words::{said, Lang, Message, Phrase};
use serde_json::{Map, Value};
use strum::IntoEnumIterator;

/// A word of the pages, by the id the page's script knows it by (`PageWord::Check` is
/// `"check"`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, strum::EnumIter, strum::IntoStaticStr)]
#[strum(serialize_all = "snake_case")]
pub enum PageWord {
    /// The button that checks an answer.
    Check,
    /// Said while an answer is being checked.
    Checking,
    /// The button that empties a problem's cells (and what the browser kept of them).
    Clear,
    /// Where the student's answers are kept.
    KeptHere,
    /// A cell's preview when the server gives no reason why it could not read it.
    ReadError,
    /// The server's queue is full (503).
    Busy,
    /// A request answered with an error.
    Failed,
    /// A request that got no answer.
    Unreachable,
    /// Said while the page loads its problems.
    Loading,
    /// The verdict of an answer that is right.
    Correct,
    /// The verdict of an answer (or a cell) that is wrong.
    Wrong,
    /// The verdict of an answer that does not read.
    Unreadable,
    /// The heading of the score.
    Score,
    /// The heading of the diagnoses of an answer.
    Diagnosis,
    /// The heading of the checked answer's report.
    Report,
    /// The heading of the worked solution.
    Solution,
    /// The label of the language switch.
    Language,
    /// English, named in English (the switch's entry).
    English,
    /// Spanish, named in Spanish (the switch's entry).
    Spanish,
    /// The alternative text of a problem's figure (before its title).
    Figure,
    /// The heading of a problem's statement.
    Statement,
    /// The heading of the student's cells.
    YourAnswer,
    /// The word before a cell's entry in its label.
    Entry,
    /// The word before a cell's coordinate in its label.
    Coordinate,
    /// A yes/no cell's yes.
    Yes,
    /// A yes/no cell's no.
    No,
    /// A yes/no cell not chosen yet.
    Choose,
    /// The student's page's title.
    StudentTitle,
    /// The teacher's page's title.
    TeacherTitle,
    /// The label of the teacher's text box.
    ProblemJson,
    /// The teacher's text does not read as JSON.
    NotJson,
    /// The teacher's button that solves the problem.
    Solve,
    /// The heading of the problem's errors.
    Errors,
    /// The heading of the problem's answer key.
    Key,
    /// The button that downloads the answer key.
    DownloadKey,
    /// The button that downloads the statement sheet.
    DownloadSheet,
    /// The button that shows the problem as students see it.
    Preview,
    /// Said above the preview: its cells are not checked.
    PreviewNote,
    /// The heading of the teacher's interactive figure.
    InteractiveFigure,
    /// The field `bezier` of an answer form: the control points of a Bézier curve or mesh.
    FieldBezier,
    /// The field `bspline`: the control points of a B-spline.
    FieldBspline,
    /// The field `weights`.
    FieldWeights,
    /// The field `knots`.
    FieldKnots,
    /// The field `degree`.
    FieldDegree,
    /// The field `triangle`: the control net of a Bézier triangle.
    FieldTriangle,
}

impl Message for PageWord {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            PageWord::Check => said(lang, "Check", "Comprobar", []),
            PageWord::FieldBezier | PageWord::FieldBspline => {
                said(lang, "control points", "puntos de control", [])
            }
            PageWord::FieldWeights => said(lang, "weights", "pesos", []),
            PageWord::FieldKnots => said(lang, "knots", "nudos", []),
            PageWord::FieldDegree => said(lang, "degree", "grado", []),
            PageWord::FieldTriangle => said(lang, "control net", "red de control", []),
            PageWord::Checking => said(lang, "Checking…", "Comprobando…", []),
            PageWord::Clear => said(lang, "Clear", "Borrar", []),
            PageWord::KeptHere => said(
                lang,
                "Your answers are kept in this browser only.",
                "Tus respuestas se guardan solo en este navegador.",
                [],
            ),
            PageWord::ReadError => said(
                lang,
                "This cell cannot be read.",
                "No se puede leer esta casilla.",
                [],
            ),
            PageWord::Busy => said(
                lang,
                "The server is busy; try again in a moment.",
                "El servidor está ocupado; vuelve a intentarlo en un momento.",
                [],
            ),
            PageWord::Failed => said(lang, "The request failed:", "La petición ha fallado:", []),
            PageWord::Unreachable => said(
                lang,
                "The server cannot be reached.",
                "No se puede conectar con el servidor.",
                [],
            ),
            PageWord::Loading => said(lang, "Loading…", "Cargando…", []),
            PageWord::Correct => said(lang, "Correct", "Correcto", []),
            PageWord::Wrong => said(lang, "Wrong", "Incorrecto", []),
            PageWord::Unreadable => said(lang, "Unreadable", "Ilegible", []),
            PageWord::Score => said(lang, "Score", "Puntuación", []),
            PageWord::Diagnosis => said(lang, "Diagnosis", "Diagnóstico", []),
            PageWord::Report => said(lang, "Report", "Informe", []),
            PageWord::Solution => said(lang, "Solution", "Solución", []),
            PageWord::Language => said(lang, "Language", "Idioma", []),
            PageWord::English => said(lang, "English", "English", []),
            PageWord::Spanish => said(lang, "Español", "Español", []),
            PageWord::Figure => said(lang, "Figure:", "Figura:", []),
            PageWord::Statement => said(lang, "Statement", "Enunciado", []),
            PageWord::YourAnswer => said(lang, "Your answer", "Tu respuesta", []),
            PageWord::Entry => said(lang, "entry", "entrada", []),
            PageWord::Coordinate => said(lang, "coordinate", "coordenada", []),
            PageWord::Yes => said(lang, "yes", "sí", []),
            PageWord::No => said(lang, "no", "no", []),
            PageWord::Choose => said(lang, "(choose)", "(elige)", []),
            PageWord::StudentTitle => said(lang, "Problem set", "Hoja de problemas", []),
            PageWord::TeacherTitle => said(lang, "Teacher's page", "Página del profesor", []),
            PageWord::ProblemJson => said(lang, "Problem (JSON)", "Problema (JSON)", []),
            PageWord::NotJson => said(
                lang,
                "The text is not valid JSON:",
                "El texto no es un JSON válido:",
                [],
            ),
            PageWord::Solve => said(lang, "Solve", "Resolver", []),
            PageWord::Errors => said(lang, "Errors", "Errores", []),
            PageWord::Key => said(lang, "Answer key", "Solución", []),
            PageWord::DownloadKey => said(
                lang,
                "Download the answer key (.tex)",
                "Descargar la solución (.tex)",
                [],
            ),
            PageWord::DownloadSheet => said(
                lang,
                "Download the statement sheet (.tex)",
                "Descargar la hoja de enunciados (.tex)",
                [],
            ),
            PageWord::Preview => said(
                lang,
                "Preview as students see it",
                "Vista previa como la verán los alumnos",
                [],
            ),
            PageWord::PreviewNote => said(
                lang,
                "A preview: its cells are neither read nor checked here.",
                "Una vista previa: aquí sus casillas no se leen ni se comprueban.",
                [],
            ),
            PageWord::InteractiveFigure => {
                said(lang, "Interactive figure", "Figura interactiva", [])
            }
        }
    }
}

/// Every word of the pages in `lang`, by id.
pub fn all(lang: Lang) -> Value {
    let mut out = Map::new();
    for w in PageWord::iter() {
        let id: &'static str = w.into();
        out.insert(id.to_string(), Value::String(w.phrase(lang).text()));
    }
    Value::Object(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_page_word_in_both_languages() {
        for w in PageWord::iter() {
            assert_eq!(cagd_words::check_both(&w), Ok(()), "{w:?}");
        }
    }
}
