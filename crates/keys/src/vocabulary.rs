//! The fixed words of the keys in each language: headings and labels ([`Word`]), and what each
//! operation computes ([`op_words`]).

use crate::Lang;

/// The fixed words of the keys (headings, labels) in each language.
pub trait Word {
    /// A word of the answer keys in this language.
    fn word(self, key: &str) -> String;
}

impl Word for Lang {
    fn word(self, key: &str) -> String {
        let es = match key {
            "source" => "fuente",
            "input" => "datos",
            "steps" => "pasos",
            "result" => "resultado",
            "verdict" => "veredicto",
            "matches the notes" => "coincide con los apuntes",
            "matches the expected answer" => "coincide con la respuesta esperada",
            "erratum" => "errata",
            "the notes print" => "los apuntes dicen",
            "the exact value is" => "el valor exacto es",
            "mesh" => "malla de control",
            "weights" => "pesos",
            "knots" => "nudos",
            "bidegree" => "bigrado",
            "degree" => "grado",
            "polygon" => "polígono de control",
            "control vector" => "vector de control",
            "control vectors" => "vectores de control",
            "closed form" => "parametrización",
            "error" => "error",
            "failed" => "falla",
            "Answer key" => "Soluciones",
            "Problem" => "Problema",
            "problem" => "problema",
            "field" => "campo",
            "remarks" => "observaciones",
            "note" => "nota",
            "operation" => "operación",
            "Statements" => "Enunciados",
            "Data" => "Datos",
            "Find" => "Calcula",
            other => other,
        };
        match self {
            Lang::En => key.to_string(),
            Lang::Es => es.to_string(),
        }
    }
}

/// What an operation computes, in words: the line under a key's heading.
pub fn op_words(op: &str, lang: Lang) -> &'static str {
    let (en, es) = match op {
        "evaluate" => ("evaluation", "evaluación"),
        "closed_form" => ("closed form", "parametrización"),
        "restrict" => ("restriction to a subdomain", "restricción a un subrecinto"),
        "elevate" => ("degree elevation", "elevación del grado"),
        "derivative" => ("derivative", "derivada"),
        "normal" => ("normal vector", "vector normal"),
        "continuity" => (
            "continuity of a join",
            "continuidad de la unión de dos superficies",
        ),
        "interpolate" => ("interpolation", "interpolación"),
        "approximate" => (
            "least-squares approximation",
            "aproximación por mínimos cuadrados",
        ),
        "translational" => ("translational surface", "superficie traslacional"),
        "ruled" => ("ruled surface", "superficie reglada"),
        "developable" => ("developability criterion", "criterio de desarrollabilidad"),
        "coons" => ("Coons surface", "superficie de Coons"),
        "revolution" => ("surface of revolution", "superficie de revolución"),
        "insert_knot" => ("knot insertion", "algoritmo de inserción"),
        "graph" => ("graph of a function", "gráfica de una función"),
        "circle" => ("circle", "circunferencia"),
        "blossom" => ("blossom (polar form)", "forma polar"),
        "subdivide" => ("subdivision", "subdivisión"),
        "boundary" => ("boundary curves", "curvas borde"),
        "isocurve" => ("iso-parametric curve", "curva isoparamétrica"),
        "extract" => ("Bézier extraction", "extracción de los trozos de Bézier"),
        "remove_knot" => ("knot removal", "eliminación de un nudo"),
        "reverse" => ("reversal", "inversión del sentido"),
        "reduce_degree" => ("degree reduction", "reducción del grado"),
        "curve_continuity" => (
            "continuity of two curves",
            "continuidad de la unión de dos curvas",
        ),
        "gaussian_curvature" => ("Gaussian curvature", "curvatura de Gauss"),
        "tangent_developable" => (
            "tangent developable surface",
            "superficie desarrollable tangencial",
        ),
        "conic" => ("conic", "cónica"),
        "arc_length" => ("arc length", "longitud de arco"),
        "knot_vector" => (
            "knot vector: multiplicities and spans",
            "sucesión de nudos: multiplicidades y tramos",
        ),
        "invert_point" => ("point inversion", "inversión de un punto"),
        "normalize" => (
            "reparametrization onto [0, 1]",
            "reparametrización sobre [0, 1]",
        ),
        "integral" => ("integral", "integral"),
        "area" => ("area", "área"),
        "loft" => ("lofted surface", "superficie por secciones"),
        // an operation without words: its name is printed (never an empty title)
        _ => ("", ""),
    };
    match lang {
        Lang::En => en,
        Lang::Es => es,
    }
}

/// A pair of words, English and Spanish, in the language asked.
pub(crate) fn words(lang: Lang, en: &str, es: &str) -> String {
    match lang {
        Lang::En => en.to_string(),
        Lang::Es => es.to_string(),
    }
}

/// The operation of a key in words ([`op_words`]), its name only for an operation without
/// words.
pub(crate) fn operation_words(op: &str, lang: Lang) -> String {
    match op_words(op, lang) {
        "" => op.to_string(),
        words => words.to_string(),
    }
}
