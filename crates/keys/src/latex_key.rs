//! The LaTeX answer key: one section per problem ([`example_latex`]), its formulas fitted to
//! the page, and the document around the sections ([`latex_document`]), which compiles with
//! pdflatex.

use crate::assessment;
use crate::escape::escape_latex;
use crate::latex_math::{fit_matrices, open_parentheses};
use crate::parts::{key_parts, Item};
use crate::steps;
use crate::values::latex;
use crate::verdict::{no_raise, RaiseWith};
use crate::vocabulary::{operation_words, Word};
use crate::{tex, Lang};
use cagd_contract::input::SurfaceIn;
use cagd_contract::{Exact, Verdict};

/// The LaTeX (math mode) of an item's value.
pub(crate) fn item_latex(it: &Item, lang: Lang) -> String {
    match (&it.value, it.data) {
        (
            Exact::Surface(SurfaceIn::Bezier {
                mesh,
                weights: None,
            }),
            true,
        ) => mesh.to_latex(),
        // a rational map: its numerator over w, and w on a line of its own (a fraction of
        // long polynomials cannot break across lines)
        (Exact::Rational(r), _) if r.denominator().to_text() != "1" => format!(
            "\\frac{{1}}{{w}}\\, {},\\quad w = {}",
            r.numerator().to_latex(),
            r.denominator().to_latex()
        ),
        (v, _) => latex(v, lang),
    }
}

/// The LaTeX of one item: `$\displaystyle label = value$`, matrices scaled to the line when
/// wider, lists free to break after a comma.
pub(crate) fn latex_item(it: &Item, lang: Lang) -> String {
    if let Some(words) = &it.words {
        if let (Exact::Text(t), "c(u, v)") = (&it.value, it.label.text.as_str()) {
            // the parametrization of a surface of revolution: mathematics with cos v, sin v
            return format!("$\\displaystyle {} = {}$", it.label.latex, tex::math(t));
        }
        return format!("${}$: {}", it.label.latex, words.latex);
    }
    // a closed form breaks inside its parentheses; a list of points between them
    let value = item_latex(it, lang);
    // a list of surfaces breaks between the meshes of its surfaces (below), a list of pieces
    // between its pieces, a long list (a triangular net) after its commas, which the brackets
    // \left[ ... \right] could not span
    let value = if value.contains(",\\quad ") || value.contains(";\\quad ") || value.len() > 200 {
        value.replace("\\left[", "[").replace("\\right]", "]")
    } else {
        value
    };
    let formula = match it.value {
        Exact::Map(_) | Exact::Rational(_) | Exact::Poly(_) => true,
        // a point in letters, long as a closed form
        Exact::Point(_) => value.len() > 120,
        _ => false,
    };
    // a mesh, its weights and its knots: one line each
    let parts: Vec<String> = value
        .split(",\\quad ")
        .map(|part| match formula {
            true => fit_matrices(&open_parentheses(part)),
            false => fit_matrices(part),
        })
        .collect();
    let item = format!(
        "$\\displaystyle {}{}{}$",
        it.label.latex,
        if it.sep() == " = " {
            " = "
        } else {
            "\\colon\\ "
        },
        parts.join(",$\\newline$\\displaystyle ")
    );
    if formula && value.len() > LONG_FORMULA {
        // a long polynomial breaks only after its + and -, between terms of a few hundred
        // points each (the fractions of a big interpolation): set ragged right, a line may
        // end short instead of running off the page
        format!("{{\\raggedright {item}\\par}}")
    } else {
        item
    }
}

/// The length (in characters of LaTeX) above which a formula of a key is set ragged right,
/// free to end a line short between its terms ([`latex_item`]).
const LONG_FORMULA: usize = 250;

/// The worked solution's long lines (closed forms in letters, a hundred terms) free to break
/// inside their parentheses.
fn long_lines_breakable(tex: &str) -> String {
    tex.split_inclusive('\n')
        .map(|line| match line.len() > 250 {
            true => open_parentheses(&columns_as_tuples(line)),
            false => line.to_string(),
        })
        .collect()
}

