//! The catalogue's computations, one module per operation family: for each mistake, the
//! answer a student who made it writes (`None` where it does not apply to the problem).

mod circle;
mod continuity;
mod coons;
mod derivative;
mod elevate;
mod evaluate;
mod insert_knot;
mod interpolate;
mod normal;
mod revolution;
mod ruled;
mod subdivide;
mod translational;

use crate::{Context, Mistaken};
use cagd_problem::Mistake;

/// The answer of `m` to the problem of `cx`, or `None` where it does not apply.
pub(crate) fn mistaken(m: Mistake, cx: &Context) -> Option<Mistaken> {
    match m {
        Mistake::Evaluate(m) => evaluate::mistaken(m, cx),
        Mistake::Elevate(m) => elevate::mistaken(m, cx),
        Mistake::Subdivide(m) => subdivide::mistaken(m, cx),
        Mistake::InsertKnot(m) => insert_knot::mistaken(m, cx),
        Mistake::Derivative(m) => derivative::mistaken(m, cx),
        Mistake::Normal(m) => normal::mistaken(m, cx),
        Mistake::Continuity(m) => continuity::mistaken(m, cx),
        Mistake::Ruled(m) => ruled::mistaken(m, cx),
        Mistake::Translational(m) => translational::mistaken(m, cx),
        Mistake::Coons(m) => coons::mistaken(m, cx),
        Mistake::Revolution(m) => revolution::mistaken(m, cx),
        Mistake::Circle(m) => circle::mistaken(m, cx),
        Mistake::Interpolate(m) => interpolate::mistaken(m, cx),
    }
}
