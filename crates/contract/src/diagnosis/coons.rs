//! Mistakes in Coons surfaces (chapter 6, §5): the bilinearly blended patch
//! c = c_c + c_d − c_cd (eq. (15)-(17)), its Bézier mesh (eq. (18)-(19)), and the cubic
//! blending.

use super::{Catalogued, MistakeFormula, NotesPlace};
use cagd_words::{said, Lang, Message, Phrase};

/// A mistake in a Coons surface.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum CoonsMistake {
    /// The bilinear patch c_cd added instead of subtracted: c_c + c_d + c_cd.
    CdAdded,
    /// The bilinear patch c_cd left out: c_c + c_d.
    CdLeftOut,
    /// Only one ruled surface: c_c + c_d − c_cd with c_d left out, c = c_c (the patch
    /// interpolates two borders only).
    OnlyOneRuled,
    /// Linear blending functions used where the problem asks for cubic (Hermite) blending.
    LinearBlending,
}

impl CoonsMistake {
    /// Every Coons mistake.
    pub const ALL: &'static [CoonsMistake] = &[
        CoonsMistake::CdAdded,
        CoonsMistake::CdLeftOut,
        CoonsMistake::OnlyOneRuled,
        CoonsMistake::LinearBlending,
    ];
}

const RIGHT: MistakeFormula = MistakeFormula {
    text: "c = c_c + c_d - c_cd",
    tex: r"\mathbf c = \mathbf c_c + \mathbf c_d - \mathbf c_{cd}",
};

const PLACE: NotesPlace = NotesPlace::Notes {
    chapter: 6,
    section: 5,
    equation: Some("17"),
};

impl Message for CoonsMistake {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            CoonsMistake::CdAdded => said(
                lang,
                "added the bilinear patch c_cd instead of subtracting it",
                "sumó la superficie bilineal c_cd en lugar de restarla",
                [],
            ),
            CoonsMistake::CdLeftOut => said(
                lang,
                "left out the bilinear patch c_cd: added the two ruled surfaces only",
                "omitió la superficie bilineal c_cd: sumó solo las dos superficies regladas",
                [],
            ),
            CoonsMistake::OnlyOneRuled => said(
                lang,
                "took the ruled surface c_c between c₁ and c₂ alone, as if it were the Coons surface",
                "tomó solo la superficie reglada c_c entre c₁ y c₂, como si fuera la superficie de Coons",
                [],
            ),
            CoonsMistake::LinearBlending => said(
                lang,
                "used the linear blending functions 1 − u, u where the cubic ones are asked",
                "usó las funciones de mezcla lineales 1 − u, u donde se piden las cúbicas",
                [],
            ),
        }
    }
}

impl Catalogued for CoonsMistake {
    fn id(&self) -> &'static str {
        match self {
            CoonsMistake::CdAdded => "coons.cd_added",
            CoonsMistake::CdLeftOut => "coons.cd_left_out",
            CoonsMistake::OnlyOneRuled => "coons.only_one_ruled",
            CoonsMistake::LinearBlending => "coons.linear_blending",
        }
    }

    fn place(&self) -> NotesPlace {
        match self {
            CoonsMistake::LinearBlending => NotesPlace::Notes {
                chapter: 6,
                section: 5,
                equation: Some("16"),
            },
            _ => PLACE,
        }
    }

    fn right(&self) -> MistakeFormula {
        match self {
            CoonsMistake::LinearBlending => MistakeFormula {
                text: "f_0(u) = 1 - 3u^2 + 2u^3, f_1(u) = 3u^2 - 2u^3",
                tex: r"f_0(u) = 1 - 3u^2 + 2u^3,\quad f_1(u) = 3u^2 - 2u^3",
            },
            _ => RIGHT,
        }
    }

    fn used(&self) -> MistakeFormula {
        match self {
            CoonsMistake::CdAdded => MistakeFormula {
                text: "c = c_c + c_d + c_cd",
                tex: r"\mathbf c = \mathbf c_c + \mathbf c_d + \mathbf c_{cd}",
            },
            CoonsMistake::CdLeftOut => MistakeFormula {
                text: "c = c_c + c_d",
                tex: r"\mathbf c = \mathbf c_c + \mathbf c_d",
            },
            CoonsMistake::OnlyOneRuled => MistakeFormula {
                text: "c = c_c",
                tex: r"\mathbf c = \mathbf c_c",
            },
            CoonsMistake::LinearBlending => MistakeFormula {
                text: "f_0(u) = 1 - u, f_1(u) = u",
                tex: r"f_0(u) = 1 - u,\quad f_1(u) = u",
            },
        }
    }
}
