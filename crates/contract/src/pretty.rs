//! The pretty JSON of `cagd solve --format json`, written straight into bytes.
//!
//! [`JsonWriter`] writes exactly what `serde_json::to_writer_pretty` writes with [`Pretty`]
//! (two spaces a level), without serde's machinery per value: a number of an answer is its
//! digits written into the buffer (no `String`, no escaping scan: a rational's text is digits,
//! `-` and `/`), each indentation one copy. What it does not write itself (the typed steps of
//! a derivation) it hands to serde_json with [`Pretty`] at its level, so the bytes are the
//! same either way.

use serde::Serialize;
use serde_json::ser::Formatter;
use std::io::Write;

/// serde_json's `PrettyFormatter` (two spaces a level) starting at `level`, writing each
/// indentation at once.
pub struct Pretty {
    /// The containers open (plus the levels the output starts at).
    pub level: usize,
    /// Whether the container being written has a value yet.
    pub has_value: bool,
}

/// Spaces for the indentation of 64 levels; deeper ones are written in pieces.
const SPACES: &[u8; 128] = &[b' '; 128];

/// A comma, a newline and the spaces of 63 levels: an item's line start is a slice of it.
const LINE: &[u8; 128] = b",\n                                                                                                                              ";

/// Writes a newline (after a comma when `comma`) and the indentation of `level`.
fn newline<W: ?Sized + Write>(w: &mut W, level: usize, comma: bool) -> std::io::Result<()> {
    w.write_all(if comma { b",\n" } else { b"\n" })?;
    let mut left = 2 * level;
    while left > 0 {
        let n = left.min(SPACES.len());
        w.write_all(SPACES.get(..n).unwrap_or_default())?;
        left -= n;
    }
    Ok(())
}

impl Pretty {
    /// The formatter of a value written at `level`.
    pub fn at(level: usize) -> Self {
        Pretty {
            level,
            has_value: false,
        }
    }
}

impl Formatter for Pretty {
    fn begin_array<W: ?Sized + Write>(&mut self, w: &mut W) -> std::io::Result<()> {
        self.level += 1;
        self.has_value = false;
        w.write_all(b"[")
    }
    fn end_array<W: ?Sized + Write>(&mut self, w: &mut W) -> std::io::Result<()> {
        self.level = self.level.saturating_sub(1);
        if self.has_value {
            newline(w, self.level, false)?;
        }
        w.write_all(b"]")
    }
    fn begin_array_value<W: ?Sized + Write>(
        &mut self,
        w: &mut W,
        first: bool,
    ) -> std::io::Result<()> {
        newline(w, self.level, !first)
    }
    fn end_array_value<W: ?Sized + Write>(&mut self, _: &mut W) -> std::io::Result<()> {
        self.has_value = true;
        Ok(())
    }
    fn begin_object<W: ?Sized + Write>(&mut self, w: &mut W) -> std::io::Result<()> {
        self.level += 1;
        self.has_value = false;
        w.write_all(b"{")
    }
    fn end_object<W: ?Sized + Write>(&mut self, w: &mut W) -> std::io::Result<()> {
        self.level = self.level.saturating_sub(1);
        if self.has_value {
            newline(w, self.level, false)?;
        }
        w.write_all(b"}")
    }
    fn begin_object_key<W: ?Sized + Write>(
        &mut self,
        w: &mut W,
        first: bool,
    ) -> std::io::Result<()> {
        newline(w, self.level, !first)
    }
    fn begin_object_value<W: ?Sized + Write>(&mut self, w: &mut W) -> std::io::Result<()> {
        w.write_all(b": ")
    }
    fn end_object_value<W: ?Sized + Write>(&mut self, _: &mut W) -> std::io::Result<()> {
        self.has_value = true;
        Ok(())
    }
}

