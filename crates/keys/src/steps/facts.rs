//! The facts of a worked solution (the knot span, the points changed, the passes of a surface,
//! the pieces) and the matrices shown by their size, in words.

use crate::vocabulary::words;
use crate::Lang;
use cagd_contract::steps::{Entries, Fact, Line, MatrixSummary};
use cagd_contract::Exact;
use cagd_scalar::Print;

/// A fact in words; symbols in `sym` form, values through `value`.
pub(super) fn fact_words(
    f: &Fact,
    lang: Lang,
    sym: &dyn Fn(&str) -> String,
    value: &dyn Fn(&Exact) -> String,
) -> String {
    match f {
        Fact::Span(span) => {
            let cagd_contract::steps::Span {
                knots,
                t,
                k,
                left,
                right,
            } = span.as_ref();
            let span = format!(
                "{} ≤ {} < {}",
                sym(&format!("{knots}_{{{}}}", k.saturating_sub(1))),
                value(t),
                sym(&format!("{knots}_{{{k}}}"))
            );
            let values = format!("[{}, {})", value(left), value(right));
            match lang {
                Lang::En => format!("The parameter lies in the span {span}, that is {values}; k = {k}."),
                Lang::Es => format!("El parámetro está en el tramo {span}, es decir {values}; k = {k}."),
            }
        }
        Fact::Changed { first, last } => {
            let (a, b) = (sym(&format!("d_{{{first}}}")), sym(&format!("d_{{{last}}}")));
            match lang {
                Lang::En => format!("Only the points {a}, ..., {b} are new; the others are kept (renumbered after them)."),
                Lang::Es => format!("Sólo los puntos {a}, ..., {b} son nuevos; los demás se conservan (renumerados tras ellos)."),
            }
        }
        Fact::Insertion { step, of } => match lang {
            Lang::En => format!("Insertion {step} of {of}:"),
            Lang::Es => format!("Inserción {step} de {of}:"),
        },
        Fact::Homogeneous => words(
            lang,
            "The work is done on the homogeneous points (w c, w); the point is the quotient by the last coordinate.",
            "Se opera con los puntos homogéneos (w c, w); el punto es el cociente por la última coordenada.",
        ),
        Fact::AlongU => words(
            lang,
            "First pass, along u: the algorithm on each column j of the mesh.",
            "Primer paso, en u: el algoritmo en cada columna j de la malla de control.",
        ),
        Fact::AlongV => words(
            lang,
            "Second pass, along v: the algorithm on the points of the first pass.",
            "Segundo paso, en v: el algoritmo sobre los puntos del primer paso.",
        ),
        Fact::EachColumn => words(
            lang,
            "Along u: in each column j of the mesh, with the same knots and ratios.",
            "En u: en cada columna j de la malla de control, con los mismos nudos y cocientes.",
        ),
        Fact::EachRow => words(
            lang,
            "Along v: in each row i of the mesh, with the same knots and ratios.",
            "En v: en cada fila i de la malla de control, con los mismos nudos y cocientes.",
        ),
        Fact::Degree { from, to } => match lang {
            Lang::En => format!("From degree {from} to degree {to}:"),
            Lang::Es => format!("Del grado {from} al grado {to}:"),
        },
        Fact::At { params } => {
            let ps = params.iter().map(value).collect::<Vec<_>>().join(", ");
            match lang {
                Lang::En => format!("At the parameter ({ps}):"),
                Lang::Es => format!("En el parámetro ({ps}):"),
            }
        }
        Fact::RestrictRows => {
            let hat = sym("\\hat{c}");
            match lang {
                Lang::En => format!("First pass, in v: each row i of the mesh, a polygon in v, is restricted to [c, d] by the polar form of curves; this gives the mesh {hat}."),
                Lang::Es => format!("Primer paso, en v: cada fila i de la malla de control, un polígono en v, se restringe a [c, d] con la forma polar de curvas; así se obtiene la malla {hat}."),
            }
        }
        Fact::RestrictColumns => {
            let (hat, tilde) = (sym("\\hat{c}"), sym("\\tilde{c}"));
            match lang {
                Lang::En => format!("Second pass, in u: each column j of {hat}, a polygon in u, is restricted to [a, b]; this gives the mesh {tilde}."),
                Lang::Es => format!("Segundo paso, en u: cada columna j de {hat}, un polígono en u, se restringe a [a, b]; así se obtiene la malla {tilde}."),
            }
        }
        Fact::CurveElevated {
            curve,
            from,
            to,
            partner,
        } => {
            let (c, p) = (sym(curve), sym(partner));
            match lang {
                Lang::En => format!("{c} has degree {from} and {p} degree {to}: the mesh needs polygons of the same degree, so {c} is first raised to degree {to}:"),
                Lang::Es => format!("{c} es de grado {from} y {p} de grado {to}: la malla de control necesita polígonos del mismo grado, así que primero se eleva {c} al grado {to}:"),
            }
        }
        Fact::SplinePass { line } => match (lang, line) {
            (Lang::En, Line::Row) => format!(
                "First pass, in v: each row i of data points is interpolated by a cubic spline, the system {} with the same matrix for every row; its solutions are the rows of the mesh {}.",
                sym("N_V \\tilde{D}_i = A_i"),
                sym("\\tilde{d}")
            ),
            (Lang::Es, Line::Row) => format!(
                "Primer paso, en v: cada fila i de puntos dato se interpola con un spline cúbico, el sistema {} con la misma matriz para todas las filas; sus soluciones son las filas de la malla {}.",
                sym("N_V \\tilde{D}_i = A_i"),
                sym("\\tilde{d}")
            ),
            (Lang::En, Line::Column) => format!(
                "Second pass, in u: each column j of {} is interpolated in the same way, the system {}; its solutions are the columns of the mesh.",
                sym("\\tilde{d}"),
                sym("N_U D_j = \\tilde{A}_j")
            ),
            (Lang::Es, Line::Column) => format!(
                "Segundo paso, en u: cada columna j de {} se interpola del mismo modo, el sistema {}; sus soluciones son las columnas de la malla de control.",
                sym("\\tilde{d}"),
                sym("N_U D_j = \\tilde{A}_j")
            ),
        },
        Fact::Piece { index, interval } => {
            let interval = format!(
                "[{}]",
                interval.iter().map(value).collect::<Vec<_>>().join(", ")
            );
            match lang {
                Lang::En => format!("Bézier piece {index}, on {interval}:"),
                Lang::Es => format!("Tramo de Bézier {index}, en {interval}:"),
            }
        }
        Fact::Construction => words(
            lang,
            "The mesh is built by the construction's formula; its intermediate values follow.",
            "La malla de control se obtiene con la fórmula de la construcción; siguen sus valores intermedios.",
        ),
        Fact::SameForTheOthers { shown, more } => {
            let worked = match (lang, *shown) {
                (Lang::En, 1) => "the steps are worked for the first one".to_string(),
                (Lang::En, k) => format!("the steps are worked for the first {k}"),
                (Lang::Es, 1) => "se desarrollan los pasos del primero".to_string(),
                (Lang::Es, k) => format!("se desarrollan los pasos de los {k} primeros"),
            };
            match (lang, *more == 1) {
                (Lang::En, true) => format!("The other point is found in the same way ({worked})."),
                (Lang::En, false) => format!("The other {more} points are found in the same way ({worked})."),
                (Lang::Es, true) => format!("El otro punto se obtiene del mismo modo ({worked})."),
                (Lang::Es, false) => format!("Los otros {more} puntos se obtienen del mismo modo ({worked})."),
            }
        }
        Fact::SameInTheOtherLines { line, shown, more } => {
            let worked = match (lang, *shown) {
                (Lang::En, 1) => "the steps are shown for the first one".to_string(),
                (Lang::En, k) => format!("the steps are shown for the first {k}"),
                (Lang::Es, 1) => "se desarrollan los pasos de la primera".to_string(),
                (Lang::Es, k) => format!("se desarrollan los pasos de las {k} primeras"),
            };
            match (lang, line, *more == 1) {
                (Lang::En, Line::Column, true) => format!("The other column is worked in the same way ({worked})."),
                (Lang::En, Line::Column, false) => format!("The other {more} columns are worked in the same way ({worked})."),
                (Lang::En, Line::Row, true) => format!("The other row is worked in the same way ({worked})."),
                (Lang::En, Line::Row, false) => format!("The other {more} rows are worked in the same way ({worked})."),
                (Lang::Es, Line::Column, true) => format!("La otra columna se trata del mismo modo ({worked})."),
                (Lang::Es, Line::Column, false) => format!("Las otras {more} columnas se tratan del mismo modo ({worked})."),
                (Lang::Es, Line::Row, true) => format!("La otra fila se trata del mismo modo ({worked})."),
                (Lang::Es, Line::Row, false) => format!("Las otras {more} filas se tratan del mismo modo ({worked})."),
            }
        }
        _ => String::new(),
    }
}

