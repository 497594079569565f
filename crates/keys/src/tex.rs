//! The one LaTeX escaper of cagd-keys: the text of a problem never runs.
//!
//! A problem's words (its `name`, `title`, `note`, `errata`, their Spanish, an `expected` key
//! echoed in a verdict, a string echoed in an error, the input file's name) enter a LaTeX
//! document only through the functions of this module:
//!
//! - [`text`]: text mode. Every character TeX treats specially is escaped (`\` is
//!   `\textbackslash{}`, `^` is `\^{}`), control characters are written visibly, and a Unicode
//!   character passes only when the preamble handles it (the letters and symbols that LaTeX's
//!   `utf8` sets up for T1, TS1, OT1 and OMS, and the symbols [`latex_preamble`] declares);
//!   any other is written as a visible `U+0416` in typewriter, which cannot fail.
//! - [`math`]: the whitelist typesetter of plain-text mathematics (`c_{1,1}`, `Δ^{1,0}c_{0,j}`,
//!   `√2/2`, `c~`), for math mode. Every token it writes comes from a fixed table: letters,
//!   digits, a few operators and punctuation, `_`/`^` followed by a group whose braces it
//!   balances itself (with `{}` before a second script of one kind, so `x^^2` is `x^{}{}^{2}`),
//!   known Unicode symbols mapped to fixed commands, `\text{...}` of [`text`] for anything
//!   else. A backslash, `$`, `%`, `#`, `&`, `~`, an unbalanced brace, `^^` (TeX's `^^5c` is a
//!   backslash) or a control character from its input is never written raw.
//! - [`words`]: text of unknown make. A word that looks like mathematics (with `_`, `^`, `Δ`,
//!   `√`, ...) is typeset by [`math`], one word at a time (a math span never crosses a space);
//!   identifiers in backticks are typewriter; the rest is [`text`].
//! - [`graphics`]: a figure's path in `\includegraphics`, whatever its characters.
//!
//! The engine's own mathematics (numbers, meshes, polynomials from exact values) is LaTeX
//! written by the engine's printers and is set as it is; [`known_characters`] writes a letter
//! the preamble cannot set (a parameter named `ж`) visibly there too.
//!
//! [`latex_preamble`]: crate::latex_preamble

/// The characters above U+009F that LaTeX's `utf8` input encoding sets up for the font
/// encodings the preamble loads (T1, TS1, OT1, OMS), as inclusive ranges of code points: the
/// `\DeclareUnicodeCharacter` lines of `t1enc.dfu`, `ts1enc.dfu`, `ot1enc.dfu`, `omsenc.dfu`
/// and `utf8.def` (TeX Live 2022), each compiled with pdflatex. Latin-1 and most of Latin
/// Extended-A are here; `Ħ`, `ĸ`, `Ŀ`, `ŉ`, `Ŧ`, `ſ` are not.
const SET_UP: &[(u32, u32)] = &[
    (0x00A0, 0x0125),
    (0x0128, 0x0137),
    (0x0139, 0x013E),
    (0x0141, 0x0148),
    (0x014A, 0x0165),
    (0x0168, 0x017E),
    (0x0192, 0x0192),
    (0x01C4, 0x01D4),
    (0x01E2, 0x01E3),
    (0x01E6, 0x01EB),
    (0x01F0, 0x01F0),
    (0x01F4, 0x01F5),
    (0x0218, 0x021B),
    (0x0232, 0x0233),
    (0x0237, 0x0237),
    (0x02C6, 0x02C7),
    (0x02D8, 0x02D9),
    (0x02DB, 0x02DD),
    (0x0E3F, 0x0E3F),
    (0x1E02, 0x1E03),
    (0x1E0D, 0x1E0D),
    (0x1E1E, 0x1E21),
    (0x1E25, 0x1E25),
    (0x1E30, 0x1E31),
    (0x1E37, 0x1E37),
    (0x1E43, 0x1E43),
    (0x1E45, 0x1E45),
    (0x1E47, 0x1E47),
    (0x1E5B, 0x1E5B),
    (0x1E63, 0x1E63),
    (0x1E6D, 0x1E6D),
    (0x1E8E, 0x1E91),
    (0x1E9E, 0x1E9E),
    (0x1EF2, 0x1EF3),
    (0x200C, 0x200C),
    (0x2010, 0x2016),
    (0x2018, 0x201A),
    (0x201C, 0x201E),
    (0x2020, 0x2022),
    (0x2026, 0x2026),
    (0x2030, 0x2031),
    (0x2039, 0x203B),
    (0x203D, 0x203D),
    (0x2044, 0x2044),
    (0x204E, 0x204E),
    (0x2052, 0x2052),
    (0x20A1, 0x20A1),
    (0x20A4, 0x20A4),
    (0x20A6, 0x20A6),
    (0x20A9, 0x20A9),
    (0x20AB, 0x20AC),
    (0x20B1, 0x20B1),
    (0x2103, 0x2103),
    (0x2116, 0x2117),
    (0x211E, 0x211E),
    (0x2120, 0x2120),
    (0x2122, 0x2122),
    (0x2126, 0x2127),
    (0x212E, 0x212E),
    (0x2190, 0x2193),
    (0x2329, 0x232A),
    (0x2422, 0x2423),
    (0x25E6, 0x25E6),
    (0x25EF, 0x25EF),
    (0x266A, 0x266A),
    (0x27E8, 0x27E9),
    (0x3008, 0x3009),
    (0xFB00, 0xFB06),
    (0xFEFF, 0xFEFF),
];

