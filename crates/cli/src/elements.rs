//! A batch (a JSON array of problems) read element by element from a file or standard input,
//! so that `cagd solve` holds a few problems at a time, not the whole batch.
//!
//! The reader finds where each element of the top-level array ends (brackets and braces
//! outside strings), checks that its text is JSON, and hands it over; what follows it must be
//! `,` or the closing `]`, and after the array only white space. A syntax error stops the
//! batch there: the problems before it have been handed over (and are answered), and the
//! error says where it is, by line and column of the whole input, and in which element.

use cagd_problem::message::contract::Contract;
use cagd_problem::problem::serde_error;
use cagd_problem::{Limits, Problem, ProblemError, ProblemSource};
use std::io::BufRead;

/// Where a syntax error of the batch is, and what it is.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SyntaxError {
    /// The element it is in (or after), counted from 0.
    pub element: usize,
    /// Its line in the whole input, from 1.
    pub line: usize,
    /// Its column in that line, from 1.
    pub column: usize,
    /// What is wrong, in serde_json's words (without a position).
    pub message: String,
}

/// The elements of a top-level JSON array, as texts, read from `input`.
pub struct Elements<R> {
    input: R,
    /// Line and column (from 1) of the next byte.
    line: usize,
    column: usize,
    /// The elements handed over so far.
    count: usize,
    /// Where the reading stands.
    state: State,
    /// The first syntax error, once met (the reading then ends).
    pub error: Option<SyntaxError>,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum State {
    /// Before the first element (just after `[`).
    First,
    /// After a `,`: an element must follow.
    AfterComma,
    /// Done (the closing `]` read, or an error).
    Done,
}

impl<R: BufRead> Elements<R> {
    /// The elements of the array that `input` starts with (after white space and `[`, which
    /// the caller has seen: `line` and `column` are where the reading starts).
    pub fn new(input: R, line: usize, column: usize) -> Self {
        Elements {
            input,
            line,
            column,
            count: 0,
            state: State::First,
            error: None,
        }
    }

    /// The next byte, without taking it.
    fn peek(&mut self) -> std::io::Result<Option<u8>> {
        Ok(self.input.fill_buf()?.first().copied())
    }

    /// Takes one byte, keeping the line and column.
    fn bump(&mut self, b: u8) {
        self.input.consume(1);
        if b == b'\n' {
            self.line += 1;
            self.column = 1;
        } else {
            // columns count bytes, as serde_json's do
            self.column += 1;
        }
    }

    /// Skips white space; the next byte after it.
    fn skip_space(&mut self) -> std::io::Result<Option<u8>> {
        while let Some(b) = self.peek()? {
            if !matches!(b, b' ' | b'\t' | b'\n' | b'\r') {
                return Ok(Some(b));
            }
            self.bump(b);
        }
        Ok(None)
    }

    /// Ends the reading with a syntax error at the current place.
    fn fail<T>(&mut self, message: impl Into<String>) -> Option<T> {
        self.fail_at(self.line, self.column, message.into())
    }

    fn fail_at<T>(&mut self, line: usize, column: usize, message: String) -> Option<T> {
        self.state = State::Done;
        self.error = Some(SyntaxError {
            element: self.count,
            line,
            column,
            message,
        });
        None
    }

    /// Takes the first `n` bytes of the buffer, keeping the line and column.
    fn advance(&mut self, n: usize, newlines: usize, after_last_newline: Option<usize>) {
        self.input.consume(n);
        self.line += newlines;
        self.column = match after_last_newline {
            Some(k) => n - k + 1,
            None => self.column + n,
        };
    }

    /// The text of the element that starts here: up to its closing bracket or brace (outside
    /// strings), or to the end of a string or of a number or word. The buffer is scanned a
    /// slice at a time.
    fn element_bytes(&mut self) -> std::io::Result<Result<Vec<u8>, String>> {
        let mut out = Vec::new();
        let mut scan = Scan::default();
        loop {
            let buf = self.input.fill_buf()?;
            if buf.is_empty() {
                if scan.depth == 0 && !scan.in_string && !out.is_empty() {
                    // a number or word at the end of the input
                    return Ok(Ok(out));
                }
                return Ok(Err("EOF while parsing a list".into()));
            }
            let end = scan.end(buf);
            let n = end.unwrap_or(buf.len());
            let chunk = buf.get(..n).unwrap_or_default();
            out.extend_from_slice(chunk);
            // most batches hold a problem on one line: `contains` is a fast search
            let (newlines, after) = if chunk.contains(&b'\n') {
                (
                    chunk.iter().filter(|&&b| b == b'\n').count(),
                    chunk.iter().rposition(|&b| b == b'\n').map(|k| k + 1),
                )
            } else {
                (0, None)
            };
            self.advance(n, newlines, after);
            if end.is_some() {
                return Ok(Ok(out));
            }
        }
    }