/// What the entries of a matrix shown by its size are, in words; symbols through `sym`.
fn entries_words(e: Entries, lang: Lang, sym: &dyn Fn(&str) -> String) -> String {
    match (e, lang) {
        (Entries::Bernstein, Lang::En) => {
            "row i: the Bernstein polynomials at the i-th parameter".to_string()
        }
        (Entries::Bernstein, Lang::Es) => {
            "fila i: los polinomios de Bernstein en el parámetro i-ésimo".to_string()
        }
        (Entries::TensorBernstein, Lang::En) => format!(
            "row k: {} in column {}",
            sym("B_i^m(u_k) B_j^n(v_k)"),
            sym("i (n+1) + j")
        ),
        (Entries::TensorBernstein, Lang::Es) => format!(
            "fila k: {} en la columna {}",
            sym("B_i^m(u_k) B_j^n(v_k)"),
            sym("i (n+1) + j")
        ),
        (Entries::NormalMatrix, Lang::En) => format!(
            "entry (a, b) = {}, a symmetric matrix",
            sym("\\sum_k B_{k,a} B_{k,b}")
        ),
        (Entries::NormalMatrix, Lang::Es) => format!(
            "elemento (a, b) = {}, una matriz simétrica",
            sym("\\sum_k B_{k,a} B_{k,b}")
        ),
        (Entries::NormalRhs, Lang::En) => format!("row a = {}", sym("\\sum_k B_{k,a} a_k")),
        (Entries::NormalRhs, Lang::Es) => format!("fila a = {}", sym("\\sum_k B_{k,a} a_k")),
        _ => String::new(),
    }
}