/// The characters the preamble declares (`\DeclareUnicodeCharacter{code}{\ensuremath{tex}}`):
/// the mathematical symbols a note or a title may have in its words, superscript digits,
/// combining accents, and every Greek letter (a parameter may be `β`).
pub(crate) const DECLARED: &[(char, &str)] = &[
    ('∂', "\\partial"),
    ('Σ', "\\Sigma"),
    ('Δ', "\\Delta"),
    ('√', "\\surd"),
    ('·', "\\cdot"),
    ('×', "\\times"),
    ('≡', "\\equiv"),
    ('∞', "\\infty"),
    ('≠', "\\neq"),
    ('≤', "\\leq"),
    ('≥', "\\geq"),
    ('θ', "\\theta"),
    ('π', "\\pi"),
    ('α', "\\alpha"),
    ('ω', "\\omega"),
    ('∈', "\\in"),
    ('→', "\\to"),
    ('∑', "\\sum"),
    ('σ', "\\sigma"),
    ('λ', "\\lambda"),
    ('ρ', "\\rho"),
    ('τ', "\\tau"),
    // superscript digits in words (C⁰, w⁴): ¹ ² ³ are inputenc's own
    ('⁰', "^{0}"),
    ('⁴', "^{4}"),
    ('⁵', "^{5}"),
    ('⁶', "^{6}"),
    ('⁷', "^{7}"),
    ('⁸', "^{8}"),
    ('⁹', "^{9}"),
    // combining accents in words (f̂, b̃): the accent after its letter
    ('\u{302}', "\\hat{}"),
    ('\u{303}', "\\tilde{}"),
    // the other Greek letters, which `parameters` accepts
    ('β', "\\beta"),
    ('γ', "\\gamma"),
    ('δ', "\\delta"),
    ('ε', "\\varepsilon"),
    ('ϵ', "\\epsilon"),
    ('ζ', "\\zeta"),
    ('η', "\\eta"),
    ('ϑ', "\\vartheta"),
    ('ι', "\\iota"),
    ('κ', "\\kappa"),
    ('μ', "\\mu"),
    ('ν', "\\nu"),
    ('ξ', "\\xi"),
    ('ο', "o"),
    ('ϖ', "\\varpi"),
    ('ϱ', "\\varrho"),
    ('ς', "\\varsigma"),
    ('υ', "\\upsilon"),
    ('φ', "\\varphi"),
    ('ϕ', "\\phi"),
    ('χ', "\\chi"),
    ('ψ', "\\psi"),
    ('Α', "\\mathrm{A}"),
    ('Β', "\\mathrm{B}"),
    ('Γ', "\\Gamma"),
    ('Ε', "\\mathrm{E}"),
    ('Ζ', "\\mathrm{Z}"),
    ('Η', "\\mathrm{H}"),
    ('Θ', "\\Theta"),
    ('Ι', "\\mathrm{I}"),
    ('Κ', "\\mathrm{K}"),
    ('Λ', "\\Lambda"),
    ('Μ', "\\mathrm{M}"),
    ('Ν', "\\mathrm{N}"),
    ('Ξ', "\\Xi"),
    ('Ο', "\\mathrm{O}"),
    ('Π', "\\Pi"),
    ('Ρ', "\\mathrm{P}"),
    ('Τ', "\\mathrm{T}"),
    ('Υ', "\\Upsilon"),
    ('Φ', "\\Phi"),
    ('Χ', "\\mathrm{X}"),
    ('Ψ', "\\Psi"),
    ('Ω', "\\Omega"),
    // the other symbols of the engine's sentences (u ↦ a + b - u, ∫|σ|/w² dt, BᵗB, (B_Vᵗ)⁻¹)
    ('∫', "\\int"),
    ('↦', "\\mapsto"),
    ('−', "-"),
    ('≈', "\\approx"),
    ('⇒', "\\Rightarrow"),
    ('⇔', "\\Leftrightarrow"),
    ('↔', "\\leftrightarrow"),
    ('∏', "\\prod"),
    ('∉', "\\notin"),
    ('∘', "\\circ"),
    ('⋯', "\\cdots"),
    ('ℓ', "\\ell"),
    ('ṽ', "\\tilde{v}"),
    ('⁺', "^{+}"),
    ('⁻', "^{-}"),
    ('ᵗ', "^{t}"),
    ('ᵀ', "^{T}"),
    ('₀', "_{0}"),
    ('₁', "_{1}"),
    ('₂', "_{2}"),
    ('₃', "_{3}"),
    ('₄', "_{4}"),
    ('₅', "_{5}"),
    ('₆', "_{6}"),
    ('₇', "_{7}"),
    ('₈', "_{8}"),
    ('₉', "_{9}"),
];

