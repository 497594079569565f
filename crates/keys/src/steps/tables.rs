//! The tables of a worked solution (De Casteljau and De Boor schemes, basis values, forward
//! differences, ratios): their titles, and the table in text, LaTeX and Markdown.

use super::symbols::symbol_text;
use crate::values::{latex, text};
use crate::vocabulary::words;
use crate::Lang;
use cagd_contract::steps::{Table, TableTitle};

pub(super) fn table_title(t: TableTitle, lang: Lang) -> String {
    match t {
        TableTitle::DeCasteljau => words(lang, "De Casteljau scheme", "Esquema de De Casteljau"),
        TableTitle::DeBoor => words(lang, "De Boor scheme", "Esquema de De Boor"),
        TableTitle::Basis => words(lang, "Basis functions", "Funciones base"),
        TableTitle::Differences => words(lang, "Forward differences", "Diferencias progresivas"),
        TableTitle::Alphas => words(lang, "The ratios α_i", "Los cocientes α_i"),
        _ => words(lang, "Table", "Tabla"),
    }
}

pub(super) fn table_text(t: &Table, lang: Lang) -> String {
    let mut grid: Vec<Vec<String>> = Vec::with_capacity(t.rows.len() + 1);
    let mut head = vec![String::new()];
    head.extend(t.columns.iter().map(|c| symbol_text(c)));
    grid.push(head);
    for (label, cells) in &t.rows {
        let mut row = vec![symbol_text(label)];
        row.extend(
            cells
                .iter()
                .map(|c| c.as_ref().map(|x| text(x, lang)).unwrap_or_default()),
        );
        grid.push(row);
    }
    let cols = grid.iter().map(Vec::len).max().unwrap_or(0);
    let widths: Vec<usize> = (0..cols)
        .map(|j| {
            grid.iter()
                .map(|r| r.get(j).map_or(0, |s| s.chars().count()))
                .max()
                .unwrap_or(0)
        })
        .collect();
    let mut out = String::new();
    for row in &grid {
        let line: Vec<String> = row
            .iter()
            .zip(&widths)
            .map(|(s, w)| format!("{s}{}", " ".repeat(w.saturating_sub(s.chars().count()))))
            .collect();
        out += &format!("      {}\n", line.join(" | ").trim_end());
    }
    out
}

pub(super) fn table_latex(t: &Table, lang: Lang) -> String {
    let cols = t.columns.len();
    let mut out = format!("\\[\\begin{{array}}{{c|{}}}\n", "c".repeat(cols));
    out += &format!(" & {} \\\\ \\hline\n", t.columns.join(" & "));
    for (label, cells) in &t.rows {
        let cells: Vec<String> = cells
            .iter()
            .map(|c| c.as_ref().map(|x| latex(x, lang)).unwrap_or_default())
            .collect();
        out += &format!("{label} & {} \\\\\n", cells.join(" & "));
    }
    out + "\\end{array}\\]\n"
}

pub(super) fn table_markdown(t: &Table, lang: Lang) -> String {
    let mut out = format!(
        "| | {} |\n|---|{}\n",
        t.columns
            .iter()
            .map(|c| format!("${c}$"))
            .collect::<Vec<_>>()
            .join(" | "),
        "---|".repeat(t.columns.len())
    );
    for (label, cells) in &t.rows {
        let cells: Vec<String> = cells
            .iter()
            .map(|c| {
                c.as_ref()
                    .map(|x| format!("${}$", latex(x, lang)))
                    .unwrap_or_default()
            })
            .collect();
        out += &format!("| ${label}$ | {} |\n", cells.join(" | "));
    }
    out
}