/// A pretty JSON writer into a byte buffer, the bytes of serde_json with [`Pretty`]: a
/// container's items each on a line indented two spaces a level, `[]` and `{}` when empty.
pub(crate) struct JsonWriter<'a> {
    out: &'a mut Vec<u8>,
    /// The containers open, plus the level the output starts at.
    level: usize,
}

impl<'a> JsonWriter<'a> {
    /// A writer appending to `out`, its values indented from `level`.
    pub(crate) fn new(out: &'a mut Vec<u8>, level: usize) -> Self {
        JsonWriter { out, level }
    }

    /// A newline, after a comma unless `first`, and the indentation of the current level.
    fn item(&mut self, first: bool) {
        // the comma, the newline and the spaces in one copy, up to 63 levels
        let start = usize::from(first);
        match LINE.get(start..2 + 2 * self.level) {
            Some(line) => self.out.extend_from_slice(line),
            // writing to memory cannot fail
            None => {
                let _ = newline(self.out, self.level, !first);
            }
        }
    }

    /// A list, `[]` when empty, each item written by `f`.
    pub(crate) fn seq<T>(
        &mut self,
        items: impl IntoIterator<Item = T>,
        mut f: impl FnMut(&mut Self, T),
    ) {
        self.out.push(b'[');
        self.level += 1;
        let mut first = true;
        for x in items {
            self.item(first);
            first = false;
            f(self, x);
        }
        self.level -= 1;
        if !first {
            self.item(true);
        }
        self.out.push(b']');
    }

    /// An object, `{}` when empty: `f` writes its entries with [`JsonWriter::key`].
    pub(crate) fn object(&mut self, f: impl FnOnce(&mut Object<'_, 'a>)) {
        self.out.push(b'{');
        self.level += 1;
        let mut o = Object {
            writer: self,
            first: true,
        };
        f(&mut o);
        let empty = o.first;
        self.level -= 1;
        if !empty {
            self.item(true);
        }
        self.out.push(b'}');
    }

    /// A string, escaped as serde_json escapes it (`"`, `\` and control characters) when it
    /// has such a character.
    pub(crate) fn string(&mut self, s: &str) {
        if s.bytes().any(|b| b == b'"' || b == b'\\' || b < 0x20) {
            let _ = serde_json::to_writer(&mut *self.out, s);
        } else {
            self.out.push(b'"');
            self.out.extend_from_slice(s.as_bytes());
            self.out.push(b'"');
        }
    }

    /// A string whose text `f` appends to the buffer, which needs no escaping (digits, `-`,
    /// `/`).
    pub(crate) fn plain_string(&mut self, f: impl FnOnce(&mut Vec<u8>)) {
        self.out.push(b'"');
        f(self.out);
        self.out.push(b'"');
    }

    /// `true` or `false`.
    pub(crate) fn bool(&mut self, b: bool) {
        self.out
            .extend_from_slice(if b { b"true" as &[u8] } else { b"false" });
    }

    /// An integer.
    pub(crate) fn int(&mut self, n: impl itoa::Integer) {
        self.out
            .extend_from_slice(itoa::Buffer::new().format(n).as_bytes());
    }

    /// Any serializable value, by serde_json at this level: the same bytes.
    pub(crate) fn serde<T: Serialize + ?Sized>(&mut self, value: &T) {
        let mut ser =
            serde_json::Serializer::with_formatter(&mut *self.out, Pretty::at(self.level));
        // writing to memory fails only if serializing does, which these types never do
        let _ = value.serialize(&mut ser);
    }
}

/// The entries of an object being written.
pub(crate) struct Object<'w, 'a> {
    writer: &'w mut JsonWriter<'a>,
    first: bool,
}

impl<'a> Object<'_, 'a> {
    /// Writes the key of the next entry; its value is written next, on the writer returned.
    pub(crate) fn key(&mut self, key: &str) -> &mut JsonWriter<'a> {
        self.writer.item(self.first);
        self.first = false;
        self.writer.string(key);
        self.writer.out.extend_from_slice(b": ");
        self.writer
    }
}
