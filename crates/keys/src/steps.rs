//! The worked solution of an answer (its typed [`Step`]s) as text, LaTeX and Markdown, in
//! English or in the notes' Spanish: each formula with its sentence and the notes' equation
//! number, the substitutions, the tables (De Casteljau schemes, De Boor tables, basis values),
//! and the short legend, once a document, for readers of Farin or The NURBS Book where the
//! names differ.

mod combinations;
mod facts;
mod formulas;
mod inline_math;
mod legend;
mod symbols;
mod tables;

pub use symbols::symbol_text;

use crate::escape::escape_html;
use crate::values::{latex, text};
use crate::vocabulary::words;
use crate::Lang;
use cagd_contract::steps::Step;
use cagd_contract::{Exact, Verdict};
use combinations::{latex_terms, product_latex, product_text, text_terms};
use facts::{fact_latex, fact_words, matrix_words, rows_latex};
use formulas::{equation_label, said_of};
use inline_math::{latex_words, math_words};
pub use legend::{legend_latex, legend_markdown, legend_text};
use tables::{table_latex, table_markdown, table_text, table_title};

fn derivation(verdict: &Verdict) -> &[Step] {
    match &verdict.answer {
        Ok(a) => &a.derivation,
        Err(_) => &[],
    }
}

fn heading(lang: Lang) -> String {
    words(lang, "worked solution", "desarrollo")
}

/// The worked solution of a verdict's answer in plain text (empty without steps).
pub fn text_block(verdict: &Verdict, lang: Lang) -> String {
    let steps = derivation(verdict);
    if steps.is_empty() {
        return String::new();
    }
    let value = |x: &Exact| text(x, lang);
    let sym = |s: &str| symbol_text(s);
    let mut out = format!("{}:\n", heading(lang));
    for s in steps {
        match s {
            Step::Formula { formula, .. } => {
                let said = said_of(*formula);
                let eq = equation_label(*formula, lang)
                    .map(|e| format!(" [{e}]"))
                    .unwrap_or_default();
                out += &format!("  {}{eq}:\n", words(lang, said.en, said.es));
                if !said.text.is_empty() {
                    out += &format!("      {}\n", said.text);
                }
            }
            Step::Value { symbol, value: v } => {
                out += &format!(
                    "    {} = {}\n",
                    symbol_text(symbol),
                    text(v, lang).replace("; ", ";\n        ")
                );
            }
            Step::Combination {
                symbol,
                terms,
                value: v,
            } => {
                out += &format!(
                    "    {} = {} = {}\n",
                    symbol_text(symbol),
                    text_terms(terms, lang),
                    text(v, lang)
                );
            }
            Step::Table { title, table } => {
                out += &format!("    {}:\n", table_title(*title, lang));
                out += &table_text(table, lang);
            }
            Step::Fact(f) => out += &format!("    {}\n", fact_words(f, lang, &sym, &value)),
            Step::Matrix(m) => {
                out += &format!(
                    "    {}\n      {}\n",
                    matrix_words(m, lang, &sym),
                    text(&m.first_rows, lang).replace("; ", ";\n        ")
                );
            }
            Step::Product {
                symbol,
                factors,
                value: v,
            } => {
                out += &format!(
                    "    {} = {} = {}\n",
                    symbol_text(symbol),
                    product_text(factors, lang),
                    text(v, lang)
                );
            }
            Step::Identity { symbol, equals } => {
                out += &format!("    {} = {}\n", symbol_text(symbol), symbol_text(equals));
            }
            _ => {}
        }
    }
    out
}

/// A value in LaTeX; a map of several components as a column, one component per line, so
/// that long closed forms fit the page.
fn latex_value(v: &Exact, lang: Lang) -> String {
    match v {
        Exact::Map(m) if m.components().len() > 1 => format!(
            "\\begin{{pmatrix}} {} \\end{{pmatrix}}",
            m.components()
                .iter()
                .map(|p| p.to_latex())
                .collect::<Vec<_>>()
                .join(" \\\\ ")
        ),
        _ => latex(v, lang),
    }
}

