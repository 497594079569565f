//! `cagd serve`: a problem set served to students, who check their answers on a page, and
//! the teacher's page (a problem's key and figure). The HTTP contract is `API.md` beside this
//! crate's `Cargo.toml`.

pub mod words;
