//! The answer keys: Spanish without English left (`spanish`), the notes' notation and
//! conventions (`notation`), LaTeX that typesets (`latex`).

mod latex;
mod notation;
mod spanish;
