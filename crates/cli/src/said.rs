//! The command line's own sentences, typed: what it says when it cannot read or write a file,
//! when an input is not JSON or not UTF-8, when a flag's value is wrong... Each is worded in
//! English and in the notes' Spanish beside its definition; an error carries its sentence
//! ([`Said`]) and is worded in the language asked when it is printed.

use crate::cli::LimitArgs;
use cagd_keys::{Lang, Raise, Sentence};
use cagd_problem::{Limit, ProblemError};
use cagd_words::{said, Message, Phrase};

/// A sentence of the command line.
#[derive(Debug, Clone, PartialEq, Eq, Default, strum::EnumIter)]
pub enum CliMessage {
    /// A file that cannot be read.
    CannotRead {
        /// The path given.
        path: String,
        /// Why, as the system says.
        why: Io,
    },
    /// Standard input that cannot be read.
    CannotReadStdin {
        /// Why, as the system says.
        why: String,
    },
    /// A document that is not JSON.
    NotJson {
        /// The input.
        input: Input,
        /// Where, from 1.
        line: usize,
        /// Where, from 1.
        column: usize,
        /// What is wrong, in serde_json's words.
        error: String,
    },
    /// A batch that stops being JSON.
    NotJsonInBatch {
        /// The input.
        input: Input,
        /// Where, from 1.
        line: usize,
        /// Where, from 1.
        column: usize,
        /// The problem it is in, from 1.
        problem: usize,
        /// What is wrong, in serde_json's words.
        error: String,
    },
    /// Standard input that is not UTF-8.
    NotUtf8Stdin {
        /// The encoding it looks like.
        looks: String,
    },
    /// A file that is not UTF-8.
    NotUtf8File {
        /// The path given.
        path: String,
        /// The encoding it looks like.
        looks: String,
    },
    /// Standard input that stops being UTF-8 at a byte.
    NotUtf8StdinAt {
        /// The byte (`0xE9`).
        byte: String,
        /// Where, from 1.
        line: usize,
        /// Where, from 1.
        column: usize,
        /// The encoding it looks like.
        looks: String,
    },
    /// A file that stops being UTF-8 at a byte.
    NotUtf8FileAt {
        /// The path given.
        path: String,
        /// The byte (`0xE9`).
        byte: String,
        /// Where, from 1.
        line: usize,
        /// Where, from 1.
        column: usize,
        /// The encoding it looks like.
        looks: String,
    },
    /// No example has a name that starts with the names given.
    NoExample {
        /// The names given.
        names: String,
    },
    /// `cagd generate` without `--topic`.
    TopicRequired {
        /// The topics, one a line.
        topics: String,
    },
    /// An empty path given for a file.
    EmptyFile {
        /// The flag or argument (`FILE`, `--svg`).
        what: String,
    },
    /// An empty path given for a folder.
    EmptyFolder {
        /// The flag (`--out`).
        what: String,
    },
    /// The figures of a problem set cannot be written.
    SetNotWritten {
        /// Why.
        why: Box<CliMessage>,
    },
    /// Two outputs to one file.
    SameFile {
        /// The flag of the first.
        first_flag: String,
        /// The path of the first.
        first: String,
        /// The flag of the second.
        flag: String,
        /// The path of the second.
        path: String,
    },
    /// An output to the input file.
    IsInput {
        /// The flag of the output.
        flag: String,
        /// Its path.
        path: String,
    },
    /// A folder that cannot be created.
    CannotCreate {
        /// The path.
        path: String,
        /// Why, as the system says.
        why: String,
    },
    /// A file that cannot be written.
    CannotWrite {
        /// The path.
        path: String,
        /// Why, as the system says.
        why: String,
    },
    /// A flag whose value is not a positive integer.
    Positive {
        /// The flag.
        flag: String,
        /// The value given.
        found: String,
    },
    /// `--max-seconds` with a value that is not a number of seconds.
    Seconds {
        /// The value given.
        found: String,
    },
    /// A flag above its ceiling.
    AtMost {
        /// The flag.
        flag: String,
        /// The ceiling.
        max: String,
    },
    /// A flag whose value is not a whole number.
    Whole {
        /// The flag.
        flag: String,
        /// The value given.
        found: String,
    },
    /// A flag whose value is not a number of degrees.
    Degrees {
        /// The flag.
        flag: String,
        /// The value given.
        found: String,
    },
    /// `--density` out of its range.
    Density {
        /// The value given.
        found: String,
    },
    /// A layer of `--layers` that does not exist.
    UnknownLayer {
        /// The name given.
        layer: String,
    },
    /// `cagd render` without an output.
    #[default]
    NoOutput,
    /// `--plot` of a scene without a surface.
    NoSurface,
    /// A figure not drawn within `--max-seconds`.
    NotDrawn {
        /// The output's path.
        path: String,
        /// The limit, in seconds.
        seconds: String,
    },
    /// A tessellated figure (OBJ, STL) not drawn within `--max-seconds`.
    NotDrawnDense {
        /// The output's path.
        path: String,
        /// The limit, in seconds.
        seconds: String,
    },
    /// A parameter of `--parameters` that is not one letter, or is a variable.
    NotParameter {
        /// The value given, quoted.
        given: String,
    },
    /// An unknown letter in `cagd expand`: how to declare it.
    DeclareParameters {
        /// The parser's message.
        error: String,
    },
    /// Standard output that cannot be written (a full disk; a closed pipe is not said).
    CannotWriteOutput {
        /// Why, as the system says.
        why: String,
    },
    /// A file a command wrote (`cagd generate`, `cagd render`), one a line of its report.
    Wrote {
        /// The path written.
        path: String,
    },
    /// A LaTeX document pdflatex could not compile, with its log.
    PdflatexFailed {
        /// The document (`key.tex`).
        document: String,
        /// The path of pdflatex's log.
        log: String,
    },
    /// A fixture of the examples that is not JSON.
    FixtureNotJson {
        /// Its path.
        path: String,
        /// What is wrong, in serde_json's words.
        error: String,
    },
    /// `--bind` that is not an IP address.
    NotAnAddress {
        /// What was given.
        found: String,
    },
}

