//! The answer keys: Spanish without English left (`spanish`), the notes' notation and
//! conventions (`notation`), LaTeX that typesets (`latex`), the problem's keywords as words
//! (`keywords`).

mod keywords;
mod latex;
mod notation;
mod spanish;