/// A column vector `\begin{pmatrix} a \\ b \end{pmatrix}` written as the tuple `(a, b)`,
/// which can break across lines (a matrix cannot); a matrix with columns is left alone.
fn columns_as_tuples(line: &str) -> String {
    let (open, close) = ("\\begin{pmatrix}", "\\end{pmatrix}");
    let mut out = String::new();
    let mut rest = line;
    while let Some(i) = rest.find(open) {
        let (before, tail) = rest.split_at(i);
        out += before;
        let Some(j) = tail.find(close) else {
            rest = tail;
            break;
        };
        let inner = &tail[open.len()..j];
        if inner.contains('&') {
            out += &tail[..j + close.len()];
        } else {
            let rows: Vec<&str> = inner.split("\\\\").map(str::trim).collect();
            out += &format!("({})", rows.join(", "));
        }
        rest = &tail[j + close.len()..];
    }
    out + rest
}

/// One example as a LaTeX section (inside [`latex_document`]).
pub fn example_latex(verdict: &Verdict, lang: Lang) -> String {
    example_latex_with(verdict, lang, no_raise)
}

/// [`example_latex`] written by a front end that says how to raise a limit.
pub fn example_latex_with(verdict: &Verdict, lang: Lang, raise: RaiseWith) -> String {
    let (head, rest) = example_parts(verdict, lang, raise);
    tex::known_characters(&(head + &rest))
}

/// [`example_latex`] with its figure (the image at `path`, relative to the document) beside
/// the example's head (source, note, operation, input), so that a figure never takes a page of
/// its own: the head in 0.6 of the line, the figure in 0.38 (at most 0.36 of the page high);
/// without a figure, [`example_latex`].
pub fn example_latex_beside(verdict: &Verdict, lang: Lang, path: Option<&str>) -> String {
    let Some(path) = path else {
        return example_latex(verdict, lang);
    };
    let figure = tex::graphics(
        path,
        "width=\\linewidth,height=0.36\\textheight,keepaspectratio",
    );
    let (head, rest) = example_parts(verdict, lang, no_raise);
    let (heading, head) = head.split_once('\n').unwrap_or((&head, ""));
    tex::known_characters(&format!(
        "{heading}\n\\par\\noindent\\begin{{minipage}}[t]{{0.6\\linewidth}}\\vspace{{0pt}}\n{head}\\end{{minipage}}\\hfill\n\\begin{{minipage}}[t]{{0.38\\linewidth}}\\vspace{{0pt}}\\centering\n{figure}\n\\end{{minipage}}\n\n{rest}"
    ))
}

/// An example's LaTeX in two parts: its head (the section's heading on its first line, then
/// source, note, operation and input) and the rest (worked solution, steps, result, remarks,
/// verdict).
fn example_parts(verdict: &Verdict, lang: Lang, raise: RaiseWith) -> (String, String) {
    let k = key_parts(verdict, lang, raise);
    let mut out = format!("\\section*{{{}}}\n", tex::words(&k.heading));
    if !k.source.is_empty() {
        out += &format!(
            "\\textit{{{}: {}}}\\\\\n",
            lang.word("source"),
            escape_latex(&k.source)
        );
    }
    if let Some(n) = &k.note {
        out += &format!("\\textit{{{}:}} {}\\\\\n", lang.word("note"), tex::words(n));
    }
    if !k.op.is_empty() {
        out += &format!(
            "{}: {}\n",
            lang.word("operation"),
            escape_latex(&operation_words(&k.op, lang))
        );
    }
    let block = |title: &str, items: &[Item]| -> String {
        if items.is_empty() {
            return String::new();
        }
        let mut b = format!(
            "\\paragraph{{{}}}\n\\begin{{itemize}}\n",
            escape_latex(title)
        );
        for it in items {
            b += &format!("\\item {}\n", latex_item(it, lang));
        }
        b + "\\end{itemize}\n"
    };
    out += &block(&lang.word("input"), &k.inputs);
    let mut rest = long_lines_breakable(&steps::latex_block(verdict, lang));
    rest += &block(&lang.word("steps"), &k.steps);
    rest += &block(&lang.word("result"), &k.result);
    for r in &k.remarks {
        rest += &format!("\\textit{{{}}}\\\\\n", r.latex);
    }
    if let Some(e) = &k.error {
        rest += &format!("\\textbf{{{}}}: {}\\\\\n", lang.word("error"), e.latex);
    }
    if verdict.checked {
        // kept on the page of the last line of the result
        rest += &format!(
            "\\par\\nopagebreak\\smallskip\\textbf{{{}:}} {}\n\n",
            escape_latex(&lang.word("verdict")),
            k.verdict.latex
        );
        if let Some(a) = assessment::of(verdict) {
            rest += &assessment::latex_block(a, verdict.problem.as_deref(), lang);
        }
    }
    (out, rest)
}

