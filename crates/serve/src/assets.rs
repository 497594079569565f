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
        "common.js" => (include_bytes!("../assets/common.js"), JS),
        "page.css" => (include_bytes!("../assets/page.css"), CSS),
        "katex/katex.min.js" => (include_bytes!("../assets/katex/katex.min.js"), JS),
        "katex/katex.min.css" => (include_bytes!("../assets/katex/katex.min.css"), CSS),
        "katex/fonts/KaTeX_AMS-Regular.woff2" => (
            include_bytes!("../assets/katex/fonts/KaTeX_AMS-Regular.woff2"),
            WOFF2,
        ),
        "katex/fonts/KaTeX_Caligraphic-Bold.woff2" => (
            include_bytes!("../assets/katex/fonts/KaTeX_Caligraphic-Bold.woff2"),
            WOFF2,
        ),
        "katex/fonts/KaTeX_Caligraphic-Regular.woff2" => (
            include_bytes!("../assets/katex/fonts/KaTeX_Caligraphic-Regular.woff2"),
            WOFF2,
        ),
        "katex/fonts/KaTeX_Fraktur-Bold.woff2" => (
            include_bytes!("../assets/katex/fonts/KaTeX_Fraktur-Bold.woff2"),
            WOFF2,
        ),
        "katex/fonts/KaTeX_Fraktur-Regular.woff2" => (
            include_bytes!("../assets/katex/fonts/KaTeX_Fraktur-Regular.woff2"),
            WOFF2,
        ),
        "katex/fonts/KaTeX_Main-Bold.woff2" => (
            include_bytes!("../assets/katex/fonts/KaTeX_Main-Bold.woff2"),
            WOFF2,
        ),
        "katex/fonts/KaTeX_Main-BoldItalic.woff2" => (
            include_bytes!("../assets/katex/fonts/KaTeX_Main-BoldItalic.woff2"),
            WOFF2,
        ),
        "katex/fonts/KaTeX_Main-Italic.woff2" => (
            include_bytes!("../assets/katex/fonts/KaTeX_Main-Italic.woff2"),
            WOFF2,
        ),
        "katex/fonts/KaTeX_Main-Regular.woff2" => (
            include_bytes!("../assets/katex/fonts/KaTeX_Main-Regular.woff2"),
            WOFF2,
        ),
        "katex/fonts/KaTeX_Math-BoldItalic.woff2" => (
            include_bytes!("../assets/katex/fonts/KaTeX_Math-BoldItalic.woff2"),
            WOFF2,
        ),
        "katex/fonts/KaTeX_Math-Italic.woff2" => (
            include_bytes!("../assets/katex/fonts/KaTeX_Math-Italic.woff2"),
            WOFF2,
        ),
        "katex/fonts/KaTeX_SansSerif-Bold.woff2" => (
            include_bytes!("../assets/katex/fonts/KaTeX_SansSerif-Bold.woff2"),
            WOFF2,
        ),
        "katex/fonts/KaTeX_SansSerif-Italic.woff2" => (
            include_bytes!("../assets/katex/fonts/KaTeX_SansSerif-Italic.woff2"),
            WOFF2,
        ),
        "katex/fonts/KaTeX_SansSerif-Regular.woff2" => (
            include_bytes!("../assets/katex/fonts/KaTeX_SansSerif-Regular.woff2"),
            WOFF2,
        ),
        "katex/fonts/KaTeX_Script-Regular.woff2" => (
            include_bytes!("../assets/katex/fonts/KaTeX_Script-Regular.woff2"),
            WOFF2,
        ),
        "katex/fonts/KaTeX_Size1-Regular.woff2" => (
            include_bytes!("../assets/katex/fonts/KaTeX_Size1-Regular.woff2"),
            WOFF2,
        ),
        "katex/fonts/KaTeX_Size2-Regular.woff2" => (
            include_bytes!("../assets/katex/fonts/KaTeX_Size2-Regular.woff2"),
            WOFF2,
        ),
        "katex/fonts/KaTeX_Size3-Regular.woff2" => (
            include_bytes!("../assets/katex/fonts/KaTeX_Size3-Regular.woff2"),
            WOFF2,
        ),
        "katex/fonts/KaTeX_Size4-Regular.woff2" => (
            include_bytes!("../assets/katex/fonts/KaTeX_Size4-Regular.woff2"),
            WOFF2,
        ),
        "katex/fonts/KaTeX_Typewriter-Regular.woff2" => (
            include_bytes!("../assets/katex/fonts/KaTeX_Typewriter-Regular.woff2"),
            WOFF2,
        ),
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

    /// Every script, style sheet and font under `assets/` is served (KaTeX's fonts included:
    /// its style sheet asks for them by name).
    #[test]
    fn every_file_the_pages_ask_for_is_in_the_table() {
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("assets");
        let mut names = Vec::new();
        let mut dirs = vec![root.clone()];
        while let Some(d) = dirs.pop() {
            for e in std::fs::read_dir(&d).unwrap() {
                let p = e.unwrap().path();
                if p.is_dir() {
                    dirs.push(p);
                } else if ["js", "css", "woff2"]
                    .iter()
                    .any(|x| p.extension().is_some_and(|e| e == *x))
                {
                    let rel = p
                        .strip_prefix(&root)
                        .unwrap()
                        .to_string_lossy()
                        .replace('\\', "/");
                    names.push(rel);
                }
            }
        }
        assert!(names.len() > 20, "{names:?}");
        for n in names {
            assert!(get(&n).is_some(), "{n} is not served");
        }
        let css = String::from_utf8_lossy(get("katex/katex.min.css").unwrap().bytes).into_owned();
        for font in css.split("url(fonts/").skip(1) {
            let file = font.split(')').next().unwrap();
            if file.ends_with(".woff2") {
                assert!(get(&format!("katex/fonts/{file}")).is_some(), "{file}");
            }
        }
    }
}
