//! Answer keys of cagd-exact: text, LaTeX and Markdown, in English or in the notes' Spanish.
//!
//! A key is written from a [`Verdict`]: the typed problem (its fixture fields, its arguments in
//! the order written) and its answer (results, steps, remarks), and the comparison with
//! `expected` when the problem says what to expect. Nothing here reads JSON or solves.
//!
//! [`Verdict`]: cagd_contract::Verdict

pub mod names;

pub use assessment::{mathematics_in_words, AssessmentWords};
pub use names::Label;
pub use said::Sentence;
pub use sentences::{CurvatureSign, KeyRemark, Keyword, Raise};

pub mod said;
pub mod sentences;
pub mod steps;
pub mod tex;

mod assessment;
mod escape;
mod knot_convention;
mod latex_key;
mod latex_math;
mod markdown_key;
mod parts;
mod question;
mod source;
mod statements;
mod text_key;
mod values;
mod verdict;
mod vocabulary;

pub use cagd_words::Lang;
pub use escape::{escape_html, escape_latex, escape_markdown, escape_text};
pub use latex_key::{
    example_latex, example_latex_beside, example_latex_with, latex_document, latex_key_document,
    latex_preamble,
};
pub use markdown_key::{
    assessment_markdown, example_markdown, example_markdown_with, markdown_document,
    markdown_image, markdown_key_document,
};
pub use names::latex_name;
pub use question::{Fit, Question, Shape, Turn};
pub use source::{Document, Place, Source};
pub use statements::{
    statement_document, statement_heading, statement_latex, statement_markdown, Described,
    SheetHeader, SheetWord,
};
pub use steps::{legend_latex, legend_markdown, legend_text};
pub use text_key::{example_text, example_text_with};
pub use values::{latex, text};
pub use verdict::{error_sentence, error_sentence_with, no_raise, verdict_text, RaiseWith};
pub use vocabulary::{op_words, Word};