/// The input of a command: a file, or standard input.
#[derive(Debug, Clone, PartialEq, Eq, Default, strum::EnumIter)]
pub enum Input {
    /// Standard input (`-`).
    #[default]
    Stdin,
    /// A file, by the path given.
    File(String),
}

impl Input {
    /// The input of a path (`-` is standard input).
    pub fn of(path: &str) -> Input {
        if path == "-" {
            Input::Stdin
        } else {
            Input::File(path.to_string())
        }
    }
}

impl Message for Input {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            Input::Stdin => said(lang, "standard input", "entrada estándar", []),
            Input::File(path) => said(lang, "‹›", "‹›", [path.into()]),
        }
    }
}

/// Why a file cannot be read, as the system says: a file that does not exist is said in the
/// language asked, any other reason as the system words it.
#[derive(Debug, Clone, PartialEq, Eq, strum::EnumIter)]
pub enum Io {
    /// No such file.
    NotFound {
        /// The system's words.
        system: String,
    },
    /// Another reason, in the system's words.
    Other {
        /// The system's words.
        system: String,
    },
}

impl Default for Io {
    fn default() -> Self {
        Io::Other {
            system: "Permission denied (os error 13)".into(),
        }
    }
}

impl Io {
    /// Why an input cannot be read.
    pub fn of(e: &std::io::Error) -> Io {
        let system = e.to_string();
        match e.kind() {
            std::io::ErrorKind::NotFound => Io::NotFound { system },
            _ => Io::Other { system },
        }
    }
}

impl Message for Io {
    fn phrase(&self, lang: Lang) -> Phrase {
        match (self, lang) {
            // the system's words are English: a missing file is said in Spanish
            (Io::NotFound { .. }, Lang::Es) => Phrase::fill("el archivo no existe", []),
            (Io::NotFound { system } | Io::Other { system }, _) => Phrase::data(system),
        }
    }
}

