//! The keys' own sentences, typed: the remarks a key adds, the words of a problem's keywords
//! and of the sign of the Gaussian curvature, and how a front end says to raise a limit. Each
//! is worded in English and in the notes' Spanish beside its definition.

use crate::said::Sentence;
use crate::{escape_latex, said, Lang};
use cagd_words::{said, Message, Phrase};

/// A remark of a key, beside the answer's own.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, strum::EnumIter)]
pub enum KeyRemark {
    /// The knots are printed with their end knots, as the problem gave them.
    #[default]
    FullKnots,
}

impl Message for KeyRemark {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            KeyRemark::FullKnots => said(
                lang,
                "the knots are printed as the data gives them, with one more knot at each end than the notes' convention (Piegl and Tiller's)",
                "los nudos se dan como en los datos, con un nudo más en cada extremo que en el convenio de los apuntes (el de Piegl y Tiller)",
                [],
            ),
        }
    }
}

/// A keyword of a problem that has words of its own (`parametrization`: `chord_length`, `end`:
/// `bessel`, `blend`: `cubic`...), echoed in its key as words. Any other keyword is echoed as
/// it is written, its `_` as spaces.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, strum::EnumIter)]
pub enum Keyword {
    /// `uniform` parameters.
    #[default]
    Uniform,
    /// `chord_length` parameters.
    ChordLength,
    /// `centripetal` parameters.
    Centripetal,
    /// `linear` blending functions.
    Linear,
    /// `cubic` blending functions.
    Cubic,
    /// `natural` end conditions.
    Natural,
    /// `bessel` end conditions.
    Bessel,
    /// `clamped` end conditions.
    Clamped,
    /// The `bicubic` spline basis.
    Bicubic,
    /// The `bezier` basis.
    Bezier,
    /// The `bspline` basis.
    BSpline,
    /// Knots in the `notes`' convention.
    Notes,
    /// Knots in The NURBS Book's convention (`nurbs_book`).
    NurbsBook,
    /// An `open_uniform` knot vector.
    OpenUniform,
}

impl Keyword {
    /// The keyword as written in a problem, when it has words of its own.
    pub fn of(keyword: &str) -> Option<Keyword> {
        Some(match keyword_text(keyword).as_str() {
            "uniform" => Keyword::Uniform,
            "chord length" => Keyword::ChordLength,
            "centripetal" => Keyword::Centripetal,
            "linear" => Keyword::Linear,
            "cubic" => Keyword::Cubic,
            "natural" => Keyword::Natural,
            "Bessel" => Keyword::Bessel,
            "clamped" => Keyword::Clamped,
            "bicubic" => Keyword::Bicubic,
            "bezier" => Keyword::Bezier,
            "bspline" => Keyword::BSpline,
            "notes" => Keyword::Notes,
            "nurbs book" => Keyword::NurbsBook,
            "open uniform" => Keyword::OpenUniform,
            _ => return None,
        })
    }
}

/// A keyword as written, as words: `chord_length` is "chord length", `bessel` "Bessel", any
/// other with its `_` as spaces.
pub fn keyword_text(keyword: &str) -> String {
    match keyword {
        "chord_length" => "chord length".into(),
        "bessel" => "Bessel".into(),
        k => k.replace('_', " "),
    }
}

impl Message for Keyword {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            Keyword::Uniform => said(lang, "uniform", "uniformes", []),
            Keyword::ChordLength => said(lang, "chord length", "por longitud de cuerda", []),
            Keyword::Centripetal => said(lang, "centripetal", "centrípetos", []),
            Keyword::Linear => said(lang, "linear", "lineales", []),
            Keyword::Cubic => said(lang, "cubic", "cúbicas", []),
            Keyword::Natural => said(lang, "natural", "naturales", []),
            Keyword::Bessel => said(lang, "Bessel", "de Bessel", []),
            Keyword::Clamped => said(lang, "clamped", "derivadas dadas", []),
            Keyword::Bicubic => said(lang, "bicubic", "spline bicúbico", []),
            Keyword::Bezier => said(lang, "Bézier", "Bézier", []),
            Keyword::BSpline => said(lang, "B-spline", "B-spline", []),
            Keyword::Notes => said(
                lang,
                "the notes' (without end knots, n + p - 1 knots)",
                "el de los apuntes (sin nudos extremos, n + p - 1 nudos)",
                [],
            ),
            Keyword::NurbsBook => said(
                lang,
                "The NURBS Book's (one more knot at each end, n + p + 1 knots)",
                "el de Piegl y Tiller (un nudo más en cada extremo, n + p + 1 nudos)",
                [],
            ),
            Keyword::OpenUniform => said(
                lang,
                "open uniform (clamped)",
                "uniformes con extremos repetidos",
                [],
            ),
        }
    }
}

