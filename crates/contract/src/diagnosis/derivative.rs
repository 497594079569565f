//! Mistakes in derivatives and twists (chapter 5, §6, eq. (16)-(20) and (24)): the derivative
//! patch m!n!/((m−r)!(n−s)!) Σ Δ^{r,s}c_{i,j} B_i^{m−r}(u) B_j^{n−s}(v) of (18), its rows on
//! a border (19)-(20), the twist mn Σ Δ^{1,1}c_{i,j} B_i^{m−1}(u) B_j^{n−1}(v) of (24), and
//! the derivative n!/(n−r)! Σ Δ^r c_i B_i^{n−r}(t) of a Bézier curve.

use super::{Catalogued, MistakeFormula, NotesPlace};
use cagd_words::{said, Lang, Message, Phrase};

/// A mistake in derivatives and twists.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum DerivativeMistake {
    /// The factor m!n!/((m−r)!(n−s)!) of (18) left out (n!/(n−r)! of a curve, mn of a
    /// twist): the differences Δ^{r,s}c_{i,j} taken for the derivative's control points.
    DegreeFactorLeftOut,
    /// The powers m^r n^s taken for the falling factorials m!/(m−r)! n!/(n−s)! of (18): n² for
    /// n(n−1) in a second derivative (only where an order is 2 or more).
    PowerForFalling,
    /// The differences reversed, c_{i,j} − c_{i+1,j} for Δ^{1,0}c_{i,j} = c_{i+1,j} − c_{i,j}:
    /// the derivative times (−1)^{r+s} (only where r + s is odd).
    DifferencesReversed,
    /// The derivative taken in the other parameter: ∂^{s+r}/∂u^s∂v^r for ∂^{r+s}/∂u^r∂v^s
    /// (c_v for c_u: on a border u = 0 the tangential derivative for the cross-boundary one).
    OtherDirection,
}

impl DerivativeMistake {
    /// Every mistake of the family.
    pub const ALL: &'static [DerivativeMistake] = &[
        DerivativeMistake::DegreeFactorLeftOut,
        DerivativeMistake::PowerForFalling,
        DerivativeMistake::DifferencesReversed,
        DerivativeMistake::OtherDirection,
    ];
}

/// (18): the derivative of order (r, s) of a Bézier patch.
const RIGHT: MistakeFormula = MistakeFormula {
    text: "∂^{r+s} c/∂u^r ∂v^s = m! n!/((m-r)! (n-s)!) Σ_i Σ_j Δ^{r,s} c_{i,j} B_i^{m-r}(u) B_j^{n-s}(v)",
    tex: r"\frac{\partial^{r+s} \mathbf c}{\partial u^r \partial v^s} = \frac{m!\, n!}{(m-r)!\,(n-s)!} \sum_{i=0}^{m-r} \sum_{j=0}^{n-s} \Delta^{r,s}\mathbf c_{i,j} B_i^{m-r}(u) B_j^{n-s}(v)",
};

impl Message for DerivativeMistake {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            DerivativeMistake::DegreeFactorLeftOut => said(
                lang,
                "left out the factor m!n!/((m−r)!(n−s)!) (m for c_u, mn for the twist c_uv): took the differences of the control points alone",
                "omitió el factor m!n!/((m−r)!(n−s)!) (m en c_u, mn en la derivada segunda cruzada c_uv): tomó solo las diferencias de los puntos de control",
                [],
            ),
            DerivativeMistake::PowerForFalling => said(
                lang,
                "multiplied by the powers m^r n^s instead of m!/(m−r)! n!/(n−s)! (n² instead of n(n−1) in a second derivative)",
                "multiplicó por las potencias m^r n^s en lugar de m!/(m−r)! n!/(n−s)! (n² en lugar de n(n−1) en una derivada segunda)",
                [],
            ),
            DerivativeMistake::DifferencesReversed => said(
                lang,
                "reversed the differences, c_{i,j} − c_{i+1,j} instead of c_{i+1,j} − c_{i,j}: the derivative has the opposite sign",
                "invirtió las diferencias, c_{i,j} − c_{i+1,j} en lugar de c_{i+1,j} − c_{i,j}: la derivada tiene el signo contrario",
                [],
            ),
            DerivativeMistake::OtherDirection => said(
                lang,
                "differentiated with respect to the other parameter: v for u (on a border u = 0, the derivative along the border for the cross-boundary one)",
                "derivó respecto del otro parámetro: v en lugar de u (en un borde u = 0, la derivada a lo largo del borde en lugar de la derivada transversal)",
                [],
            ),
        }
    }
}