impl Message for CliMessage {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            CliMessage::CannotRead { path, why } => said(
                lang,
                "cannot read ‹›: «»",
                "no se puede leer ‹›: «»",
                [path.into(), why.phrase(lang).into()],
            ),
            CliMessage::CannotReadStdin { why } => said(
                lang,
                "cannot read standard input: ‹›",
                "no se puede leer la entrada estándar: ‹›",
                [why.into()],
            ),
            CliMessage::NotJson {
                input,
                line,
                column,
                error,
            } => said(
                lang,
                "«»: not valid JSON at line ‹›, column ‹›: ‹›",
                "«»: JSON no válido en la línea ‹›, columna ‹›: ‹›",
                [
                    input.phrase(lang).into(),
                    line.into(),
                    column.into(),
                    error.into(),
                ],
            ),
            CliMessage::NotJsonInBatch {
                input,
                line,
                column,
                problem,
                error,
            } => said(
                lang,
                "«»: not valid JSON at line ‹›, column ‹›, in problem ‹› of the batch (the \
                 problems before it are answered): ‹›",
                "«»: JSON no válido en la línea ‹›, columna ‹›, en el problema ‹› del lote (los \
                 problemas anteriores están respondidos): ‹›",
                [
                    input.phrase(lang).into(),
                    line.into(),
                    column.into(),
                    problem.into(),
                    error.into(),
                ],
            ),
            CliMessage::NotUtf8Stdin { looks } => said(
                lang,
                "standard input is not UTF-8 (it looks like ‹›): save it as UTF-8",
                "la entrada estándar no está en UTF-8 (parece ‹›): guárdela en UTF-8",
                [looks.into()],
            ),
            CliMessage::NotUtf8File { path, looks } => said(
                lang,
                "‹› is not UTF-8 (it looks like ‹›): save it as UTF-8",
                "‹› no está en UTF-8 (parece ‹›): guárdelo en UTF-8",
                [path.into(), looks.into()],
            ),
            CliMessage::NotUtf8StdinAt {
                byte,
                line,
                column,
                looks,
            } => said(
                lang,
                "standard input is not UTF-8: byte ‹› at line ‹›, column ‹› (it looks like ‹›): \
                 save it as UTF-8",
                "la entrada estándar no está en UTF-8: byte ‹› en la línea ‹›, columna ‹› \
                 (parece ‹›): guárdela en UTF-8",
                [byte.into(), line.into(), column.into(), looks.into()],
            ),
            CliMessage::NotUtf8FileAt {
                path,
                byte,
                line,
                column,
                looks,
            } => said(
                lang,
                "‹› is not UTF-8: byte ‹› at line ‹›, column ‹› (it looks like ‹›): save it as \
                 UTF-8",
                "‹› no está en UTF-8: byte ‹› en la línea ‹›, columna ‹› (parece ‹›): guárdelo \
                 en UTF-8",
                [
                    path.into(),
                    byte.into(),
                    line.into(),
                    column.into(),
                    looks.into(),
                ],
            ),
            CliMessage::NoExample { names } => said(
                lang,
                "no example is called ‹› (see ‹›)",
                "ningún ejemplo se llama ‹› (vea ‹›)",
                [names.into(), (&"cagd examples --list").into()],
            ),
            CliMessage::TopicRequired { topics } => said(
                lang,
                "--topic is required; the topics are:\n‹›",
                "falta --topic; los temas son:\n‹›",
                [topics.into()],
            ),
            CliMessage::EmptyFile { what } => said(
                lang,
                "‹› takes the path of a file, found an empty one",
                "‹› lleva la ruta de un archivo, y se encontró una vacía",
                [what.into()],
            ),
            CliMessage::EmptyFolder { what } => said(
                lang,
                "‹› takes the path of a folder, found an empty one",
                "‹› lleva la ruta de una carpeta, y se encontró una vacía",
                [what.into()],
            ),
            CliMessage::SetNotWritten { why } => said(
                lang,
                "the problem set is not written, as its figures cannot be: «»",
                "la colección no se escribe, porque sus figuras no se pueden escribir: «»",
                [why.phrase(lang).into()],
            ),
            CliMessage::SameFile {
                first_flag,
                first,
                flag,
                path,
            } => said(
                lang,
                "‹› ‹› and ‹› ‹› are the same file: give each output a file of its own",
                "‹› ‹› y ‹› ‹› son el mismo archivo: dé a cada salida un archivo propio",
                [first_flag.into(), first.into(), flag.into(), path.into()],
            ),
            CliMessage::IsInput { flag, path } => said(
                lang,
                "‹› ‹› is the input file: give the output another name",
                "‹› ‹› es el archivo de entrada: dé otro nombre a la salida",
                [flag.into(), path.into()],
            ),
            CliMessage::CannotCreate { path, why } => said(
                lang,
                "cannot create ‹›: ‹›",
                "no se puede crear ‹›: ‹›",
                [path.into(), why.into()],
            ),
            CliMessage::CannotWrite { path, why } => said(
                lang,
                "cannot write ‹›: ‹›",
                "no se puede escribir ‹›: ‹›",
                [path.into(), why.into()],
            ),
            CliMessage::Positive { flag, found } => said(
                lang,
                "‹› takes a positive integer, found '‹›'",
                "‹› lleva un entero positivo, y se encontró '‹›'",
                [flag.into(), found.into()],
            ),
            CliMessage::Seconds { found } => said(
                lang,
                "--max-seconds takes a number of seconds (0 for no deadline), found '‹›'",
                "--max-seconds lleva un número de segundos (0: sin plazo), y se encontró '‹›'",
                [found.into()],
            ),
            CliMessage::AtMost { flag, max } => said(
                lang,
                "‹› is at most ‹›",
                "‹› vale como mucho ‹›",
                [flag.into(), max.into()],
            ),
            CliMessage::Whole { flag, found } => said(
                lang,
                "‹› takes a whole number, found '‹›'",
                "‹› lleva un número entero, y se encontró '‹›'",
                [flag.into(), found.into()],
            ),
            CliMessage::Degrees { flag, found } => said(
                lang,
                "‹› takes a number of degrees, found '‹›'",
                "‹› lleva un número de grados, y se encontró '‹›'",
                [flag.into(), found.into()],
            ),
            CliMessage::Density { found } => said(
                lang,
                "--density takes 1 to 256, found '‹›'",
                "--density lleva de 1 a 256, y se encontró '‹›'",
                [found.into()],
            ),
            CliMessage::UnknownLayer { layer } => said(
                lang,
                "unknown layer '‹›' (surface, mesh, boundary, normals, curves, axes)",
                "capa desconocida '‹›' (`surface`, `mesh`, `boundary`, `normals`, `curves`, \
                 `axes`)",
                [layer.into()],
            ),
            CliMessage::NoOutput => said(
                lang,
                "render needs at least one output: --svg, --html, --obj, --stl, --iges or --plot",
                "render necesita al menos una salida: --svg, --html, --obj, --stl, --iges o --plot",
                [],
            ),
            CliMessage::NoSurface => said(
                lang,
                "there is no surface to plot",
                "no hay superficie que dibujar",
                [],
            ),
            CliMessage::NotDrawn { path, seconds } => said(
                lang,
                "‹›: not drawn within the limit of ‹› s: the work was stopped (raise it with \
                 --max-seconds)",
                "‹›: sin dibujar dentro del límite de ‹› s: se detuvo el cálculo (súbalo con \
                 --max-seconds)",
                [path.into(), seconds.into()],
            ),
            CliMessage::NotDrawnDense { path, seconds } => said(
                lang,
                "‹›: not drawn within the limit of ‹› s: the work was stopped (raise it with \
                 --max-seconds, or lower --density)",
                "‹›: sin dibujar dentro del límite de ‹› s: se detuvo el cálculo (súbalo con \
                 --max-seconds, o baje --density)",
                [path.into(), seconds.into()],
            ),
            CliMessage::NotParameter { given } => said(
                lang,
                "‹›: ‹› is not a parameter: each is one letter, and not one of the variables u, \
                 v, w, t, s, x, y, z",
                "‹›: ‹› no es un parámetro: cada uno es una letra, y ninguna de las variables u, \
                 v, w, t, s, x, y, z",
                [(&"--parameters").into(), given.into()],
            ),
            CliMessage::DeclareParameters { error } => said(
                lang,
                "‹›; a letter that stands for a number is declared with ‹›",
                "‹›; una letra que representa un número se declara con ‹›",
                [error.into(), (&"--parameters").into()],
            ),
            CliMessage::CannotWriteOutput { why } => said(
                lang,
                "cannot write the output: ‹›",
                "no se puede escribir la salida: ‹›",
                [why.into()],
            ),
            CliMessage::Wrote { path } => said(lang, "wrote ‹›", "se ha escrito ‹›", [path.into()]),
            CliMessage::PdflatexFailed { document, log } => said(
                lang,
                "pdflatex failed on ‹› (see ‹›)",
                "pdflatex no pudo compilar ‹› (vea ‹›)",
                [document.into(), log.into()],
            ),
            CliMessage::FixtureNotJson { path, error } => said(
                lang,
                "fixture ‹› is not valid JSON: ‹›",
                "el ejemplo ‹› no es JSON válido: ‹›",
                [path.into(), error.into()],
            ),
            CliMessage::NotAnAddress { found } => said(
                lang,
                "'‹›' is not an IP address (127.0.0.1, 0.0.0.0, ::1)",
                "'‹›' no es una dirección IP (127.0.0.1, 0.0.0.0, ::1)",
                [found.into()],
            ),
        }
    }
}