/// The worked solution as a LaTeX paragraph (inside [`crate::example_latex`]).
pub fn latex_block(verdict: &Verdict, lang: Lang) -> String {
    let steps = derivation(verdict);
    if steps.is_empty() {
        return String::new();
    }
    let value = |x: &Exact| format!("${}$", latex(x, lang));
    let sym = |s: &str| format!("${s}$");
    let mut out = format!("\\paragraph{{{}}}\n\\begin{{itemize}}\n", heading(lang));
    for s in steps {
        match s {
            Step::Formula { formula, .. } => {
                let said = said_of(*formula);
                let eq = equation_label(*formula, lang)
                    .map(|e| format!(" [{e}]"))
                    .unwrap_or_default();
                out += &format!(
                    "\\item {}{eq}:\n\\[ {} \\]\n",
                    latex_words(&words(lang, said.en, said.es)),
                    said.latex
                );
            }
            Step::Value { symbol, value: v } => {
                out += &format!(
                    "\\item[] $\\displaystyle {symbol} = {}$\n",
                    crate::latex_math::lines_of_parts(&latex_value(v, lang))
                );
            }
            Step::Combination {
                symbol,
                terms,
                value: v,
            } => {
                out += &format!(
                    "\\item[] ${symbol} = {} = {}$\n",
                    latex_terms(terms, lang),
                    latex(v, lang)
                );
            }
            Step::Table { title, table } => {
                out += &format!(
                    "\\item[] {}:\n{}",
                    latex_words(&table_title(*title, lang)),
                    table_latex(table, lang)
                );
            }
            Step::Fact(f) => {
                out += &format!("\\item[] {}\n", fact_latex(f, lang, &sym, &value));
            }
            Step::Matrix(m) => {
                let words = matrix_words(m, lang, &sym).replace('×', "$\\times$");
                out += &format!(
                    "\\item[] {words}\\\\\n{}\n",
                    rows_latex(&m.first_rows).join("\\\\\n")
                );
            }
            Step::Product {
                symbol,
                factors,
                value: v,
            } => {
                out += &format!("\\item[] ${}$\n", product_latex(symbol, factors, v, lang));
            }
            Step::Identity { symbol, equals } => {
                out += &format!("\\item[] ${symbol} = {equals}$\n");
            }
            _ => {}
        }
    }
    out += "\\end{itemize}\n";
    out
}

/// The worked solution in Markdown with `$...$` math (inside [`crate::example_markdown`]).
pub fn markdown_block(verdict: &Verdict, lang: Lang) -> String {
    let steps = derivation(verdict);
    if steps.is_empty() {
        return String::new();
    }
    let value = |x: &Exact| format!("${}$", latex(x, lang));
    let sym = |s: &str| format!("${s}$");
    let mut out = format!("**{}**\n\n", heading(lang));
    for s in steps {
        match s {
            Step::Formula { formula, .. } => {
                let said = said_of(*formula);
                let eq = equation_label(*formula, lang)
                    .map(|e| format!(" [{e}]"))
                    .unwrap_or_default();
                out += &format!(
                    "- {}{eq}: $\\displaystyle {}$\n",
                    math_words(&words(lang, said.en, said.es), &escape_html),
                    said.latex
                );
            }
            Step::Value { symbol, value: v } => {
                out += &format!("  - ${symbol} = {}$\n", latex(v, lang));
            }
            Step::Combination {
                symbol,
                terms,
                value: v,
            } => {
                out += &format!(
                    "  - ${symbol} = {} = {}$\n",
                    latex_terms(terms, lang),
                    latex(v, lang)
                );
            }
            Step::Table { title, table } => {
                out += &format!(
                    "\n  {}:\n\n{}\n",
                    math_words(&table_title(*title, lang), &escape_html),
                    table_markdown(table, lang)
                );
            }
            Step::Fact(f) => out += &format!("  - {}\n", fact_words(f, lang, &sym, &value)),
            Step::Matrix(m) => {
                out += &format!("  - {}\n", matrix_words(m, lang, &sym));
                for row in rows_latex(&m.first_rows) {
                    out += &format!("    - {}\n", row.replace(",\\allowbreak ", ", "));
                }
            }
            Step::Product {
                symbol,
                factors,
                value: v,
            } => {
                out += &format!("  - ${}$\n", product_latex(symbol, factors, v, lang));
            }
            Step::Identity { symbol, equals } => {
                out += &format!("  - ${symbol} = {equals}$\n");
            }
            _ => {}
        }
    }
    out += "\n";
    out
}