/// The preamble of every LaTeX document of cagd-exact: vector fonts (T1, Latin Modern), the
/// AMS packages, landscape pages, and `\fitmath`, which scales a formula down to 0.8 of the
/// line when it is wider (the hemisphere's 9-column meshes), leaving room for its label (the
/// Spanish `puntos de datos =` before a scaled grid of data).
pub fn latex_preamble(lang: Lang) -> String {
    let babel = match lang {
        Lang::En => "",
        Lang::Es => "",
    };
    // the mathematical characters a note or a title may have in its words, and Greek letters
    let unicode = tex::declarations();
    format!(
        "\\documentclass[10pt]{{article}}\n\
         \\usepackage[utf8]{{inputenc}}\n\
         \\usepackage[T1]{{fontenc}}\n\
         \\usepackage{{lmodern}}\n{babel}\
         \\usepackage{{amsmath,amssymb}}\n\
         \\usepackage[margin=2cm,landscape]{{geometry}}\n\
         \\usepackage{{graphicx}}\n\
         \\setcounter{{MaxMatrixCols}}{{40}}\n\
         {unicode}\
         \\allowdisplaybreaks\n\
         \\setlength{{\\parindent}}{{0pt}}\n\
         \\emergencystretch=3em\n\
         \\newsavebox{{\\cagdbox}}\n\
         \\newcommand{{\\fitmath}}[1]{{\\sbox{{\\cagdbox}}{{$\\displaystyle #1$}}%\n\
         \\ifdim\\wd\\cagdbox>0.8\\linewidth\\resizebox{{0.8\\linewidth}}{{!}}{{\\usebox{{\\cagdbox}}}}%\n\
         \\else\\usebox{{\\cagdbox}}\\fi}}\n"
    )
}

/// The layout of a document of keys: lists without space between items, headings of
/// sections in `\large`, and fractions in meshes and matrices at the size of the text
/// (every cell of a matrix in `\displaystyle`, its rows spaced to hold them).
const COMPACT: &str = "\\usepackage{array}\n\\makeatletter\n\
\\def\\@listI{\\leftmargin\\leftmargini \\parsep\\z@ \\topsep 2\\p@ \\itemsep\\z@ \\partopsep\\z@}\n\
\\let\\@listi\\@listI\n\
\\def\\@listii{\\leftmargin\\leftmarginii \\labelwidth\\leftmarginii \\advance\\labelwidth-\\labelsep \\parsep\\z@ \\topsep\\z@ \\itemsep\\z@ \\partopsep\\z@}\n\
\\renewcommand\\section{\\@startsection{section}{1}{\\z@}{-2.5ex \\@plus -1ex \\@minus -.2ex}{1ex \\@plus .2ex}{\\normalfont\\large\\bfseries}}\n\
\\renewcommand\\paragraph{\\@startsection{paragraph}{4}{\\z@}{1.5ex \\@plus .5ex \\@minus .2ex}{-1em}{\\normalfont\\normalsize\\bfseries}}\n\
\\def\\env@matrix{\\hskip -\\arraycolsep \\let\\@ifnextchar\\new@ifnextchar \\def\\arraystretch{1.6}\\array{*\\c@MaxMatrixCols{>{\\displaystyle}c}}}\n\
\\makeatother\n";

/// A complete LaTeX document around sections from [`example_latex`], titled "Answer key:
/// `title`"; compiles with pdflatex.
pub fn latex_document(title: &str, sections: &[String], lang: Lang) -> String {
    let title = format!("{}: {title}", lang.word("Answer key"));
    latex_key_document(&title, "", sections, lang)
}

/// A complete LaTeX document of keys under its own `title` (words, escaped), the `legend`
/// (LaTeX, from [`crate::legend_latex`]) once after the title, then the sections from
/// [`example_latex`]; compiles with pdflatex.
pub fn latex_key_document(title: &str, legend: &str, sections: &[String], lang: Lang) -> String {
    let mut out = latex_preamble(lang) + COMPACT;
    out += &format!(
        "\\title{{{}}}\n\\date{{}}\n\\begin{{document}}\n\\maketitle\n",
        tex::words(title)
    );
    out += legend;
    for s in sections {
        out += s;
    }
    out + "\\end{document}\n"
}