/// The `sign` of `gaussian_curvature` in words.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, strum::EnumIter)]
pub enum CurvatureSign {
    /// 1: G > 0 on the whole domain.
    #[default]
    Positive,
    /// -1: G < 0 on the whole domain.
    Negative,
    /// 0: G vanishes somewhere on the domain.
    None,
}

impl CurvatureSign {
    /// The sign of the answer's `sign` (1, -1 or 0).
    pub fn of(sign: i64) -> CurvatureSign {
        match sign.signum() {
            1 => CurvatureSign::Positive,
            -1 => CurvatureSign::Negative,
            _ => CurvatureSign::None,
        }
    }
}

impl Message for CurvatureSign {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            CurvatureSign::Positive => said(lang, "positive (G > 0)", "positivo (G > 0)", []),
            CurvatureSign::Negative => said(lang, "negative (G < 0)", "negativo (G < 0)", []),
            CurvatureSign::None => said(
                lang,
                "none (G vanishes on the domain)",
                "ninguno (G se anula en el recinto)",
                [],
            ),
        }
    }
}

/// How a front end says to raise the limit a problem is past, after the error's message.
#[derive(Debug, Clone, PartialEq, Eq, strum::EnumIter)]
pub enum Raise {
    /// The flag of the command line that raises it (`--max-degree`).
    Flag {
        /// The flag.
        flag: String,
    },
    /// The keyword of the Python module that raises it (`max_degree`).
    Keyword {
        /// The keyword.
        keyword: String,
    },
}

impl Default for Raise {
    fn default() -> Self {
        Raise::Flag {
            flag: "--max-degree".into(),
        }
    }
}

impl Message for Raise {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            Raise::Flag { flag } => {
                said(lang, "(raise it with ‹›)", "(súbalo con ‹›)", [flag.into()])
            }
            Raise::Keyword { keyword } => said(
                lang,
                "(raise it with ‹›=N)",
                "(súbalo con ‹›=N)",
                [keyword.into()],
            ),
        }
    }
}

cagd_words::display_english!(KeyRemark, Keyword, CurvatureSign, Raise);

impl Raise {
    /// The sentence in `lang`, the flag or keyword in typewriter in LaTeX.
    pub fn sentence(&self, lang: Lang) -> Sentence {
        let p = self.phrase(lang);
        Sentence {
            text: p.text(),
            latex: said::latex_with(&p, &|d| format!("\\texttt{{{}}}", escape_latex(d))),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use strum::IntoEnumIterator;

    #[test]
    fn every_variant_in_both_languages() {
        for m in KeyRemark::iter() {
            assert_eq!(cagd_words::check_both(&m), Ok(()));
        }
        for m in Keyword::iter() {
            assert_eq!(cagd_words::check_both(&m), Ok(()));
        }
        for m in CurvatureSign::iter() {
            assert_eq!(cagd_words::check_both(&m), Ok(()));
        }
        for m in Raise::iter() {
            assert_eq!(cagd_words::check_both(&m), Ok(()));
        }
    }

    #[test]
    fn keywords_by_their_words() {
        assert_eq!(Keyword::of("chord_length"), Some(Keyword::ChordLength));
        assert_eq!(Keyword::of("bessel"), Some(Keyword::Bessel));
        assert_eq!(Keyword::of("bezier"), Some(Keyword::Bezier));
        assert_eq!(Keyword::of("not_a_knot"), None);
        assert_eq!(keyword_text("not_a_knot"), "not a knot");
    }

    #[test]
    fn a_flag_in_typewriter() {
        let r = Raise::Flag {
            flag: "--max-batch".into(),
        };
        assert_eq!(r.to_string(), "(raise it with --max-batch)");
        let s = r.sentence(Lang::Es);
        assert_eq!(s.text, "(súbalo con --max-batch)");
        assert_eq!(s.latex, "(súbalo con \\texttt{--max-batch})");
    }
}
