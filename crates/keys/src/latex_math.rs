//! Formulas of a LaTeX key set to fit the line: matrices scaled down to it, lists free to break
//! after their commas, parentheses that do not stop a break. A leaf of the LaTeX writers.

/// Wraps every matrix of a formula in `\fitmath{...}` (scaled down to the line when wider,
/// see `latex_document`) and lets lists break after their commas.
pub(crate) fn fit_matrices(math: &str) -> String {
    let mut out = String::new();
    let mut rest = math;
    while let Some(i) = rest.find("\\begin{") {
        let (before, tail) = rest.split_at(i);
        out += &breakable(before);
        let env = tail
            .get(7..)
            .and_then(|t| t.split_once('}'))
            .map(|(e, _)| e)
            .unwrap_or_default();
        let end = format!("\\end{{{env}}}");
        match tail.find(&end) {
            Some(j) => {
                let (m, after) = tail.split_at(j + end.len());
                out += &format!("\\fitmath{{{m}}}");
                rest = after;
            }
            None => {
                out += tail;
                rest = "";
            }
        }
    }
    out + &breakable(rest)
}

/// A value of an assessment in text mode (`$...$`): its matrices scaled to the line, free to
/// break after its commas and inside its parentheses.
pub(crate) fn inline_value(math: &str) -> String {
    format!("${}$", fit_matrices(&open_parentheses(math)))
}

/// A value with parts (a curve's degree, polygon and knots; a list of curves) set one part a
/// line, as the keys' results are: `\left[ ... \right]` opened (it could not span the
/// lines), each part fitted to the line, the parts joined by a new line in display style.
/// A value without parts is returned as it is.
pub(crate) fn lines_of_parts(math: &str) -> String {
    if !math.contains(",\\quad ") && !math.contains(";\\quad ") {
        return math.to_string();
    }
    let open = math.replace("\\left[", "[").replace("\\right]", "]");
    open.split(",\\quad ")
        .map(|part| {
            part.split(";\\quad ")
                .map(fit_matrices)
                .collect::<Vec<_>>()
                .join(";$\\newline$\\displaystyle ")
        })
        .collect::<Vec<_>>()
        .join(",$\\newline$\\displaystyle ")
}

/// A formula whose parentheses do not stop a line break: `\left(...\right)` is one box to
/// TeX, `(...)` is not.
pub(crate) fn open_parentheses(math: &str) -> String {
    math.replace("\\left(", "(").replace("\\right)", ")")
}

/// A formula free to break after its commas (inline math breaks only where allowed).
fn breakable(math: &str) -> String {
    math.replace(",\\quad ", ",\\allowbreak\\quad ")
        .replace(";\\quad ", ";\\allowbreak\\quad ")
        .replace(", ", ",\\allowbreak ")
}