/// A matrix shown by its size: `B is a 200 × 49 matrix (row k: ...); its first 2 rows:`.
pub(super) fn matrix_words(m: &MatrixSummary, lang: Lang, sym: &dyn Fn(&str) -> String) -> String {
    let MatrixSummary {
        symbol,
        rows,
        cols,
        entries,
        first_rows,
    } = m;
    let shown = match first_rows {
        Exact::Matrix(r) => r.len(),
        _ => 0,
    };
    let what = entries_words(*entries, lang, sym);
    let symbol = sym(symbol);
    match (lang, shown) {
        (Lang::En, 1) => format!("{symbol} is a {rows} × {cols} matrix ({what}); its first row:"),
        (Lang::En, _) => {
            format!("{symbol} is a {rows} × {cols} matrix ({what}); its first {shown} rows:")
        }
        (Lang::Es, 1) => {
            format!("{symbol} es una matriz {rows} × {cols} ({what}); su primera fila:")
        }
        (Lang::Es, _) => {
            format!("{symbol} es una matriz {rows} × {cols} ({what}); sus {shown} primeras filas:")
        }
    }
}

/// The rows shown of a matrix in LaTeX: each a list free to break after its commas.
pub(super) fn rows_latex(first_rows: &Exact) -> Vec<String> {
    match first_rows {
        Exact::Matrix(rows) => rows
            .iter()
            .map(|r| {
                format!(
                    "$({})$",
                    r.iter()
                        .map(Print::to_latex)
                        .collect::<Vec<_>>()
                        .join(",\\allowbreak ")
                )
            })
            .collect(),
        _ => Vec::new(),
    }
}

/// A fact in LaTeX: its words escaped, its symbols and values in math mode.
pub(super) fn fact_latex(
    f: &Fact,
    lang: Lang,
    sym: &dyn Fn(&str) -> String,
    value: &dyn Fn(&Exact) -> String,
) -> String {
    // The facts' own words carry no LaTeX specials but `≤`, `<`, `[`, `(`.
    fact_words(f, lang, sym, value)
        .replace('≤', "$\\le$")
        .replace(" < ", " $<$ ")
        .replace("α", "$\\alpha$")
}