cagd_words::display_english!(CliMessage);

/// A value parser's error is a sentence of the command line (clap keeps it as the error's
/// source, and the command line words it in the language asked).
impl std::error::Error for CliMessage {}

/// What an error of the command line says, typed until it is printed in a language.
#[derive(Debug)]
pub enum Said {
    /// A sentence of the command line.
    Cli(Box<CliMessage>),
    /// A problem that cannot be answered, its limit's flag named.
    Problem(Box<ProblemError>),
    /// A message of the engine.
    Engine(Box<cagd_problem::Message>),
    /// Why a figure is not drawn (cagd-render).
    Render(Box<cagd_render::RenderError>),
    /// Why a problem set is not generated (cagd-exercises).
    Exercise(Box<cagd_exercises::ExerciseError>),
    /// Why the server does not serve (cagd-serve).
    Serve(Box<cagd_serve::ServeError>),
}

/// The command line's sentence after an error past a limit: the flag that raises it.
pub fn raise(limit: Limit) -> Option<Raise> {
    let flag = LimitArgs::flag(limit);
    (!flag.is_empty()).then_some(Raise::Flag { flag })
}

impl Said {
    /// The words in `lang`, as text.
    pub fn text(&self, lang: Lang) -> String {
        self.sentence(lang).text
    }

