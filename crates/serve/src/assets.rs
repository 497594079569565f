//! The pages' files, embedded in the binary: a fixed table from a name to its bytes and type.
//! No name is ever turned into a path: a name not in the table is not found.

/// An embedded file: its bytes and its Content-Type.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Asset {
    /// The bytes.
    pub bytes: &'static [u8],
    /// The Content-Type.
    pub content_type: &'static str,
}

const HTML: &str = "text/html; charset=utf-8";
const JS: &str = "text/javascript; charset=utf-8";
const CSS: &str = "text/css; charset=utf-8";
#[allow(dead_code)]
const WOFF2: &str = "font/woff2";

/// The student's page.
pub const STUDENT_HTML: Asset = Asset {
    bytes: include_bytes!("../assets/student.html"),
    content_type: HTML,
};

/// The teacher's page.
pub const TEACHER_HTML: Asset = Asset {
    bytes: include_bytes!("../assets/teacher.html"),
    content_type: HTML,
};

/// The file of `/assets/<name>`, by a fixed table (no path is opened).
pub fn get(name: &str) -> Option<Asset> {
    let (bytes, content_type): (&'static [u8], &'static str) = match name {
        "student.js" => (include_bytes!("../assets/student.js"), JS),
        "teacher.js" => (include_bytes!("../assets/teacher.js"), JS),
        "page.css" => (include_bytes!("../assets/page.css"), CSS),
        "katex/katex.min.js" => (include_bytes!("../assets/katex/katex.min.js"), JS),
        "katex/katex.min.css" => (include_bytes!("../assets/katex/katex.min.css"), CSS),
        // TODO(merger): KaTeX's fonts, one line each from the dist's fonts/ folder, e.g.
        // "katex/fonts/KaTeX_Main-Regular.woff2" => (include_bytes!("../assets/katex/fonts/KaTeX_Main-Regular.woff2"), WOFF2),
        _ => return None,
    };
    Some(Asset {
        bytes,
        content_type,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_the_table() {
        assert!(get("student.js").is_some());
        assert_eq!(get("page.css").map(|a| a.content_type), Some(CSS));
        for name in [
            "../Cargo.toml",
            "/etc/passwd",
            "katex/../student.js",
            "",
            "student.js/",
        ] {
            assert!(get(name).is_none(), "{name}");
        }
    }
}
