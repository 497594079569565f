//! The answer keys: Spanish without English left (`spanish`), the notes' notation and
//! conventions (`notation`), LaTeX that typesets (`latex`), the problem's keywords as words
//! (`keywords`), the text of a problem shown as data in Markdown and plain text
//! (`text_is_data`), no machinery (ids, file names, the legend in every example) in the keys
//! handed to students (`machinery`).

mod keywords;
mod latex;
mod machinery;
mod notation;
mod questions;
mod spanish;
mod text_is_data;