impl Catalogued for DerivativeMistake {
    fn id(&self) -> &'static str {
        match self {
            DerivativeMistake::DegreeFactorLeftOut => "derivative.degree_factor_left_out",
            DerivativeMistake::PowerForFalling => "derivative.power_for_falling",
            DerivativeMistake::DifferencesReversed => "derivative.differences_reversed",
            DerivativeMistake::OtherDirection => "derivative.other_direction",
        }
    }

    fn place(&self) -> NotesPlace {
        let equation = match self {
            DerivativeMistake::DegreeFactorLeftOut | DerivativeMistake::PowerForFalling => "18",
            DerivativeMistake::DifferencesReversed => "16",
            DerivativeMistake::OtherDirection => "16-17",
        };
        NotesPlace::Notes {
            chapter: 5,
            section: 6,
            equation: Some(equation),
        }
    }

    fn right(&self) -> MistakeFormula {
        match self {
            DerivativeMistake::DifferencesReversed => MistakeFormula {
                text: "Δ^{1,0} c_{i,j} = c_{i+1,j} - c_{i,j}",
                tex: r"\Delta^{1,0}\mathbf c_{i,j} = \mathbf c_{i+1,j} - \mathbf c_{i,j}",
            },
            DerivativeMistake::OtherDirection => MistakeFormula {
                text: "∂c/∂u = m Σ_i Σ_j Δ^{1,0} c_{i,j} B_i^{m-1}(u) B_j^n(v)",
                tex: r"\frac{\partial \mathbf c}{\partial u} = m \sum_{i=0}^{m-1} \sum_{j=0}^{n} \Delta^{1,0}\mathbf c_{i,j} B_i^{m-1}(u) B_j^n(v)",
            },
            _ => RIGHT,
        }
    }

    fn used(&self) -> MistakeFormula {
        match self {
            DerivativeMistake::DegreeFactorLeftOut => MistakeFormula {
                text: "∂^{r+s} c/∂u^r ∂v^s = Σ_i Σ_j Δ^{r,s} c_{i,j} B_i^{m-r}(u) B_j^{n-s}(v)",
                tex: r"\frac{\partial^{r+s} \mathbf c}{\partial u^r \partial v^s} = \sum_{i=0}^{m-r} \sum_{j=0}^{n-s} \Delta^{r,s}\mathbf c_{i,j} B_i^{m-r}(u) B_j^{n-s}(v)",
            },
            DerivativeMistake::PowerForFalling => MistakeFormula {
                text: "∂^{r+s} c/∂u^r ∂v^s = m^r n^s Σ_i Σ_j Δ^{r,s} c_{i,j} B_i^{m-r}(u) B_j^{n-s}(v)",
                tex: r"\frac{\partial^{r+s} \mathbf c}{\partial u^r \partial v^s} = m^r n^s \sum_{i=0}^{m-r} \sum_{j=0}^{n-s} \Delta^{r,s}\mathbf c_{i,j} B_i^{m-r}(u) B_j^{n-s}(v)",
            },
            DerivativeMistake::DifferencesReversed => MistakeFormula {
                text: "Δ^{1,0} c_{i,j} = c_{i,j} - c_{i+1,j}",
                tex: r"\Delta^{1,0}\mathbf c_{i,j} = \mathbf c_{i,j} - \mathbf c_{i+1,j}",
            },
            DerivativeMistake::OtherDirection => MistakeFormula {
                text: "∂c/∂u = n Σ_i Σ_j Δ^{0,1} c_{i,j} B_i^m(u) B_j^{n-1}(v)",
                tex: r"\frac{\partial \mathbf c}{\partial u} = n \sum_{i=0}^{m} \sum_{j=0}^{n-1} \Delta^{0,1}\mathbf c_{i,j} B_i^m(u) B_j^{n-1}(v)",
            },
        }
    }
}
