//! Input that is not UTF-8, named as such: JSON is read as UTF-8 (a UTF-8 byte-order mark is
//! skipped), and a file saved as UTF-16, UTF-32 or Latin-1 is refused with a message that says
//! so and what to do ("save it as UTF-8"), instead of a JSON parser's "invalid unicode code
//! point" or "expected value at line 1 column 1".

use crate::said::{CliMessage, Input};
use cagd_problem::message::contract::Contract;

/// An encoding that a document which is not UTF-8 looks like.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Encoding {
    /// UTF-16, little-endian (Windows' "Unicode").
    Utf16Le,
    /// UTF-16, big-endian.
    Utf16Be,
    /// UTF-32, little-endian.
    Utf32Le,
    /// UTF-32, big-endian.
    Utf32Be,
    /// One byte a character: ISO 8859-1 or Windows-1252 (`é` as the byte 0xE9).
    Latin1,
}

impl Encoding {
    /// Its usual name (`UTF-16LE`, `Latin-1`): the same in every language.
    pub fn name(self) -> &'static str {
        match self {
            Encoding::Utf16Le => "UTF-16LE",
            Encoding::Utf16Be => "UTF-16BE",
            Encoding::Utf32Le => "UTF-32LE",
            Encoding::Utf32Be => "UTF-32BE",
            Encoding::Latin1 => "Latin-1",
        }
    }
}

/// The wide encoding (UTF-16 or UTF-32) the first bytes of a document show: its byte-order
/// mark, or the NUL bytes beside the first ASCII character (a JSON document never holds a NUL
/// byte, and 0xFE, 0xFF never occur in UTF-8). `None` when they may be UTF-8.
pub fn wide(head: &[u8]) -> Option<Encoding> {
    match head {
        [0xFF, 0xFE, 0, 0, ..] => Some(Encoding::Utf32Le),
        [0, 0, 0xFE, 0xFF, ..] => Some(Encoding::Utf32Be),
        [0xFF, 0xFE, ..] => Some(Encoding::Utf16Le),
        [0xFE, 0xFF, ..] => Some(Encoding::Utf16Be),
        [a, 0, 0, 0, ..] if *a != 0 => Some(Encoding::Utf32Le),
        [0, 0, 0, a, ..] if *a != 0 => Some(Encoding::Utf32Be),
        [a, 0, ..] if *a != 0 => Some(Encoding::Utf16Le),
        [0, a, ..] if *a != 0 => Some(Encoding::Utf16Be),
        _ => None,
    }
}

/// Where a document stops being UTF-8, and what it looks like.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct NotUtf8 {
    /// The encoding it looks like.
    pub encoding: Encoding,
    /// The first byte that is not UTF-8, with its line and column (from 1; columns count
    /// bytes, as the JSON errors' do); `None` for a wide encoding, seen from the start.
    pub at: Option<(u8, usize, usize)>,
}

impl NotUtf8 {
    /// The message of a whole input: `p.json is not UTF-8 (it looks like UTF-16LE): save it
    /// as UTF-8` (`standard input is not UTF-8...`).
    pub fn message(&self, path: &str) -> CliMessage {
        let looks = self.encoding.name().to_string();
        match (Input::of(path), self.at) {
            (Input::Stdin, None) => CliMessage::NotUtf8Stdin { looks },
            (Input::File(path), None) => CliMessage::NotUtf8File { path, looks },
            (Input::Stdin, Some((byte, line, column))) => CliMessage::NotUtf8StdinAt {
                byte: format!("0x{byte:02X}"),
                line,
                column,
                looks,
            },
            (Input::File(path), Some((byte, line, column))) => CliMessage::NotUtf8FileAt {
                path,
                byte: format!("0x{byte:02X}"),
                line,
                column,
                looks,
            },
        }
    }

    /// The message of one problem of a batch, whose file is named by the batch: `the file is
    /// not UTF-8: byte 0xE9 at line 2, column 14 (it looks like Latin-1): save it as UTF-8`.
    pub fn in_batch(&self) -> Contract {
        Contract::NotUtf8InBatch {
            at: self
                .at
                .map(|(byte, line, column)| (format!("0x{byte:02X}"), line, column)),
            looks: self.encoding.name().to_string(),
        }
    }
}

/// The bytes as text, or where they stop being UTF-8 (`line` and `column` are where `bytes`
/// start in the whole input): a wide encoding is seen from the first bytes, any other bytes
/// that are not UTF-8 are taken for Latin-1.
pub fn utf8(bytes: &[u8], line: usize, column: usize) -> Result<&str, NotUtf8> {
    if let Some(encoding) = wide(bytes) {
        return Err(NotUtf8 { encoding, at: None });
    }
    std::str::from_utf8(bytes).map_err(|e| {
        let at = e.valid_up_to();
        let before = bytes.get(..at).unwrap_or_default();
        let newlines = before.iter().filter(|&&b| b == b'\n').count();
        let column = match before.iter().rposition(|&b| b == b'\n') {
            Some(k) => at - k,
            None => column + at,
        };
        NotUtf8 {
            encoding: Encoding::Latin1,
            at: Some((
                bytes.get(at).copied().unwrap_or_default(),
                line + newlines,
                column,
            )),
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wide_encodings_by_their_first_bytes() {
        let text = "{\"op\": \"circle\"}";
        let utf16le: Vec<u8> = text.encode_utf16().flat_map(u16::to_le_bytes).collect();
        let utf16be: Vec<u8> = text.encode_utf16().flat_map(u16::to_be_bytes).collect();
        let utf32le: Vec<u8> = text
            .chars()
            .flat_map(|c| (c as u32).to_le_bytes())
            .collect();
        let utf32be: Vec<u8> = text
            .chars()
            .flat_map(|c| (c as u32).to_be_bytes())
            .collect();
        assert_eq!(wide(&utf16le), Some(Encoding::Utf16Le));
        assert_eq!(wide(&utf16be), Some(Encoding::Utf16Be));
        assert_eq!(wide(&utf32le), Some(Encoding::Utf32Le));
        assert_eq!(wide(&utf32be), Some(Encoding::Utf32Be));
        assert_eq!(
            wide(&[&[0xFF, 0xFE][..], &utf16le].concat()),
            Some(Encoding::Utf16Le)
        );
        assert_eq!(
            wide(&[&[0xFE, 0xFF][..], &utf16be].concat()),
            Some(Encoding::Utf16Be)
        );
        assert_eq!(wide(text.as_bytes()), None);
        assert_eq!(wide(b"5"), None);
        assert_eq!(wide(b""), None);
        assert_eq!(utf8(text.as_bytes(), 1, 1), Ok(text));
    }

    #[test]
    fn latin1_names_the_first_byte_and_its_place() {
        let e = utf8(b"{\"op\": \"circle\",\n \"title\": \"B\xE9zier\"}", 1, 1).unwrap_err();
        assert_eq!(e.encoding, Encoding::Latin1);
        assert_eq!(e.at, Some((0xE9, 2, 13)));
        assert_eq!(
            e.message("p.json").to_string(),
            "p.json is not UTF-8: byte 0xE9 at line 2, column 13 (it looks like Latin-1): save \
             it as UTF-8"
        );
        // inside a batch, from where the problem starts
        let e = utf8(b"{\"t\": \"\xF1\"}", 3, 5).unwrap_err();
        assert_eq!(e.at, Some((0xF1, 3, 12)));
    }
}
