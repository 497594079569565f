//! A batch (a JSON array of problems) read element by element from a file or standard input,
//! so that `cagd solve` holds a few problems at a time, not the whole batch.
//!
//! The reader finds where each element of the top-level array ends (brackets and braces
//! outside strings), checks that its text is JSON, and hands it over; what follows it must be
//! `,` or the closing `]`, and after the array only white space. A syntax error stops the
//! batch there: the problems before it have been handed over (and are answered), and the
//! error says where it is, by line and column of the whole input, and in which element.

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

/// serde_json's message of an error without its " at line L column C".
fn bare_message(e: &serde_json::Error) -> String {
    let text = e.to_string();
    let tail = format!(" at line {} column {}", e.line(), e.column());
    text.strip_suffix(&tail)
        .map_or(text.clone(), str::to_string)
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
        } else if b & 0xC0 != 0x80 {
            // a column per character, not per byte of UTF-8
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
    fn fail(&mut self, message: impl Into<String>) -> Option<String> {
        self.fail_at(self.line, self.column, message.into())
    }

    fn fail_at(&mut self, line: usize, column: usize, message: String) -> Option<String> {
        self.state = State::Done;
        self.error = Some(SyntaxError {
            element: self.count,
            line,
            column,
            message,
        });
        None
    }

    /// The text of the element that starts here: up to its closing bracket or brace (outside
    /// strings), or to the end of a string or of a number or word.
    fn element_bytes(&mut self) -> std::io::Result<Result<Vec<u8>, String>> {
        let mut out = Vec::new();
        let (mut depth, mut in_string, mut escaped) = (0usize, false, false);
        loop {
            let Some(b) = self.peek()? else {
                if depth == 0 && !in_string && !out.is_empty() {
                    // a number or word at the end of the input
                    return Ok(Ok(out));
                }
                return Ok(Err("EOF while parsing a list".into()));
            };
            if in_string {
                match b {
                    _ if escaped => escaped = false,
                    b'\\' => escaped = true,
                    b'"' => in_string = false,
                    _ => {}
                }
            } else {
                match b {
                    b'"' => in_string = true,
                    b'[' | b'{' => depth += 1,
                    b']' | b'}' if depth > 0 => depth -= 1,
                    // a number or word ends where a separator begins
                    b',' | b']' | b'}' | b' ' | b'\t' | b'\n' | b'\r' if depth == 0 => {
                        return Ok(Ok(out));
                    }
                    _ => {}
                }
            }
            out.push(b);
            self.bump(b);
            if depth == 0 && !in_string && matches!(b, b']' | b'}' | b'"') {
                return Ok(Ok(out));
            }
        }
    }

    /// The next element's text; `None` at the end of the array or at a syntax error (then in
    /// [`Elements::error`]).
    pub fn next_element(&mut self) -> std::io::Result<Option<String>> {
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
            Ok(bytes) => bytes,
            Err(m) => return Ok(self.fail(m)),
        };
        let text = match String::from_utf8(bytes) {
            Ok(text) => text,
            Err(_) => return Ok(self.fail_at(line, column, "invalid unicode code point".into())),
        };
        if let Err(e) = serde_json::from_str::<serde::de::IgnoredAny>(&text) {
            // where in the whole input
            let (l, c) = if e.line() <= 1 {
                (line, column + e.column().saturating_sub(1))
            } else {
                (line + e.line() - 1, e.column())
            };
            return Ok(self.fail_at(l, c, bare_message(&e)));
        }
        match self.skip_space()? {
            Some(b',') => {
                self.bump(b',');
                self.state = State::AfterComma;
            }
            Some(b']') => {
                self.bump(b']');
                self.count += 1;
                // the element is answered; what follows the array, if anything, is the error
                self.end()?;
                return Ok(Some(text));
            }
            // the element is answered; the error is after it
            Some(_) => {
                self.count += 1;
                self.fail("expected `,` or `]`");
                return Ok(Some(text));
            }
            None => {
                self.count += 1;
                self.fail("EOF while parsing a list");
                return Ok(Some(text));
            }
        }
        self.count += 1;
        Ok(Some(text))
    }

    /// After the closing `]`: only white space may follow.
    fn end(&mut self) -> std::io::Result<()> {
        self.state = State::Done;
        if self.skip_space()?.is_some() {
            self.fail("trailing characters");
        }
        Ok(())
    }
}

impl<R: BufRead> Iterator for Elements<R> {
    type Item = String;

    /// The next element; a read error of the input ends the batch as a syntax error does.
    fn next(&mut self) -> Option<String> {
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
        let items: Vec<String> = e.by_ref().collect();
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
        let (items, error) = all("[{\"op\": 1},\n {\"op\": 2},\n {\"op\" 3}, {}]");
        assert_eq!(items.len(), 2);
        let error = error.unwrap();
        assert_eq!((error.element, error.line, error.column), (2, 3, 8));
        assert_eq!(error.message, "expected `:`");
        for (text, element) in [
            ("[1, 2", 2),
            ("[1, 2,]", 2),
            ("[1 2]", 1),
            ("[1], 3", 1),
            ("[{\"a\": 1]", 0),
            ("[\"abc", 0),
            ("[", 0),
            ("[1,,2]", 1),
        ] {
            let (items, error) = all(text);
            assert_eq!(error.as_ref().map(|e| e.element), Some(element), "{text}");
            assert!(items.len() <= element, "{text}");
        }
    }
}