/// The preamble's `\DeclareUnicodeCharacter` lines, one per [`DECLARED`] character.
pub(crate) fn declarations() -> String {
    DECLARED
        .iter()
        .map(|(c, tex)| {
            format!(
                "\\DeclareUnicodeCharacter{{{:04X}}}{{\\ensuremath{{{tex}}}}}\n",
                u32::from(*c)
            )
        })
        .collect()
}

fn declared(c: char) -> bool {
    DECLARED.iter().any(|(d, _)| *d == c)
}

fn set_up(c: char) -> bool {
    let u = u32::from(c);
    SET_UP.iter().any(|(a, b)| (*a..=*b).contains(&u))
}

/// A character the preamble cannot set, written visibly: `\texttt{U+0416}`.
fn visible(c: char) -> String {
    format!("\\texttt{{U+{:04X}}}", u32::from(c))
}

/// A character that is a script (`⁴`, `ᵗ`, `₁`): `^` or `_`, and what it raises or lowers.
fn script_char(c: char) -> Option<(char, char)> {
    let sup = match c {
        '⁰' => '0',
        '¹' => '1',
        '²' => '2',
        '³' => '3',
        '⁴' => '4',
        '⁵' => '5',
        '⁶' => '6',
        '⁷' => '7',
        '⁸' => '8',
        '⁹' => '9',
        '⁺' => '+',
        '⁻' => '-',
        'ᵗ' => 't',
        'ᵀ' => 'T',
        _ => {
            let u = u32::from(c);
            return match u {
                0x2080..=0x2089 => char::from_digit(u - 0x2080, 10).map(|d| ('_', d)),
                _ => None,
            };
        }
    };
    Some(('^', sup))
}

/// One character in text mode.
fn text_char(c: char, out: &mut String) {
    match c {
        '\\' => out.push_str("\\textbackslash{}"),
        '&' | '%' | '$' | '#' | '_' | '{' | '}' => {
            out.push('\\');
            out.push(c);
        }
        '^' => out.push_str("\\^{}"),
        '~' => out.push_str("\\~{}"),
        '√' => out.push_str("$\\sqrt{}$"),
        'Δ' => out.push_str("$\\Delta$"),
        // white space: a blank line would end a paragraph inside a command's argument
        '\n' | '\t' => out.push(' '),
        ' ' => out.push(' '),
        c if c.is_ascii_graphic() => out.push(c),
        c if declared(c) || set_up(c) => out.push(c),
        // control characters, and what the preamble does not set up
        c => out.push_str(&visible(c)),
    }
}