    /// The words in `lang`, as text and LaTeX.
    pub fn sentence(&self, lang: Lang) -> Sentence {
        match self {
            Said::Cli(m) => cagd_keys::said::said(m, lang),
            Said::Problem(e) => cagd_keys::error_sentence_with(e, lang, raise),
            Said::Engine(m) => cagd_keys::said::message(m, lang),
            Said::Render(e) => cagd_keys::said::said(e.as_ref(), lang),
            Said::Exercise(e) => cagd_keys::said::said(e.as_ref(), lang),
            Said::Serve(e) => cagd_keys::said::said(e.as_ref(), lang),
        }
    }
}

impl From<CliMessage> for Said {
    fn from(m: CliMessage) -> Said {
        Said::Cli(Box::new(m))
    }
}

impl From<cagd_render::RenderError> for Said {
    fn from(e: cagd_render::RenderError) -> Said {
        Said::Render(Box::new(e))
    }
}

impl From<cagd_serve::ServeError> for Said {
    fn from(e: cagd_serve::ServeError) -> Said {
        Said::Serve(Box::new(e))
    }
}

impl From<cagd_exercises::ExerciseError> for Said {
    fn from(e: cagd_exercises::ExerciseError) -> Said {
        Said::Exercise(Box::new(e))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use strum::IntoEnumIterator;

    #[test]
    fn every_variant_in_both_languages() {
        for m in CliMessage::iter() {
            assert_eq!(cagd_words::check_both(&m), Ok(()), "{m:?}");
        }
        // a file is its path, the system's words are data: each with its data
        for m in Input::iter() {
            let m = match m {
                Input::File(_) => Input::File("p.json".into()),
                other => other,
            };
            assert_eq!(cagd_words::check_both(&m), Ok(()));
        }
        for m in Io::iter() {
            let system = "Permission denied (os error 13)".to_string();
            let m = match m {
                Io::NotFound { .. } => Io::NotFound { system },
                Io::Other { .. } => Io::Other { system },
            };
            assert_eq!(cagd_words::check_both(&m), Ok(()));
        }
    }

    /// What `cagd generate` and `cagd render` report they wrote, in each language.
    #[test]
    fn a_file_written_is_said_in_the_language_asked() {
        let m = CliMessage::Wrote {
            path: "examen/enunciados.pdf".into(),
        };
        assert_eq!(m.phrase(Lang::En).text(), "wrote examen/enunciados.pdf");
        assert_eq!(
            m.phrase(Lang::Es).text(),
            "se ha escrito examen/enunciados.pdf"
        );
        let m = CliMessage::PdflatexFailed {
            document: "key.tex".into(),
            log: "set/key.log".into(),
        };
        assert_eq!(
            m.phrase(Lang::Es).text(),
            "pdflatex no pudo compilar key.tex (vea set/key.log)"
        );
    }

    #[test]
    fn a_file_that_does_not_exist() {
        let e = std::io::Error::from(std::io::ErrorKind::NotFound);
        let m = CliMessage::CannotRead {
            path: "p.json".into(),
            why: Io::of(&e),
        };
        assert_eq!(m.to_string(), format!("cannot read p.json: {e}"));
        assert_eq!(
            m.phrase(Lang::Es).text(),
            "no se puede leer p.json: el archivo no existe"
        );
    }
}
