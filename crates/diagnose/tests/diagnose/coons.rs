//! Coons mistakes over random Coons problems (the exercises' generator), bilinear and
//! cubic blending.

use crate::common::{generated, holds_over};
use cagd_problem::diagnosis::CoonsMistake;
use cagd_problem::Mistake;
use proptest::prelude::*;

fn cubic(mut p: serde_json::Value) -> serde_json::Value {
    p["blend"] = "cubic".into();
    p
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(4))]

    #[test]
    fn every_coons_mistake_is_diagnosed(seed in 0u64..1_000_000) {
        // a few problems: where the four borders are bilinear, both blendings agree
        let problems = generated("coons", 5, seed);
        let cubics: Vec<_> = problems.iter().cloned().map(cubic).collect();
        for m in CoonsMistake::ALL {
            let m = Mistake::Coons(*m);
            match m {
                Mistake::Coons(CoonsMistake::LinearBlending) => holds_over(&cubics, m),
                _ => holds_over(&problems, m),
            }
        }
    }
}