/// Text for LaTeX's text mode: every special character escaped, control characters and the
/// characters the preamble does not set up written visibly (`\texttt{U+001B}`).
///
/// ```
/// use cagd_keys::tex::text;
/// assert_eq!(text("50% of $x & y_1"), "50\\% of \\$x \\& y\\_1");
/// assert_eq!(text("\\input{a}"), "\\textbackslash{}input\\{a\\}");
/// assert_eq!(text("x^^5c ж"), "x\\^{}\\^{}5c \\texttt{U+0436}");
/// assert_eq!(text("parametrización"), "parametrización");
/// ```
pub fn text(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        text_char(c, &mut out);
    }
    out
}

/// What the last tokens of a formula were, to keep TeX from a double script: a sub- or
/// superscript already given to the current nucleus.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
struct Scripts {
    sub: bool,
    sup: bool,
    /// The last token was a prime (TeX joins `'^2`, `''`).
    prime: bool,
}

/// An open brace of the formula being typeset: a group after `_` or `^` (with the scripts of
/// the nucleus outside it), or a set `\{`.
#[derive(Debug, Clone, Copy)]
enum Open {
    Group(Scripts),
    Set,
}

/// The formula being typeset: its tokens (each from the fixed table), the scripts of its
/// current nucleus and its open braces.
#[derive(Debug, Default)]
struct Formula {
    tokens: Vec<String>,
    scripts: Scripts,
    open: Vec<Open>,
}

impl Formula {
    /// A new nucleus: a letter, a digit, a symbol.
    fn atom(&mut self, t: impl Into<String>) {
        self.tokens.push(t.into());
        self.scripts = Scripts::default();
    }

    /// `_` or `^`, after an empty nucleus `{}` when the nucleus has one already.
    fn script(&mut self, c: char) {
        let s = self.scripts;
        let twice = match c {
            '_' => s.sub,
            _ => s.sup && !s.prime,
        };
        if twice {
            self.tokens.push("{}".into());
            self.scripts = Scripts::default();
        }
        self.tokens.push(c.to_string());
        match c {
            '_' => self.scripts.sub = true,
            _ => self.scripts.sup = true,
        }
        self.scripts.prime = false;
    }

    fn prime(&mut self) {
        if self.scripts.sup && !self.scripts.prime {
            self.tokens.push("{}".into());
            self.scripts = Scripts::default();
        }
        self.tokens.push("'".into());
        self.scripts.sup = true;
        self.scripts.prime = true;
    }

    /// The `{` of a script's group.
    fn open_group(&mut self) {
        self.open.push(Open::Group(self.scripts));
        self.tokens.push("{".into());
        self.scripts = Scripts::default();
    }

    /// A `}`: the group or the set it closes; a `}` that closes nothing is a brace printed.
    fn close(&mut self) {
        match self.open.pop() {
            Some(Open::Group(outer)) => {
                self.tokens.push("}".into());
                self.scripts = outer;
            }
            Some(Open::Set) | None => self.atom("\\}"),
        }
    }

    /// A script's bare group: `_12` is `_{12}`.
    fn script_run(&mut self, c: char, run: &[char]) {
        self.script(c);
        self.open_group();
        for &r in run {
            self.char(r);
        }
        self.close();
    }

    /// Script characters (`x²`, `Bᵗ`, `c₁`) as a script of one kind.
    fn scripts_of(&mut self, kind: char, what: &str) {
        self.script(kind);
        self.open_group();
        self.atom(what);
        self.close();
    }

    /// One character through the fixed table.
    fn char(&mut self, c: char) {
        if let Some((kind, d)) = script_char(c) {
            return self.scripts_of(kind, &d.to_string());
        }
        match c {
            ' ' => self.tokens.push(" ".into()),
            '\'' => self.prime(),
            '{' => {
                self.atom("\\{");
                self.open.push(Open::Set);
            }
            '}' => self.close(),
            '_' | '^' => self.script_run(c, &[]),
            c => {
                let t = math_char(c);
                self.atom(t);
            }
        }
    }

    /// The formula, every group it opened closed.
    fn finish(mut self) -> String {
        while let Some(o) = self.open.pop() {
            if let Open::Group(_) = o {
                self.tokens.push("}".into());
            }
        }
        self.tokens.concat()
    }
}