    /// The next element; `None` at the end of the array or at a syntax error of the batch
    /// (then in [`Elements::error`]).
    pub fn next_element(&mut self) -> std::io::Result<Option<Element>> {
        if self.state == State::Done {
            return Ok(None);
        }
        let Some(b) = self.skip_space()? else {
            return Ok(self.fail("EOF while parsing a list"));
        };
        if b == b']' && self.state == State::First {
            self.bump(b);
            self.end()?;
            return Ok(None);
        }
        let (line, column) = (self.line, self.column);
        let bytes = match self.element_bytes()? {
            Ok(bytes) if bytes.is_empty() => return Ok(self.fail("expected value")),
            Ok(bytes) => bytes,
            Err(m) => return Ok(self.fail(m)),
        };
        // not UTF-8: this problem's error, naming the byte, where it is and what the file
        // looks like
        let (text, not_utf8) = match String::from_utf8(bytes) {
            Ok(text) => (text, None),
            Err(e) => {
                let bytes = e.into_bytes();
                let not = crate::encoding::utf8(&bytes, line, column)
                    .err()
                    .map(|n| n.in_batch());
                (String::from_utf8_lossy(&bytes).into_owned(), not)
            }
        };
        let element = Element {
            text,
            line,
            column,
            not_utf8,
        };
        self.count += 1;
        match self.skip_space()? {
            Some(b',') => {
                self.bump(b',');
                self.state = State::AfterComma;
            }
            Some(b']') => {
                self.bump(b']');
                // what follows the array, if anything, is the error
                self.end()?;
            }
            // the element is answered; the error is after it
            Some(_) => {
                self.fail::<()>("expected `,` or `]`");
            }
            None => {
                self.fail::<()>("EOF while parsing a list");
            }
        }
        Ok(Some(element))
    }

    /// After the closing `]`: only white space may follow.
    fn end(&mut self) -> std::io::Result<()> {
        self.state = State::Done;
        if self.skip_space()?.is_some() {
            self.fail::<()>("trailing characters");
        }
        Ok(())
    }
}

/// Where the scan of an element stands between two slices of the input: its depth of
/// brackets and braces, and whether it is inside a string (just after a backslash there).
#[derive(Debug, Default)]
struct Scan {
    depth: usize,
    in_string: bool,
    escaped: bool,
}

impl Scan {
    /// Scans `buf`: the length of the element's text in it when the element ends there (at
    /// its closing bracket, brace or quote, or before the separator after a number or word),
    /// `None` when it goes on past `buf`. A string is passed over to its next quote or
    /// backslash at a time, the inside of the element to its next quote, bracket or brace.
    fn end(&mut self, buf: &[u8]) -> Option<usize> {
        let mut k = 0usize;
        loop {
            let rest = buf.get(k..)?;
            if self.in_string {
                if self.escaped {
                    if rest.is_empty() {
                        return None;
                    }
                    self.escaped = false;
                    k += 1;
                    continue;
                }
                let i = rest.iter().position(|&b| b == b'"' || b == b'\\')?;
                k += i + 1;
                if rest.get(i) == Some(&b'\\') {
                    self.escaped = true;
                } else {
                    self.in_string = false;
                    if self.depth == 0 {
                        return Some(k);
                    }
                }
                continue;
            }
            // inside the element, only quotes, brackets and braces matter until it ends
            let i = if self.depth == 0 {
                0
            } else {
                rest.iter()
                    .position(|&b| matches!(b, b'"' | b'[' | b']' | b'{' | b'}'))?
            };
            let &b = rest.get(i)?;
            k += i + 1;
            match b {
                b'"' => self.in_string = true,
                b'[' | b'{' => self.depth += 1,
                b']' | b'}' if self.depth > 0 => {
                    self.depth -= 1;
                    if self.depth == 0 {
                        return Some(k);
                    }
                }
                // a number or word ends where a separator begins
                b',' | b']' | b'}' | b' ' | b'\t' | b'\n' | b'\r' if self.depth == 0 => {
                    return Some(k - 1);
                }
                _ => {}
            }
        }
    }
}

/// One problem of a batch, as written, with where it starts in the whole input.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Element {
    /// Its text.
    pub text: String,
    /// The line (from 1) it starts on.
    pub line: usize,
    /// The column (from 1, in bytes) it starts at.
    pub column: usize,
    /// Why its bytes are not UTF-8 (its text then has U+FFFD in their place), when they
    /// are not: the problem's error.
    pub not_utf8: Option<Contract>,
}

