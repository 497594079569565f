//! The topics: one per construction of chapters 5 and 6, each with its generator.

mod fit;
mod generation;
mod join;
mod patch;

use crate::Topic;

/// Every topic, in the order of the notes.
pub(crate) static TOPICS: &[Topic] = &[
    Topic {
        name: "closed_form",
        op: "closed_form",
        description: "closed form c(u, v) of a Bézier patch (or a rational one) of bidegree up to (2, 2)",
        description_es: "parametrización c(u, v) de una superficie de Bézier (o racional) de bigrado hasta (2, 2)",
        source: "002_20d988b092ff1833.txt §2",
        draw: patch::closed_form,
    },
    Topic {
        name: "graph",
        op: "graph",
        description: "Bézier patch of the graph of a small polynomial f(x, y)",
        description_es: "malla de control de la gráfica de un polinomio f(x, y)",
        source: "002_20d988b092ff1833.txt §2",
        draw: patch::graph,
    },
    Topic {
        name: "evaluate",
        op: "evaluate",
        description: "points of a Bézier patch (or a rational one) by De Casteljau at parameters in {0, 1/4, 1/3, 1/2, 2/3, 3/4, 1}",
        description_es: "puntos de una superficie de Bézier (o racional) por De Casteljau en parámetros de {0, 1/4, 1/3, 1/2, 2/3, 3/4, 1}",
        source: "002_20d988b092ff1833.txt §4",
        draw: patch::evaluate,
    },
    Topic {
        name: "restrict",
        op: "restrict",
        description: "control mesh of a patch restricted to a sub-rectangle (blossom)",
        description_es: "malla de control de la restricción a un subrectángulo (forma polar)",
        source: "002_20d988b092ff1833.txt §4",
        draw: patch::restrict,
    },
    Topic {
        name: "elevate",
        op: "elevate",
        description: "degree elevation of a Bézier patch (or a rational one, or a B-spline surface)",
        description_es: "elevación del grado de una superficie de Bézier (o racional, o B-spline)",
        source: "002_20d988b092ff1833.txt §5",
        draw: patch::elevate,
    },
    Topic {
        name: "derivative",
        op: "derivative",
        description: "partial derivatives of a patch, also on a border",
        description_es: "derivadas parciales de una superficie, también en un borde",
        source: "002_20d988b092ff1833.txt §6",
        draw: patch::derivative,
    },
    Topic {
        name: "normal",
        op: "normal",
        description: "normal vector c_u × c_v, closed form and at the corners",
        description_es: "vector normal c_u × c_v, parametrización y en las esquinas",
        source: "002_20d988b092ff1833.txt §6",
        draw: patch::normal,
    },
    Topic {
        name: "continuity",
        op: "continuity",
        description: "order of continuity of two patches sharing a border (some C^1 by construction)",
        description_es: "orden de continuidad de dos superficies con un borde común (algunas C^1 por construcción)",
        source: "002_20d988b092ff1833.txt §6",
        draw: join::continuity,
    },
    Topic {
        name: "interpolate",
        op: "interpolate",
        description: "Bézier patch (or bicubic spline) through a grid of points, at equally or unequally spaced parameters",
        description_es: "superficie de Bézier (o spline bicúbica) que interpola una malla de puntos, en parámetros equiespaciados o no",
        source: "002_20d988b092ff1833.txt §7",
        draw: fit::interpolate,
    },
    Topic {
        name: "approximate",
        op: "approximate",
        description: "least-squares bilinear patch of a few points with parameters",
        description_es: "superficie bilineal que aproxima por mínimos cuadrados unos puntos con parámetros",
        source: "002_20d988b092ff1833.txt §7",
        draw: fit::approximate,
    },
    Topic {
        name: "translational",
        op: "translational",
        description: "translational surface c(u) + d(v) - a of two curves (Bézier, rational, B-spline or polynomial)",
        description_es: "superficie traslacional c(u) + d(v) - a de dos curvas (de Bézier, racionales, B-spline o polinómicas)",
        source: "000_4f266b7df5f64f70.txt §2",
        draw: generation::translational,
    },
    Topic {
        name: "ruled",
        op: "ruled",
        description: "ruled surface (1 - v) c1(u) + v c2(u) between two curves (Bézier, rational, B-spline or polynomial)",
        description_es: "superficie reglada (1 - v) c1(u) + v c2(u) entre dos curvas (de Bézier, racionales, B-spline o polinómicas)",
        source: "000_4f266b7df5f64f70.txt §3",
        draw: generation::ruled,
    },
    Topic {
        name: "developable",
        op: "developable",
        description: "is a ruled patch developable? (cylinders and cones by construction, and others)",
        description_es: "¿es desarrollable una superficie reglada? (cilindros y conos por construcción, y otras)",
        source: "000_4f266b7df5f64f70.txt §4",
        draw: generation::developable,
    },
    Topic {
        name: "coons",
        op: "coons",
        description: "Coons patch of four boundary curves that meet at the corners (Bézier, B-spline or polynomial; linear or cubic blending)",
        description_es: "superficie de Coons de cuatro curvas de borde que se cortan en las esquinas (de Bézier, B-spline o polinómicas; mezcla lineal o cúbica)",
        source: "000_4f266b7df5f64f70.txt §5",
        draw: generation::coons,
    },
    Topic {
        name: "revolution",
        op: "revolution",
        description: "surface of revolution of a profile in the XZ plane (quadrant, half or full turn; polynomial, rational or B-spline profile)",
        description_es: "superficie de revolución de un perfil del plano XZ (cuadrante, media vuelta o vuelta completa; perfil polinómico, racional o B-spline)",
        source: "000_4f266b7df5f64f70.txt §6",
        draw: generation::revolution,
    },
];