/// One character of a formula (not a script, brace or prime) as its fixed token.
fn math_char(c: char) -> String {
    let fixed = match c {
        'Δ' => "\\Delta ",
        '·' => "\\cdot ",
        '×' => "\\times ",
        '∞' => "\\infty ",
        '≠' => "\\neq ",
        '≡' => "\\equiv ",
        '≤' => "\\leq ",
        '≥' => "\\geq ",
        'θ' => "\\theta ",
        '∂' => "\\partial ",
        'Σ' => "\\Sigma ",
        'π' => "\\pi ",
        '…' => "\\dots ",
        '~' => "\\sim ",
        '\\' => "\\backslash ",
        '&' => "\\&",
        '%' => "\\%",
        '#' => "\\#",
        '$' => "\\$",
        _ => "",
    };
    if !fixed.is_empty() {
        return fixed.into();
    }
    let plain = c.is_ascii_alphanumeric()
        || matches!(
            c,
            '+' | '-' | '=' | '<' | '>' | '/' | '(' | ')' | '[' | ']' | ',' | '.' | ';' | ':'
                | '!' | '?' | '*' | '|'
        )
        // declared in the preamble as \ensuremath{...} (superscripts are handled before)
        || declared(c);
    match plain {
        true => c.to_string(),
        false => format!("\\text{{{}}}", text(&c.to_string())),
    }
}

/// Plain-text mathematics (the engine's sentences' and a fixture's: `Δ^{1,0} c~_{0,1}`,
/// `√2/2`, `c_1,m-1`, sets in braces) as LaTeX for math mode, through a fixed table: nothing
/// of its input runs (see the module's documentation).
///
/// ```
/// use cagd_keys::tex::math;
/// assert_eq!(math("Δ^{1,0} c~_{0,1}"), "\\Delta ^{1,0} \\tilde{c}_{0,1}");
/// assert_eq!(math("√2/2"), "\\sqrt{2}/2");
/// assert_eq!(math("c_1,2^{1,0}"), "c_{1,2}^{1,0}");
/// assert_eq!(math("{c_1m, c_2m}"), "\\{c_{1m}, c_{2m}\\}");
/// assert_eq!(math("x^^2"), "x^{}{}^{2}");
/// assert_eq!(math("x_( \\input a"), "x_{}( \\backslash input a");
/// assert_eq!(math("(u + 1) cos v"), "(u + 1) \\cos v");
/// ```
pub fn math(s: &str) -> String {
    let cs: Vec<char> = s.chars().collect();
    let mut f = Formula::default();
    let mut i = 0;
    while let Some(&c) = cs.get(i) {
        match c {
            '√' => {
                let mut d = String::new();
                while let Some(&n) = cs.get(i + 1).filter(|n| n.is_ascii_alphanumeric()) {
                    d.push(n);
                    i += 1;
                }
                f.atom(format!("\\sqrt{{{d}}}"));
            }
            '~' => {
                // `c~` is c̃: the letter just written, under a tilde
                let letter = f
                    .tokens
                    .last()
                    .filter(|t| t.len() == 1 && t.chars().all(|l| l.is_ascii_alphabetic()))
                    .cloned();
                match letter {
                    Some(l) if f.scripts == Scripts::default() => {
                        f.tokens.pop();
                        f.atom(format!("\\tilde{{{l}}}"));
                    }
                    _ => f.atom(math_char('~')),
                }
            }
            '_' | '^' if cs.get(i + 1) == Some(&'{') => {
                f.script(c);
                f.open_group();
                i += 1;
            }
            '_' | '^' => {
                // a bare sub- or superscript: up to the next space or bracket
                let mut run = Vec::new();
                while let Some(&n) = cs
                    .get(i + 1)
                    .filter(|n| n.is_alphanumeric() || matches!(n, ',' | '-' | '+'))
                {
                    // a comma followed by a space ends it (a list, not an index)
                    if n == ',' && cs.get(i + 2).is_none_or(|m| *m == ' ') {
                        break;
                    }
                    run.push(n);
                    i += 1;
                }
                f.script_run(c, &run);
            }
            c if script_char(c).is_some() => {
                let kind = script_char(c).map_or('^', |k| k.0);
                let mut what: String = script_char(c).map(|k| k.1).into_iter().collect();
                while let Some((_, d)) = cs
                    .get(i + 1)
                    .and_then(|n| script_char(*n))
                    .filter(|k| k.0 == kind)
                {
                    what.push(d);
                    i += 1;
                }
                f.scripts_of(kind, &what);
            }
            c if c.is_ascii_alphabetic() => {
                // a word of letters: `cos` and `sin` are functions, the others letters
                let mut word = String::from(c);
                while let Some(&n) = cs.get(i + 1).filter(|n| n.is_ascii_alphabetic()) {
                    word.push(n);
                    i += 1;
                }
                match word.as_str() {
                    "cos" => f.atom("\\cos"),
                    "sin" => f.atom("\\sin"),
                    _ => {
                        for l in word.chars() {
                            f.atom(l.to_string());
                        }
                    }
                }
            }
            c => f.char(c),
        }
        i += 1;
    }
    f.finish()
}