impl ProblemSource for Element {
    /// The problem read from its text; a text that is not UTF-8, or not JSON, is this
    /// problem's error, with its place in the whole input.
    fn read(&self, limits: &Limits) -> Result<Problem, ProblemError> {
        if let Some(m) = &self.not_utf8 {
            return Err(ProblemError::at("", m.clone()));
        }
        Problem::read_text(&self.text, limits, |e| {
            let (line, column) = if e.line() <= 1 {
                (self.line, self.column + e.column().saturating_sub(1))
            } else {
                (self.line + e.line() - 1, e.column())
            };
            // serde_json reads any JSON text into a value: only its syntax errors reach here,
            // placed in the whole input
            let why = match serde_error(&e) {
                Contract::Syntax { what, .. } => Contract::Syntax { what, line, column },
                why => why,
            };
            ProblemError::at("", Contract::CannotRead { why: Box::new(why) })
        })
    }
}

impl<R: BufRead> Iterator for Elements<R> {
    type Item = Element;

    /// The next element; a read error of the input ends the batch as a syntax error does.
    fn next(&mut self) -> Option<Element> {
        match self.next_element() {
            Ok(text) => text,
            Err(e) => self.fail(format!("cannot read the input: {e}")),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn all(text: &str) -> (Vec<String>, Option<SyntaxError>) {
        let rest = text.trim_start().strip_prefix('[').unwrap();
        let mut e = Elements::new(rest.as_bytes(), 1, text.len() - rest.len() + 1);
        let items: Vec<String> = e.by_ref().map(|e| e.text).collect();
        (items, e.error)
    }

    #[test]
    fn each_element_as_written() {
        let (items, error) =
            all("[ {\"a\": [1, \"]\\\"\"]}, 2 ,\"x,]\", [[3]], -1.5e3, true ]  \n");
        assert_eq!(error, None);
        assert_eq!(
            items,
            [
                "{\"a\": [1, \"]\\\"\"]}",
                "2",
                "\"x,]\"",
                "[[3]]",
                "-1.5e3",
                "true"
            ]
        );
        assert_eq!(all("[]"), (vec![], None));
        assert_eq!(all(" [ \n ] \n"), (vec![], None));
    }

    #[test]
    fn a_syntax_error_ends_the_batch_where_it_is() {
        // inside an element, it is that problem's (read later); between elements, the batch's
        let (items, error) = all("[{\"op\": 1},\n {\"op\" 2},\n {}  x, {}]");
        assert_eq!(items, ["{\"op\": 1}", "{\"op\" 2}", "{}"]);
        let error = error.unwrap();
        assert_eq!((error.element, error.line, error.column), (3, 3, 6));
        assert_eq!(error.message, "expected `,` or `]`");
        for (text, element) in [
            ("[1, 2", 2),
            ("[1, 2,]", 2),
            ("[1 2]", 1),
            ("[1], 3", 1),
            ("[\"abc", 0),
            ("[", 0),
            ("[1,,2]", 1),
        ] {
            let (items, error) = all(text);
            assert_eq!(error.as_ref().map(|e| e.element), Some(element), "{text}");
            assert_eq!(items.len(), element, "{text}");
        }
    }

    #[test]
    fn elements_split_across_reads_are_whole() {
        // a reader of 1 byte at a time: every state of the scan meets the end of a slice
        let text = "[ {\"a\": [1, \"]\\\"\\\\\"]}, 2 ,\"x,\\\"]\", [[3]],\n -1.5e3, true ]";
        let rest = text.strip_prefix('[').unwrap();
        let reader = std::io::BufReader::with_capacity(1, rest.as_bytes());
        let mut e = Elements::new(reader, 1, 2);
        let items: Vec<String> = e.by_ref().map(|e| e.text).collect();
        assert_eq!(e.error, None);
        assert_eq!(
            items,
            [
                "{\"a\": [1, \"]\\\"\\\\\"]}",
                "2",
                "\"x,\\\"]\"",
                "[[3]]",
                "-1.5e3",
                "true"
            ]
        );
        assert_eq!(items, all(text).0);
    }

    #[test]
    fn a_problem_that_is_not_json_says_where_in_the_whole_input() {
        let mut e = Elements::new("\n  {\"op\": \"evaluate\" \"x\": 1}]".as_bytes(), 1, 2);
        let element = e.next().unwrap();
        assert_eq!((element.line, element.column), (2, 3));
        let error = element.read(&Limits::DEFAULT).unwrap_err();
        assert_eq!(
            error.to_string(),
            "cannot read the problem: expected `,` or `}` at line 2 column 21"
        );
        assert_eq!(e.next(), None);
        assert_eq!(e.error, None);
    }
}
