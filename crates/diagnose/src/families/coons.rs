//! The answers of the Coons mistakes (`cagd_problem::diagnosis::CoonsMistake`): the key's
//! own steps c_c, c_d, c_cd recombined with a sign or a term changed (chapter 6, eq. (17)),
//! or the problem solved with the other blending.

use crate::change::{combine, int};
use crate::{Context, Mistaken};
use cagd_problem::diagnosis::CoonsMistake;
use cagd_problem::problem::Blend;
use cagd_problem::{Op, Quantity};

/// The answer a student who made `m` writes, or `None` where it does not apply.
pub(crate) fn mistaken(m: CoonsMistake, cx: &Context) -> Option<Mistaken> {
    // c = a c_c + b c_d + k c_cd, the notes' (1, 1, -1)
    let recombined = |a: i64, b: i64, k: i64| -> Option<Mistaken> {
        let (cc, cd, ccd) = (cx.step("c_c")?, cx.step("c_d")?, cx.step("c_cd")?);
        let mut terms = vec![(int(a), cc)];
        if b != 0 {
            terms.push((int(b), cd));
        }
        if k != 0 {
            terms.push((int(k), ccd));
        }
        let surface = combine(&terms)?;
        Some(Mistaken {
            result: vec![(Quantity::Surface, surface)],
            steps: Vec::new(),
        })
    };
    match m {
        CoonsMistake::CdAdded => recombined(1, 1, 1),
        CoonsMistake::CdLeftOut => recombined(1, 1, 0),
        CoonsMistake::OnlyOneRuled => recombined(1, 0, 0),
        CoonsMistake::LinearBlending => cx.solve_changed(|op| match op {
            Op::Coons(c) if c.blend == Some(Blend::Cubic) => {
                c.blend = Some(Blend::Linear);
                true
            }
            _ => false,
        }),
    }
}