/// Text of unknown make for LaTeX's text mode (a fixture's note, a title, an engine sentence
/// with a problem's words in it): each word that looks like mathematics (with `^`, `_`, `Δ`,
/// `√`, `·`, `×`, `∞`, `≠`, `≡`, `~`, `∂`, `Σ`) typeset by [`math`] in `$...$`, its trailing
/// punctuation outside; an identifier in backticks in typewriter; the rest through [`text`].
/// A math span is one word: it never crosses a space.
///
/// ```
/// use cagd_keys::tex::words;
/// assert_eq!(words("the point c_{1,1}, twice"), "the point $c_{1,1}$, twice");
/// assert_eq!(words("see `closed_form`."), "see \\texttt{closed\\_form}.");
/// assert_eq!(words("x_( \\input /etc/hostname )"), "$x_{}($ \\textbackslash{}input /etc/hostname )");
/// ```
pub fn words(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for (i, w) in s.split(' ').enumerate() {
        if i > 0 {
            out.push(' ');
        }
        out += &word(w);
    }
    out
}

/// One word of [`words`].
fn word(word: &str) -> String {
    let mathy = word.contains(['^', '_', 'Δ', '√', '·', '×', '∞', '≠', '≡', '~', '∂', 'Σ']);
    let balance = |w: &str| {
        w.chars().fold(0i32, |b, c| match c {
            '(' | '[' => b + 1,
            ')' | ']' => b - 1,
            _ => b,
        })
    };
    let opened = word.trim_start_matches('(');
    let lead = &word[..word.len() - opened.len()];
    let core = opened.trim_end_matches([',', ';', ':', '.', ')', '?']);
    if opened.starts_with('`') && core.ends_with('`') {
        // an identifier, `closed_form`: typewriter
        let tail = &opened[core.len()..];
        return format!(
            "{lead}\\texttt{{{}}}{}",
            text(core.trim_matches('`')),
            text(tail)
        );
    }
    if !mathy {
        return text(word);
    }
    // a formula; a closing parenthesis of the sentence around it stays text
    let mut core = word.trim_end_matches([',', ';', ':', '.']);
    while core.ends_with(')') && balance(core) < 0 {
        core = &core[..core.len() - 1];
    }
    let tail = &word[core.len()..];
    format!("${}${}", math(core), text(tail))
}

/// `\includegraphics[options]{path}` for a figure's path, whatever its characters: the path
/// as it is when it has only ASCII letters, digits and `/ . - _`; else read by pdfTeX from its
/// bytes in hexadecimal (`\pdfunescapehex`, characters of category other), so that a folder
/// named `set #3` or `a%b{` is a path and not TeX. A path that TeX's file lookup (kpathsea)
/// would rewrite, with `$` before a name (`$HOME`, `${x}`) or `~` first, is not opened: it
/// is shown framed in typewriter instead. `options` are the caller's own LaTeX
/// (`width=0.5\textwidth`), never a problem's.
///
/// ```
/// use cagd_keys::tex::graphics;
/// assert_eq!(graphics("fig/a.png", "width=1cm"), "\\includegraphics[width=1cm]{fig/a.png}");
/// assert_eq!(
///     graphics("#/a.png", "width=1cm"),
///     "\\begingroup\\edef\\cagdpath{\\pdfunescapehex{232F612E706E67}}\\includegraphics[width=1cm]{\\cagdpath}\\endgroup"
/// );
/// ```
pub fn graphics(path: &str, options: &str) -> String {
    if path
        .chars()
        .all(|c| c.is_ascii_alphanumeric() || matches!(c, '/' | '.' | '-' | '_'))
        && !path.is_empty()
    {
        return format!("\\includegraphics[{options}]{{{path}}}");
    }
    let expanded = path.starts_with('~')
        || path
            .split('$')
            .skip(1)
            .any(|after| after.starts_with(|c: char| c.is_alphanumeric() || c == '_' || c == '{'));
    if expanded {
        return format!("\\fbox{{\\texttt{{{}}}}}", text(path));
    }
    let hex: String = path.bytes().map(|b| format!("{b:02X}")).collect();
    format!(
        "\\begingroup\\edef\\cagdpath{{\\pdfunescapehex{{{hex}}}}}\\includegraphics[{options}]{{\\cagdpath}}\\endgroup"
    )
}

/// LaTeX written by the engine's printers (numbers, meshes, polynomials; parameters' names),
/// with every character the preamble cannot set (a parameter named `ж` or `中`) written
/// visibly as `\text{\texttt{U+0436}}`, which works in text and in math mode. ASCII, the
/// declared symbols and the characters set up pass as they are (the LaTeX of [`text`] and
/// [`math`] has no other).
pub fn known_characters(latex: &str) -> String {
    if latex.is_ascii() {
        return latex.to_string();
    }
    let mut out = String::with_capacity(latex.len());
    for c in latex.chars() {
        if c.is_ascii() || declared(c) || set_up(c) {
            out.push(c);
        } else {
            out += &format!("\\text{{{}}}", visible(c));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// The control words [`text`], [`math`] and [`words`] may write: the fixed table's.
    const WORDS: &[&str] = &[
        "textbackslash",
        "texttt",
        "text",
        "sqrt",
        "Delta",
        "cdot",
        "times",
        "infty",
        "neq",
        "equiv",
        "leq",
        "geq",
        "theta",
        "partial",
        "Sigma",
        "pi",
        "dots",
        "sim",
        "backslash",
        "cos",
        "sin",
        "tilde",
    ];

    /// LaTeX read as TeX would: every control word in [`WORDS`], every control symbol an
    /// escaped special (`\^` and `\~` followed by `{}`), braces balanced and never closed
    /// before they open, dollars paired, no `^^`, no control character, every other character
    /// ASCII or one the preamble handles, every `^` and `_` of math followed by a group.
    fn structural(out: &str, dollars_allowed: bool) -> Result<(), String> {
        if out.contains("^^") {
            return Err("^^".into());
        }
        let cs: Vec<char> = out.chars().collect();
        let (mut depth, mut dollars, mut i) = (0i64, 0usize, 0usize);
        while let Some(&c) = cs.get(i) {
            match c {
                '\\' => {
                    let name: String = cs[i + 1..]
                        .iter()
                        .take_while(|c| c.is_ascii_alphabetic())
                        .collect();
                    if name.is_empty() {
                        let sym = cs.get(i + 1).copied().unwrap_or(' ');
                        if !"{}$%#&_^~".contains(sym) {
                            return Err(format!("control symbol \\{sym}"));
                        }
                        if "^~".contains(sym) && cs.get(i + 2..i + 4) != Some(&['{', '}'][..]) {
                            return Err(format!("\\{sym} without {{}}"));
                        }
                        i += 2;
                        continue;
                    }
                    if !WORDS.contains(&name.as_str()) {
                        return Err(format!("control word \\{name}"));
                    }
                    i += 1 + name.len();
                    continue;
                }
                '{' => depth += 1,
                '}' => {
                    depth -= 1;
                    if depth < 0 {
                        return Err("a brace closed before it opened".into());
                    }
                }
                '$' => dollars += 1,
                '^' | '_' if cs.get(i + 1) != Some(&'{') => {
                    return Err(format!("{c} without a group"));
                }
                c if c.is_control() => return Err(format!("control character {c:?}")),
                c if !c.is_ascii() && !declared(c) && !set_up(c) => {
                    return Err(format!("character {c:?} not set up"));
                }
                _ => {}
            }
            i += 1;
        }
        if depth != 0 {
            return Err(format!("{depth} braces left open"));
        }
        if dollars % 2 != 0 || (!dollars_allowed && dollars > 0) {
            return Err(format!("{dollars} dollars"));
        }
        Ok(())
    }

    /// Random text with TeX's specials, the attacks and characters of every kind.
    fn any_text() -> impl Strategy<Value = String> {
        let pieces = prop::sample::select(vec![
            "\\",
            "{",
            "}",
            "$",
            "%",
            "#",
            "&",
            "~",
            "^",
            "^^",
            "_",
            "x_(",
            "(",
            ")",
            "`",
            "'",
            " ",
            "\n",
            "\\input /etc/hostname",
            "c_{1,1}",
            "Δ^{1,0}",
            "√2/2",
            "c~",
            "²",
            "ᵗ",
            "₁",
            "β",
            "ж",
            "😀",
            "\u{1b}",
            "\u{0}",
            "\u{9b}",
            "é",
            "\u{302}",
            "cos",
            "x",
        ]);
        prop::collection::vec(
            prop_oneof![
                2 => pieces.prop_map(str::to_string),
                1 => any::<char>().prop_map(String::from),
            ],
            0..30,
        )
        .prop_map(|v| v.concat())
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 2000, ..ProptestConfig::default() })]

        #[test]
        fn text_is_structurally_inert(s in any_text()) {
            let out = text(&s);
            prop_assert!(structural(&out, true).is_ok(), "{:?} -> {out}: {:?}", s, structural(&out, true));
        }

        #[test]
        fn math_is_structurally_inert(s in any_text()) {
            let out = math(&s);
            prop_assert!(structural(&out, false).is_ok(), "{:?} -> {out}: {:?}", s, structural(&out, false));
        }

        #[test]
        fn words_are_structurally_inert(s in any_text()) {
            let out = words(&s);
            prop_assert!(structural(&out, true).is_ok(), "{:?} -> {out}: {:?}", s, structural(&out, true));
        }
    }

    #[test]
    fn the_attacks_are_text() {
        assert_eq!(
            words("x_( \\immediate\\openout7=pwned.tex \\immediate\\closeout7 )"),
            "$x_{}($ \\textbackslash{}immediate\\textbackslash{}openout7=pwned.tex \\textbackslash{}immediate\\textbackslash{}closeout7 )"
        );
        assert_eq!(math("x^^5c"), "x^{}{}^{5c}");
        assert_eq!(math("x^2^3"), "x^{2}{}^{3}");
        assert_eq!(math("x_1_2"), "x_{1}{}_{2}");
        assert_eq!(math("x'^2''"), "x'^{2}{}''");
        assert_eq!(math("x²³ᵗ"), "x^{23t}");
        assert_eq!(math("{a"), "\\{a");
        assert_eq!(math("_{a"), "_{a}");
        assert_eq!(math("a}"), "a\\}");
        assert_eq!(
            text("\u{1b}[2J\u{7}"),
            "\\texttt{U+001B}[2J\\texttt{U+0007}"
        );
        assert_eq!(text("a\n\nb"), "a  b");
        assert_eq!(known_characters("x + ж"), "x + \\text{\\texttt{U+0436}}");
        assert_eq!(known_characters("β é"), "β é");
    }

    #[test]
    fn the_structural_check_catches_what_the_old_escaping_let_through() {
        // the old key's heading of the attack, and an old caret in math
        assert!(structural("$x_{}( \\input /etc/hostname )$", true).is_err());
        // (a double superscript is structurally sound: pdflatex's tests find those)
        assert!(structural("$x^{}^{2}$", true).is_ok());
        assert!(structural("x^^5c", true).is_err());
        assert!(structural("ж", true).is_err());
    }

    #[test]
    fn the_declarations_are_the_old_preambles_first() {
        let d = declarations();
        assert!(d.starts_with(
            "\\DeclareUnicodeCharacter{2202}{\\ensuremath{\\partial}}\n\\DeclareUnicodeCharacter{03A3}{\\ensuremath{\\Sigma}}\n"
        ));
        assert!(d.contains("\\DeclareUnicodeCharacter{0303}{\\ensuremath{\\tilde{}}}\n"));
        assert!(d.contains("\\DeclareUnicodeCharacter{03B2}{\\ensuremath{\\beta}}\n"));
    }
}
