//! The catalogue of the engine's sentences: every message a key can print that the engine
//! writes in words (errors of every crate, mismatches of a check, remarks, continuity
//! sentences), each with its Spanish in the notes' register and its mathematics marked.
//!
//! The engine's crates write their messages in English, from their error enums' `Display`
//! (and the problem layer's readers, whose messages cross serde as strings). The catalogue is
//! keyed by those `Display` formats: each entry is the English format, with its holes, and
//! the Spanish one. A message is matched against every English format (of those that match,
//! the most specific wins: the one with the most words of its own), its holes captured, and the
//! sentence rebuilt in the language asked. One place to maintain, next to the one test
//! (`tests/spanish.rs`) that renders every example, every operation and a representative
//! error of every kind in Spanish and fails on any English word left: a message whose format
//! changes without its entry shows up there.
//!
//! The notation of a format:
//! - `‹›` a hole copied as it is (a number, a point, a name);
//! - `«»` a hole that is itself a sentence, translated in turn (an inner error);
//! - `$...$` mathematics: stripped in text, typeset in LaTeX (and the holes inside it with
//!   [`math_latex`]).

use crate::Lang;

pub use crate::said::Sentence;

/// (English, Spanish): the formats of the engine's sentences.
const SENTENCES: &[(&str, &str)] = &[
    // --- breadth: degree reduction, fitting domains and parameters ---
    (
        "exact: the curve is of degree ‹›, the same curve with ‹› control points",
        "exacta: la curva es de grado ‹›, la misma curva con ‹› puntos de control",
    ),
    (
        "not exact: the curve is not of degree ‹›; this is the least-squares reduction of the control polygon (E^t E c̃ = E^t c), a different curve",
        "no exacta: la curva no es de grado ‹›; esta es la reducción por mínimos cuadrados del polígono de control (E^t E c̃ = E^t c), una curva distinta",
    ),
    (
        "the parameters lie outside [0, 1]: the curve is on [‹›, ‹›], written as a B-spline of one piece (knots ‹› and ‹›, each n times) so that it is evaluated at the given parameters",
        "los parámetros quedan fuera de [0, 1]: la curva está en [‹›, ‹›], escrita como una B-spline de un solo trozo (nudos ‹› y ‹›, cada uno n veces) para que se evalúe en los parámetros dados",
    ),
    (
        "the parameters lie outside [0, 1]: the patch is on [‹›, ‹›] x [‹›, ‹›], written as a B-spline surface of one piece (knots at the ends, each m and n times) so that its mesh and its closed form agree",
        "los parámetros quedan fuera de [0, 1]: la superficie está en [‹›, ‹›] x [‹›, ‹›], escrita como una superficie B-spline de un solo trozo (nudos en los extremos, m y n veces) para que su malla y su parametrización coincidan",
    ),
    (
        "the parameters, by chord length: ‹›",
        "los parámetros, por longitud de cuerda: ‹›",
    ),
    ("the parameters, uniform: ‹›", "los parámetros, uniformes: ‹›"),
    ("the parameters, centripetal: ‹›", "los parámetros, centrípetos: ‹›"),
    // --- ends: B-spline interpolation with end derivatives (The NURBS Book §9.2.2) ---
    (
        "a B-spline interpolant with end derivatives through ‹› data points has a degree from ‹› to ‹›, found ‹›",
        "un interpolante B-spline con derivadas en los extremos por ‹› puntos de datos tiene un grado de ‹› a ‹›, se encontró ‹›",
    ),
    (
        "a B-spline interpolant with end derivatives needs at least ‹› data points, found ‹›",
        "un interpolante B-spline con derivadas en los extremos necesita al menos ‹› puntos de datos, se encontraron ‹›",
    ),
    (
        "a B-spline of `degree` p takes `end`: `clamped` with `tangents` (natural and Bessel ends are for the cubic spline, `bicubic`)",
        "una B-spline de grado p (`degree`) lleva `end`: `clamped` con `tangents` (los extremos natural y de Bessel son del spline cúbico, `bicubic`)",
    ),
    (
        "end derivatives go with `end`: `clamped` (a cubic spline, or a B-spline of `degree` p)",
        "las derivadas en los extremos van con `end`: `clamped` (un spline cúbico, o una B-spline de grado p, `degree`)",
    ),
    (
        "the start derivative $D_0$ has dimension ‹›, but data point 0 has dimension ‹›",
        "la derivada inicial $D_0$ tiene dimensión ‹›, pero el punto de datos 0 tiene dimensión ‹›",
    ),
    (
        "the end derivative $D_n$ has dimension ‹›, but data point 0 has dimension ‹›",
        "la derivada final $D_n$ tiene dimensión ‹›, pero el punto de datos 0 tiene dimensión ‹›",
    ),
    (
        "expected two end derivatives [$c'(t_0), c'(t_n)$], found ‹›",
        "se esperaban dos derivadas en los extremos [$c'(t_0), c'(t_n)$], se encontraron ‹›",
    ),
    // --- breadth: where the numerator of the Gaussian curvature vanishes ---
    (
        "$G ≡ 0$ on the domain: $K = 0$, the surface is developable (8)",
        "$G ≡ 0$ en el dominio: $K = 0$, la superficie es desarrollable (8)",
    ),
    (
        "$G > 0$ on the whole domain (its Bernstein coefficients on the domain are all positive): $K > 0$, the surface is elliptic there",
        "$G > 0$ en todo el dominio (sus coeficientes de Bernstein en el dominio son todos positivos): $K > 0$, la superficie es elíptica ahí",
    ),
    (
        "$G < 0$ on the whole domain (its Bernstein coefficients on the domain are all negative): $K < 0$, the surface is hyperbolic there",
        "$G < 0$ en todo el dominio (sus coeficientes de Bernstein en el dominio son todos negativos): $K < 0$, la superficie es hiperbólica ahí",
    ),
    (
        "$G > 0$ on the whole domain (its Bernstein coefficients are all positive on each of the ‹› rectangles the domain was cut into): $K > 0$, the surface is elliptic there",
        "$G > 0$ en todo el dominio (sus coeficientes de Bernstein son todos positivos en cada uno de los ‹› rectángulos en que se dividió el dominio): $K > 0$, la superficie es elíptica ahí",
    ),
    (
        "$G < 0$ on the whole domain (its Bernstein coefficients are all negative on each of the ‹› rectangles the domain was cut into): $K < 0$, the surface is hyperbolic there",
        "$G < 0$ en todo el dominio (sus coeficientes de Bernstein son todos negativos en cada uno de los ‹› rectángulos en que se dividió el dominio): $K < 0$, la superficie es hiperbólica ahí",
    ),
    (
        "$G$ vanishes on the domain: $G = 0$ at $(u, v) = ‹›$",
        "$G$ se anula en el dominio: $G = 0$ en $(u, v) = ‹›$",
    ),
    (
        "$G$ vanishes on the domain: $G > 0$ at $(u, v) = ‹›$ and $G < 0$ at $(u, v) = ‹›$, so $G = 0$ somewhere on the segment between them",
        "$G$ se anula en el dominio: $G > 0$ en $(u, v) = ‹›$ y $G < 0$ en $(u, v) = ‹›$, así que $G = 0$ en algún punto del segmento que los une",
    ),
    (
        "where $G$ vanishes is not decided: the signs of its Bernstein coefficients depend on the letters",
        "no se decide dónde se anula $G$: los signos de sus coeficientes de Bernstein dependen de las letras",
    ),
    (
        "where $G$ vanishes is not decided within ‹› halvings of the domain: on some rectangle the Bernstein coefficients of $G$ have both signs, and no corner gave a zero or a change of sign",
        "no se decide dónde se anula $G$ en ‹› divisiones por la mitad del dominio: en algún rectángulo los coeficientes de Bernstein de $G$ tienen ambos signos, y ninguna esquina dio un cero ni un cambio de signo",
    ),
    (
        "$G$ has no zero inside any piece, but it is positive on some pieces and negative on others: it jumps across a knot line, where the second derivatives of the surface jump",
        "$G$ no tiene ceros dentro de ningún trozo, pero es positivo en unos trozos y negativo en otros: salta a través de una línea de nudos, donde saltan las segundas derivadas de la superficie",
    ),
    // --- breadth: the continuity of two separate B-spline or NURBS surfaces ---
    (
        "the borders run over different ‹› intervals: the first's [‹›, ‹›], the second's [‹›, ‹›]; continuity compares them at the same ‹›",
        "los bordes recorren intervalos de ‹› distintos: el de la primera [‹›, ‹›], el de la segunda [‹›, ‹›]; la continuidad los compara en el mismo ‹›",
    ),
    (
        "a B-spline or NURBS surface is joined in its own parameters (its spans give the lengths): leave out `lengths`",
        "una superficie B-spline o NURBS se une en sus propios parámetros (sus intervalos dan las longitudes): quite `lengths`",
    ),
    (
        "no piece of the first surface ends at ‹› = ‹› while one of the second begins at ‹› = ‹›",
        "ningún trozo de la primera superficie acaba en ‹› = ‹› mientras uno de la segunda empieza en ‹› = ‹›",
    ),
    (
        "the second surface begins at ‹› = ‹› and the first ends at ‹› = ‹›: the second was moved by ‹› along ‹› so that they are consecutive; the derivatives are in the surfaces' own parameters",
        "la segunda superficie empieza en ‹› = ‹› y la primera acaba en ‹› = ‹›: la segunda se ha trasladado ‹› en ‹› para que sean consecutivas; las derivadas son en los parámetros propios de las superficies",
    ),
    // --- breadth: degree reduction of rational, B-spline and NURBS curves ---
    (
        "the homogeneous polygon (w_i c_i, w_i) of «» is not of degree ‹›, so the curve is not exactly of degree ‹›; a least-squares reduction of the homogeneous points can make a weight zero or negative (and is not the nearest curve), so it is not done",
        "el polígono homogéneo (w_i c_i, w_i) de «» no es de grado ‹›, así que la curva no es exactamente de grado ‹›; una reducción por mínimos cuadrados de los puntos homogéneos puede dar un peso nulo o negativo (y no es la curva más cercana), así que no se hace",
    ),
    ("this rational curve", "esta curva racional"),
    ("the piece on [‹›, ‹›]", "el trozo en [‹›, ‹›]"),
    (
        "the exact reduction has the weight ‹› at control point ‹›, not positive: it is the same curve, but not a rational curve with positive weights",
        "la reducción exacta tiene el peso ‹› en el punto de control ‹›, que no es positivo: es la misma curva, pero no una curva racional de pesos positivos",
    ),
    (
        "the piece on [‹›, ‹›] is not of degree ‹›: a B-spline curve is reduced only exactly (a least-squares reduction of each piece would not join the next)",
        "el trozo en [‹›, ‹›] no es de grado ‹›: una curva B-spline solo se reduce de forma exacta (una reducción por mínimos cuadrados de cada trozo no empalmaría con el siguiente)",
    ),
    (
        "a B-spline curve of degree ‹› cannot be reduced by ‹›: its degree must stay at least 1",
        "una curva B-spline de grado ‹› no se puede reducir en ‹›: su grado ha de seguir siendo al menos 1",
    ),
    (
        "degree reduction is for Bézier, rational Bézier, B-spline and NURBS curves",
        "la reducción del grado es para curvas de Bézier, de Bézier racionales, B-spline y NURBS",
    ),
    // --- breadth: subdivision and knot removal of B-spline and NURBS surfaces ---
    (
        "in ‹›, on column ‹› of the mesh: «»",
        "en ‹›, en la columna ‹› de la malla: «»",
    ),
    (
        "in ‹›, on row ‹› of the mesh: «»",
        "en ‹›, en la fila ‹› de la malla: «»",
    ),
    (
        "‹› is not strictly inside the domain [‹›, ‹›] of the surface in ‹›",
        "‹› no está estrictamente dentro del dominio [‹›, ‹›] de la superficie en ‹›",
    ),
    (
        "missing (give `u`, `v` or both: where the surface is split)",
        "falta (dé `u`, `v` o ambos: dónde se divide la superficie)",
    ),
    (
        "knot removal needs a B-spline or NURBS surface (`bspline`, `knots`)",
        "quitar un nudo requiere una superficie B-spline o NURBS (`bspline`, `knots`)",
    ),
    // --- breadth: the arc length of rational curves ---
    (
        "c'·c' = N/w⁴ with N = ‹› not the square of a polynomial: the arc length ∫√N/w² dt is then in general no number of Q or of one Q(√d), and it is not given, neither rounded",
        "c'·c' = N/w⁴ con N = ‹›, que no es el cuadrado de un polinomio: la longitud de arco ∫√N/w² dt no es entonces en general un número de Q ni de un Q(√d), y no se da, ni redondeada",
    ),
    (
        "|c'(t)| = |σ(t)|/w(t)² with σ = ‹› changing sign (or not decided by its Bernstein coefficients within ‹› halvings) on [‹›, ‹›]: the length needs its roots, not computed here",
        "|c'(t)| = |σ(t)|/w(t)² con σ = ‹›, que cambia de signo (o sus coeficientes de Bernstein no lo deciden en ‹› bisecciones) en [‹›, ‹›]: la longitud necesita sus raíces, que aquí no se calculan",
    ),
    (
        "|c'(t)| = |σ(t)| with σ = ‹› changing sign (or not decided by its Bernstein coefficients within ‹› halvings) on [‹›, ‹›]: the length ∫|σ| needs its roots, not computed here",
        "|c'(t)| = |σ(t)| con σ = ‹›, que cambia de signo (o sus coeficientes de Bernstein no lo deciden en ‹› bisecciones) en [‹›, ‹›]: la longitud ∫|σ| necesita sus raíces, que aquí no se calculan",
    ),
    (
        "c'·c' = σ²/w⁴ with σ = ‹› and w = ‹›: the length ∫|σ|/w² dt has no rational antiderivative (its partial fractions leave a logarithm or an arctangent; a circle arc's length R θ is one, θ in radians, no number of Q or of one Q(√d)), so it is not given, neither rounded nor written with π",
        "c'·c' = σ²/w⁴ con σ = ‹› y w = ‹›: la longitud ∫|σ|/w² dt no tiene primitiva racional (sus fracciones simples dejan un logaritmo o un arco tangente; la longitud R θ de un arco de circunferencia es una, con θ en radianes, que no es un número de Q ni de un Q(√d)), así que no se da, ni redondeada ni escrita con π",
    ),
    (
        "the weight function vanishes at the end of the interval",
        "la función peso se anula en el extremo del intervalo",
    ),
    // --- breadth: the parameters of a grid from its data ---
    (
        "the parameters, uniform and averaged over the columns (u) and the rows (v): u = ‹›; v = ‹›",
        "los parámetros, uniformes y promediados sobre las columnas (u) y las filas (v): u = ‹›; v = ‹›",
    ),
    (
        "the parameters, by chord length and averaged over the columns (u) and the rows (v): u = ‹›; v = ‹›",
        "los parámetros, por longitud de cuerda y promediados sobre las columnas (u) y las filas (v): u = ‹›; v = ‹›",
    ),
    (
        "the parameters, centripetal and averaged over the columns (u) and the rows (v): u = ‹›; v = ‹›",
        "los parámetros, centrípetos y promediados sobre las columnas (u) y las filas (v): u = ‹›; v = ‹›",
    ),
    ("the parameters of column ‹›: «»", "los parámetros de la columna ‹›: «»"),
    ("the parameters of row ‹›: «»", "los parámetros de la fila ‹›: «»"),
    (
        "either `u` and `v` or a `parametrization`, not both",
        "o bien `u` y `v` o bien una `parametrization`, no ambas",
    ),
    // --- letters: parameters, functions, generic meshes, formulas ---
    (
        "in letters, an equality that holds is an identity (it holds for all values of the letters), and one that fails, fails for general values (it may hold for special ones: put them in with \"values\")",
        "en letras, una igualdad que se cumple es una identidad (se cumple para todos los valores de las letras), y una que no se cumple falla para valores generales (puede cumplirse para valores particulares: sustitúyalos con \"values\")",
    ),
    (
        "‹›: at column ‹›: expected a number (declare letters in \"parameters\" to use them), found ‹›, which is not a declared parameter",
        "‹›: en la columna ‹›: se esperaba un número (declare las letras en \"parameters\" para usarlas), se encontró ‹›, que no es un parámetro declarado",
    ),
    (
        "at column ‹›: expected a number (declare letters in \"parameters\" to use them), found ‹›, which is not a declared parameter",
        "en la columna ‹›: se esperaba un número (declare las letras en \"parameters\" para usarlas), se encontró ‹›, que no es un parámetro declarado",
    ),
    (
        "‹›: at column ‹›: expected a number or a declared parameter (‹›), found ‹›, which is not a declared parameter",
        "‹›: en la columna ‹›: se esperaba un número o un parámetro declarado (‹›), se encontró ‹›, que no es un parámetro declarado",
    ),
    (
        "at column ‹›: expected a number or a declared parameter (‹›), found ‹›, which is not a declared parameter",
        "en la columna ‹›: se esperaba un número o un parámetro declarado (‹›), se encontró ‹›, que no es un parámetro declarado",
    ),
    (
        "‹›: at column ‹›: expected a variable (u, v, w, t, s, x, y, z) or a declared parameter, found ‹›",
        "‹›: en la columna ‹›: se esperaba una variable (u, v, w, t, s, x, y, z) o un parámetro declarado, se encontró ‹›",
    ),
    (
        "‹› is in letters, but this problem declares no parameters",
        "‹› está en letras, pero este problema no declara parámetros",
    ),
    (
        "expected a parameter of one letter (such as \"R\" or \"a\"), found ‹›",
        "se esperaba un parámetro de una letra (como \"R\" o \"a\"), se encontró ‹›",
    ),
    (
        "the parameter ‹› is declared twice",
        "el parámetro ‹› se declara dos veces",
    ),
    (
        "‹› is not a declared parameter (declare it in \"parameters\")",
        "‹› no es un parámetro declarado (declárelo en \"parameters\")",
    ),
    (
        "‹› is declared both as a parameter and as a function",
        "‹› se declara a la vez como parámetro y como función",
    ),
    (
        "‹› takes no functions of u: only ‹› does, for the parametrization $(f(u) cos v, f(u) sin v, g(u))$ of a profile $(f, 0, g)$",
        "‹› no admite funciones de u: solo las admite ‹›, para la parametrización $(f(u) cos v, f(u) sin v, g(u))$ de un perfil $(f, 0, g)$",
    ),
    (
        "‹› takes no functions of u: only ‹› does, for the parametrization (f(u) cos v, f(u) sin v, g(u)) of a profile (f, 0, g)",
        "‹› no admite funciones de u: solo las admite ‹›, para la parametrización (f(u) cos v, f(u) sin v, g(u)) de un perfil (f, 0, g)",
    ),
    (
        "the value ‹› has a denominator that vanishes at these values",
        "el valor ‹› tiene un denominador que se anula en estos valores",
    ),
    (
        "the problem solved with ‹› put in",
        "el problema resuelto sustituyendo ‹›",
    ),
    (
        "for general values of ‹›, ‹› is «»; at ‹› it is «»",
        "para valores generales de ‹›, ‹› es «»; para ‹› es «»",
    ),
    ("yes", "sí"),
    ("no", "no"),
    (
        "the interval ‹› needs a < b: the sign of ‹› is not known (it is in letters; give the letters values, or numbers here)",
        "el intervalo ‹› necesita a < b: el signo de ‹› no se conoce (está en letras; dé valores a las letras, o ponga aquí números)",
    ),
    (
        "the knots must not decrease: the sign of ‹› (knots ‹› and ‹›) is not known (it is in letters; give the letters values, or numbers here)",
        "los nudos no pueden decrecer: el signo de ‹› (nudos ‹› y ‹›) no se conoce (está en letras; dé valores a las letras, o ponga aquí números)",
    ),
    (
        "‹›: the notes' formula gives ‹›, the engine derives ‹› (an erratum found by computing that the fixture does not record)",
        "‹›: la fórmula de los apuntes da ‹›, y el cálculo da ‹› (una errata hallada al calcular que el ejemplo no registra)",
    ),
    (
        "‹›: recorded as an erratum, but the formula as printed gives the derived value",
        "‹›: registrada como errata, pero la fórmula tal como se imprime da el valor calculado",
    ),
    (
        "formula: ‹› is not a result or a step of this problem",
        "fórmula: ‹› no es un resultado ni un paso de este problema",
    ),
    (
        "formula: ‹› is not a polygon or mesh of generic points",
        "fórmula: ‹› no es un polígono ni una malla de puntos genéricos",
    ),
    (
        "formula: ‹› formulas for points of ‹› coordinates",
        "fórmula: ‹› fórmulas para puntos de ‹› coordenadas",
    ),
    (
        "a generic polygon or mesh has degree at most ‹›, found ‹›",
        "un polígono o una malla genéricos tienen grado a lo sumo ‹›, se encontró ‹›",
    ),
    (
        "a generic polygon or mesh has dimension 1, 2, 3 or \"xz\", found ‹›",
        "un polígono o una malla genéricos tienen dimensión 1, 2, 3 o \"xz\", se encontró ‹›",
    ),
    (
        "expected one letter (such as \"c\"), found ‹›",
        "se esperaba una letra (como \"c\"), se encontró ‹›",
    ),
    // --- the problem layer: reading ---
    (
        "missing: name the operation, one of ‹›",
        "falta: indique la operación, una de ‹›",
    ),
    (
        "missing (this operation needs it)",
        "falta (esta operación lo necesita)",
    ),
    (
        "unknown operation ‹› (did you mean ‹›?); the operations are: ‹›",
        "operación desconocida ‹› (¿quería decir ‹›?); las operaciones son: ‹›",
    ),
    (
        "unknown operation ‹›; the operations are: ‹›",
        "operación desconocida ‹›; las operaciones son: ‹›",
    ),
    (
        "unknown key: did you mean ‹›? ‹› takes ‹›",
        "clave desconocida: ¿quería decir ‹›? ‹› admite ‹›",
    ),
    ("unknown key: ‹› takes ‹›", "clave desconocida: ‹› admite ‹›"),
    ("unknown key: ‹›", "clave desconocida: ‹›"),
    (
        "this point has ‹› coordinates but the first has ‹›",
        "este punto tiene ‹› coordenadas, pero el primero tiene ‹›",
    ),
    (
        "row ‹› has ‹› points but row 0 has ‹›: a mesh needs rows of equal length",
        "la fila ‹› tiene ‹› puntos, pero la fila 0 tiene ‹›: las filas de una malla de control han de tener la misma longitud",
    ),
    (
        "row ‹› of the control mesh has ‹› points but row 0 has ‹›: a mesh needs rows of equal length",
        "la fila ‹› de la malla de control tiene ‹› puntos, pero la fila 0 tiene ‹›: las filas de una malla de control han de tener la misma longitud",
    ),
    (
        "‹›: at column ‹›: expected a number (variables are not allowed here), found ‹›",
        "‹›: en la columna ‹›: se esperaba un número (aquí no se admiten variables), se encontró ‹›",
    ),
    (
        "at column ‹›: expected a number (variables are not allowed here), found ‹›",
        "en la columna ‹›: se esperaba un número (aquí no se admiten variables), se encontró ‹›",
    ),
    ("‹›: at column ‹›: «»", "‹›: en la columna ‹›: «»"),
    ("at column ‹›: «»", "en la columna ‹›: «»"),
    ("division by zero", "división por cero"),
    (
        "square root of a negative number (‹›) is not real",
        "la raíz cuadrada de un número negativo (‹›) no es real",
    ),
    (
        "numbers with $‹›$ and $‹›$ cannot be mixed: a problem runs in one field $a + b√d$",
        "no se pueden mezclar números con $‹›$ y con $‹›$: un problema se resuelve en un solo cuerpo $a + b√d$",
    ),
    (
        "this number needs $‹›$, but ‹› needs $‹›$: a problem runs in one field $a + b√d$",
        "este número necesita $‹›$, pero ‹› necesita $‹›$: un problema se resuelve en un solo cuerpo $a + b√d$",
    ),
    ("limit exceeded: «»", "límite superado: «»"),
    (
        "a number of ‹› digits is longer than the limit of ‹› digits",
        "un número de ‹› cifras supera el límite de ‹› cifras",
    ),
    (
        "number at column ‹› has more than ‹› digits",
        "el número de la columna ‹› tiene más de ‹› cifras",
    ),
    (
        "exponent ‹› at column ‹› is larger than ‹›",
        "el exponente ‹› de la columna ‹› es mayor que ‹›",
    ),
    (
        "expression nested deeper than ‹› at column ‹›",
        "expresión anidada a más de ‹› niveles en la columna ‹›",
    ),
    (
        "a number of more than ‹› digits",
        "un número de más de ‹› cifras",
    ),
    (
        "square root argument ‹› is larger than ‹›",
        "el argumento ‹› de la raíz cuadrada es mayor que ‹›",
    ),
    (
        "the power at column ‹› would have more than ‹› digits",
        "la potencia de la columna ‹› tendría más de ‹› cifras",
    ),
    (
        "a list of ‹› items is longer than the limit of ‹›",
        "una lista de ‹› elementos supera el límite de ‹›",
    ),
    (
        "a mesh of ‹› points is larger than the limit of ‹›",
        "una malla de control de ‹› puntos supera el límite de ‹›",
    ),
    (
        "the number ‹› has ‹› digits, more than the limit of ‹› digits",
        "el número ‹› tiene ‹› cifras, más que el límite de ‹› cifras",
    ),
    (
        "the number ‹› has a fraction part; write it as a string (‹›)",
        "el número ‹› tiene parte decimal; escríbalo como cadena (‹›)",
    ),
    (
        "elevating degree ‹› by ‹› gives degree ‹›, above the limit of ‹›",
        "elevar el grado ‹› en ‹› da grado ‹›, por encima del límite de ‹›",
    ),
    (
        "elevating bidegree ‹› by ‹› gives bidegree ‹›, above the limit of ‹›",
        "elevar el bigrado ‹› en ‹› da bigrado ‹›, por encima del límite de ‹›",
    ),
    (
        "not answered within the limit of ‹› s: the work was stopped",
        "sin respuesta dentro del límite de ‹› s: se detuvo el cálculo",
    ),
    (
        "not written within the limit of ‹› s: the answer was found, and writing its key was stopped",
        "sin escribir dentro del límite de ‹› s: se halló la respuesta, y se detuvo al escribirla",
    ),
    (
        "not answered within the memory limit of ‹› MB: the work was stopped holding ‹› MB",
        "sin respuesta dentro del límite de memoria de ‹› MB: se detuvo el cálculo con ‹› MB ocupados",
    ),
    (
        "not written within the memory limit of ‹› MB: the answer was found, and writing its key was stopped holding ‹› MB",
        "sin escribir dentro del límite de memoria de ‹› MB: se halló la respuesta, y se detuvo al escribirla con ‹› MB ocupados",
    ),
    (
        "«» would take ‹› MB, more than the memory limit of ‹› MB: refused before the work",
        "«» ocuparían ‹› MB, más que el límite de memoria de ‹› MB: rechazado antes del cálculo",
    ),
    (
        "the normal equations of the least squares (‹› x ‹› integers of at least ‹› digits each)",
        "las ecuaciones normales de los mínimos cuadrados (‹› x ‹› enteros de al menos ‹› cifras cada uno)",
    ),
    (
        "not solved: the batch holds ‹› problems, more than the limit of ‹›",
        "sin resolver: el lote tiene ‹› problemas, más que el límite de ‹›",
    ),
    ("cannot read the problem: «»", "no se puede leer el problema: «»"),
    (
        "expected a problem object ‹›, found «»",
        "se esperaba un objeto de problema ‹›, se encontró «»",
    ),
    (
        "expected a number, found «»",
        "se esperaba un número, se encontró «»",
    ),
    (
        "expected a string, found «»",
        "se esperaba una cadena, se encontró «»",
    ),
    (
        "expected a point [x, y, z], found «»",
        "se esperaba un punto [x, y, z], se encontró «»",
    ),
    (
        "expected a mesh: a non-empty list of rows of points",
        "se esperaba una malla de control: una lista no vacía de filas de puntos",
    ),
    (
        "expected a non-negative integer, found «»",
        "se esperaba un entero no negativo, se encontró «»",
    ),
    (
        "expected two numbers [a, b], found «»",
        "se esperaban dos números [a, b], se encontró «»",
    ),
    (
        "expected two numbers [u, v] (a surface takes two parameters), found a number",
        "se esperaban dos números [u, v] (una superficie tiene dos parámetros), se encontró un número",
    ),
    (
        "expected a number t (a curve takes one parameter), found a list",
        "se esperaba un número t (una curva tiene un parámetro), se encontró una lista",
    ),
    (
        "expected two integers [m, n], found the number ‹›",
        "se esperaban dos enteros [m, n], se encontró el número ‹›",
    ),
    (
        "expected two integers [r, s], found a list of ‹›",
        "se esperaban dos enteros [r, s], se encontró una lista de ‹›",
    ),
    (
        "expected an integer r or a list [r, s]",
        "se esperaba un entero r o una lista [r, s]",
    ),
    ("expected at least one point", "se esperaba al menos un punto"),
    (
        "a point needs at least one coordinate",
        "un punto necesita al menos una coordenada",
    ),
    (
        "expected a curve: ‹›, found «»",
        "se esperaba una curva: ‹›, se encontró «»",
    ),
    (
        "expected a surface: ‹›, found «»",
        "se esperaba una superficie: ‹›, se encontró «»",
    ),
    ("expected «», found «»", "se esperaba «», se encontró «»"),
    (
        "the weights form a ‹›x‹› grid but the mesh is ‹›x‹›",
        "los pesos forman una matriz de ‹›x‹›, pero la malla de control es de ‹›x‹›",
    ),
    (
        "a rational curve needs one weight per control point: ‹› control points but ‹› weights",
        "una curva racional necesita un peso por punto de control: ‹› puntos de control, pero ‹› pesos",
    ),
    (
        "a NURBS curve needs one weight per control point: ‹› control points but ‹› weights",
        "una curva NURBS necesita un peso por punto de control: ‹› puntos de control, pero ‹› pesos",
    ),
    (
        "weight $w_‹›,‹›$ is zero: weights must be nonzero",
        "el peso $w_‹›,‹›$ es cero: los pesos han de ser no nulos",
    ),
    (
        "weight ‹› is zero: the control point would be a point at infinity",
        "el peso ‹› es cero: el punto de control sería un punto del infinito",
    ),
    (
        "unknown variable ‹› (the variables are u, v, w, t, s, x, y, z; ‹› means u v)",
        "variable desconocida ‹› (las variables son u, v, w, t, s, x, y, z; ‹› es u v)",
    ),
    (
        "division by a polynomial is not a polynomial (divisor ‹›; only nonzero constants can divide)",
        "dividir por un polinomio no da un polinomio (divisor ‹›; solo se puede dividir por constantes no nulas)",
    ),
    (
        "expected ‹›, found end of input",
        "se esperaba ‹›, pero la expresión termina",
    ),
    // --- the problem layer: operations ---
    (
        "give all the curves as expressions or polynomial Bézier curves when one is an expression",
        "cuando una curva es una expresión, dé todas como expresiones o como curvas de Bézier polinómicas",
    ),
    (
        "mixing Bézier and B-spline curves: write the Bézier ones as B-splines (knots [0, ..., 0, 1, ..., 1])",
        "se mezclan curvas de Bézier y B-spline: escriba las de Bézier como B-splines (nudos [0, ..., 0, 1, ..., 1])",
    ),
    (
        "knot insertion needs a B-spline curve (`bspline`, `knots`)",
        "el algoritmo de inserción necesita una curva B-spline (`bspline`, `knots`)",
    ),
    (
        "knot insertion needs a B-spline surface (`bspline`, `knots`)",
        "el algoritmo de inserción necesita una superficie B-spline (`bspline`, `knots`)",
    ),
    (
        "degree elevation needs a control mesh (`bezier` or `bspline`)",
        "la elevación del grado necesita una malla de control (`bezier` o `bspline`)",
    ),
    (
        "a curve given as an expression has no degree to elevate; give its control polygon",
        "una curva dada por una expresión no tiene grado que elevar; dé su polígono de control",
    ),
    (
        "continuity takes two polynomial Bézier patches (`bezier`, no weights), or B-spline or NURBS surfaces",
        "la continuidad se estudia entre dos parches de Bézier polinómicos (`bezier`, sin pesos), o entre superficies B-spline o NURBS",
    ),
    (
        "the developability test takes a ruled Bézier patch of bidegree $(m, 1)$ or a parametric surface",
        "el test de desarrollabilidad necesita un parche de Bézier reglado de bigrado $(m, 1)$ o una superficie paramétrica",
    ),
    (
        "the Coons patch of rational curves has no mesh and weights of its own (notes §5: the projective construction can give zero or negative weights); give polynomial curves",
        "el parche de Coons de curvas racionales no tiene malla de control ni pesos propios (apuntes §5: la construcción proyectiva puede dar pesos nulos o negativos); dé curvas polinómicas",
    ),
    (
        "a quadrant is for `arcs` = 1; ‹› arcs make the full turn",
        "un cuadrante es para `arcs` = 1; ‹› arcos dan la vuelta completa",
    ),
    (
        "restriction is for Bézier curves; split a B-spline at knots with insert_knot",
        "la restricción es para curvas de Bézier; divida una B-spline por sus nudos con insert_knot",
    ),
    (
        "a B-spline surface has one closed form per patch: split it into Bézier patches first",
        "una superficie B-spline tiene una parametrización por parche: divídala antes en parches de Bézier",
    ),
    (
        "a B-spline curve has one closed form per span: split it into Bézier pieces first",
        "una curva B-spline tiene una parametrización por tramo: divídala antes en tramos de Bézier",
    ),
    (
        "closed_form needs a `surface` or a `curve`",
        "closed_form necesita una superficie (`surface`) o una curva (`curve`)",
    ),
    (
        "a grid of points needs the parameters `u` and `v` (a list of points takes `params`)",
        "una malla de datos necesita los parámetros `u` y `v` (una lista de puntos lleva `params`)",
    ),
    (
        "the parameter ‹› repeats entry ‹›: the interpolation system is singular (the parameters must be distinct)",
        "el parámetro ‹› repite el valor ‹›: el sistema de interpolación es singular (los parámetros han de ser distintos)",
    ),
    (
        "the derivative is not defined there: «»",
        "la derivada no está definida ahí: «»",
    ),
    (
        "surfaces of revolution of B-spline profiles are not available yet in this build",
        "las superficies de revolución de perfiles B-spline aún no están disponibles",
    ),
    ("expected a Bézier curve", "se esperaba una curva de Bézier"),
    ("expected a B-spline curve", "se esperaba una curva B-spline"),
    ("expected two curves", "se esperaban dos curvas"),
    ("expected four curves", "se esperaban cuatro curvas"),
    (
        "internal error (a bug of cagd-exact, please report it with this problem): ‹›",
        "error interno (un fallo de cagd-exact; por favor, comuníquelo con este problema): ‹›",
    ),
    // --- the check: mismatches ---
    (
        "nothing to check: the problem has no \"expected\" answer (and no \"formula\")",
        "nada que comprobar: el problema no tiene respuesta esperada (\"expected\") ni fórmula (\"formula\")",
    ),
    (
        "step ‹›: ‹› records no step named ‹› (its steps: ‹›)",
        "paso ‹›: ‹› no registra ningún paso llamado ‹› (sus pasos: ‹›)",
    ),
    (
        "step ‹›: ‹› records no step named ‹› (its steps: ‹› and ‹› more)",
        "paso ‹›: ‹› no registra ningún paso llamado ‹› (sus pasos: ‹› y ‹› más)",
    ),
    (
        "step ‹›: ‹› records no named steps to check",
        "paso ‹›: ‹› no registra pasos con nombre que comprobar",
    ),
    (
        "`steps`: an empty object checks no step; name the steps to check",
        "`steps`: un objeto vacío no comprueba ningún paso; nombre los pasos que comprobar",
    ),
    (
        "`steps`: the steps by name (an object) or the list an answer writes, found «»",
        "`steps`: los pasos por nombre (un objeto) o la lista que escribe una respuesta, se encontró «»",
    ),
    (
        "‹›: a step {\"name\": ..., \"value\": ...}, found «»",
        "‹›: un paso {\"name\": ..., \"value\": ...}, se encontró «»",
    ),
    (
        "`steps`: ‹› steps expected, ‹› computed (a list of steps is compared whole; an object of steps by name checks some)",
        "`steps`: se esperan ‹› pasos, se obtienen ‹› (una lista de pasos se compara entera; un objeto de pasos por nombre comprueba algunos)",
    ),
    (
        "‹›: expected the step ‹›, computed ‹›",
        "‹›: se esperaba el paso ‹›, se obtiene ‹›",
    ),
    (
        "`remarks`: a list of strings (the answer's remarks, not compared), found «»",
        "`remarks`: una lista de cadenas (las observaciones de la respuesta, que no se comparan), se encontró «»",
    ),
    (
        "`derivation`: a list of objects (the answer's worked solution, not compared), found «»",
        "`derivation`: una lista de objetos (la resolución de la respuesta, que no se compara), se encontró «»",
    ),
    // the keywords of a problem echoed in its key (`base = bspline`): those with Spanish words
    ("uniform", "uniformes"),
    ("chord length", "por longitud de cuerda"),
    ("centripetal", "centrípetos"),
    ("linear", "lineales"),
    ("cubic", "cúbicas"),
    ("natural", "naturales"),
    ("Bessel", "de Bessel"),
    ("clamped", "derivadas dadas"),
    ("bicubic", "spline bicúbico"),
    // the sign of G of `gaussian_curvature`, in words
    ("positive (G > 0)", "positivo (G > 0)"),
    ("negative (G < 0)", "negativo (G < 0)"),
    ("none (G vanishes on the domain)", "ninguno (G se anula en el dominio)"),
    ("step ‹›: «»", "paso ‹›: «»"),
    (
        "expected: an empty object checks nothing; name the results to check (‹›)",
        "expected: un objeto vacío no comprueba nada; nombre los resultados que comprobar (‹›)",
    ),
    (
        "`expected`: `remarks` and `derivation` are not compared, so this checks nothing; name the results to check (‹› gives ‹›)",
        "`expected`: `remarks` y `derivation` no se comparan, así que no comprueba nada; nombre los resultados que comprobar (‹› da ‹›)",
    ),
    (
        "expected bidegree ‹›, computed ‹›",
        "se esperaba bigrado ‹›, se obtiene ‹›",
    ),
    (
        "expected degree ‹›, computed ‹›",
        "se esperaba grado ‹›, se obtiene ‹›",
    ),
    (
        "expected knots ‹› and ‹›, computed ‹› and ‹›",
        "se esperaban los nudos ‹› y ‹›, se obtienen ‹› y ‹›",
    ),
    (
        "expected knots ‹›, computed ‹›",
        "se esperaban los nudos ‹›, se obtienen ‹›",
    ),
    (
        "expected weights ‹›, computed ‹›",
        "se esperaban los pesos ‹›, se obtienen ‹›",
    ),
    (
        "expected weights, computed a polynomial surface",
        "se esperaban pesos, se obtiene una superficie polinómica",
    ),
    (
        "expected weights, computed a polynomial curve",
        "se esperaban pesos, se obtiene una curva polinómica",
    ),
    (
        "expected ‹› points, computed ‹›",
        "se esperaban ‹› puntos, se obtienen ‹›",
    ),
    (
        "expected ‹› items, computed ‹›",
        "se esperaban ‹› elementos, se obtienen ‹›",
    ),
    (
        "expected a ‹›x‹› control mesh, computed ‹›x‹›",
        "se esperaba una malla de control de ‹›x‹›, se obtiene una de ‹›x‹›",
    ),
    (
        "expected a ‹›x‹› grid of weights, computed ‹›x‹›",
        "se esperaba una matriz de pesos de ‹›x‹›, se obtiene una de ‹›x‹›",
    ),
    (
        "point ‹›: expected ‹›, computed ‹›",
        "punto ‹›: se esperaba ‹›, se obtiene ‹›",
    ),
    (
        "‹›: expected a value, none computed",
        "‹›: se esperaba un valor, no se obtiene ninguno",
    ),
    (
        "the expected expression ‹› does not parse: «»",
        "la expresión esperada ‹› no se puede leer: «»",
    ),
    ("expected ‹›, computed ‹›", "se esperaba ‹›, se obtiene ‹›"),
    // --- continuity (cagd-surface) ---
    ("not $C^0$", "no es $C^0$"),
    ("$C^‹›$, not $C^‹›$", "$C^‹›$, pero no $C^‹›$"),
    (
        "$C^∞$ (one polynomial surface)",
        "$C^∞$ (una sola superficie polinómica)",
    ),
    ("infinite", "infinito"),
    ("ellipse", "elipse"),
    ("parabola", "parábola"),
    ("hyperbola", "hipérbola"),
    (
        "undecided (the shape factor is in letters)",
        "sin decidir (el factor de forma está en letras)",
    ),
    (
        "$C^‹›$ fails at $‹› = ‹›$: $‹›$ but $‹›$",
        "$C^‹›$ falla en $‹› = ‹›$: $‹›$, pero $‹›$",
    ),
    (
        "the patches do not share a border: along ‹› the first has degree ‹› and the second degree ‹›",
        "los parches no comparten borde: en ‹› el primero tiene grado ‹› y el segundo grado ‹›",
    ),
    // --- remarks of the constructions (cagd-generate) ---
    ("knots in u: ‹›", "nudos en u: ‹›"),
    ("knots in v: ‹›", "nudos en v: ‹›"),
    (
        "$‹›$ elevated from degree ‹› to ‹›",
        "$‹›$ elevada de grado ‹› a grado ‹›",
    ),
    ("$‹›$: knots ‹› inserted", "$‹›$: se insertan los nudos ‹›"),
    // --- errors of the surfaces, curves and constructions ---
    (
        "curves ‹› and ‹› do not meet at corner ‹›: $‹›$, $‹›$",
        "las curvas ‹› y ‹› no se cortan en la esquina ‹›: $‹›$, $‹›$",
    ),
    (
        "the curves do not meet: $‹›$ = $‹›$ but $‹›$ = $‹›$",
        "las curvas no se cortan: $‹›$ = $‹›$, pero $‹›$ = $‹›$",
    ),
    ("not a ruled surface: «»", "no es una superficie reglada: «»"),
    ("not a circle: «»", "no es una circunferencia: «»"),
    ("not a circular arc: «»", "no es un arco de circunferencia: «»"),
    (
        "the radius ‹› is not positive",
        "el radio ‹› no es positivo",
    ),
    ("the control mesh is empty", "la malla de control está vacía"),
    (
        "control point $c_‹›,‹›$ has ‹› coordinates but $c_0,0$ has ‹›",
        "el punto de control $c_‹›,‹›$ tiene ‹› coordenadas, pero $c_0,0$ tiene ‹›",
    ),
    (
        "parameter ‹› = ‹› is outside the domain ‹›",
        "el parámetro ‹› = ‹› está fuera del recinto ‹›",
    ),
    (
        "parameter t = ‹› is outside the domain ‹›",
        "el parámetro t = ‹› está fuera del dominio ‹›",
    ),
    (
        "the denominator of the rational patch vanishes at ‹›: the point is at infinity",
        "el denominador del parche racional se anula en ‹›: el punto está en el infinito",
    ),
    (
        "the denominator of the rational curve vanishes at t = ‹›: the point is at infinity",
        "el denominador de la curva racional se anula en t = ‹›: el punto está en el infinito",
    ),
    (
        "the interval ‹› of ‹› is degenerate: its ends must satisfy ‹›",
        "el intervalo ‹› de ‹› es degenerado: sus extremos han de cumplir ‹›",
    ),
    (
        "the interval ‹› is degenerate: its ends must satisfy ‹›",
        "el intervalo ‹› es degenerado: sus extremos han de cumplir ‹›",
    ),
    (
        "subdivision parameter ‹› = ‹› must lie strictly inside ‹›",
        "el parámetro de subdivisión ‹› = ‹› ha de estar en el interior de ‹›",
    ),
    (
        "the polar form takes ‹› values of ‹› (the degree in ‹›), but ‹› were given",
        "la forma polar toma ‹› valores de ‹› (el grado en ‹›), pero se dieron ‹›",
    ),
    (
        "the differences $Δ^{‹›}$ need bidegree at least ‹›, but the patch has bidegree ‹›",
        "las diferencias $Δ^{‹›}$ necesitan bigrado al menos ‹›, pero el parche tiene bigrado ‹›",
    ),
    (
        "f has degree ‹› in ‹›: its graph needs degree at least ‹› in ‹›, but the patch has degree ‹›",
        "f tiene grado ‹› en ‹›: su gráfica necesita grado al menos ‹› en ‹›, pero el parche tiene grado ‹›",
    ),
    (
        "‹› must be positive, but it is ‹›",
        "‹› ha de ser positivo, pero es ‹›",
    ),
    (
        "the control polygon is empty: a Bézier curve needs at least one control point",
        "el polígono de control está vacío: una curva de Bézier necesita al menos un punto de control",
    ),
    (
        "control point ‹› has dimension ‹› but control point 0 has dimension ‹›",
        "el punto de control ‹› tiene dimensión ‹›, pero el punto de control 0 tiene dimensión ‹›",
    ),
    (
        "degree ‹› is not allowed: a B-spline curve needs degree at least 1",
        "el grado ‹› no es válido: una curva B-spline necesita grado al menos 1",
    ),
    (
        "a B-spline curve of degree ‹› needs at least ‹› control points, found ‹›",
        "una curva B-spline de grado ‹› necesita al menos ‹› puntos de control, se encontraron ‹›",
    ),
    (
        "knot vector decreases at index ‹›: ‹›",
        "la sucesión de nudos decrece en la posición ‹›: ‹›",
    ),
    (
        "the knot vector is made for ‹› control points, but ‹› were given",
        "la sucesión de nudos es para ‹› puntos de control, pero se dieron ‹›",
    ),
    (
        "knot ‹› is not inside the domain ‹› of the curve",
        "el nudo ‹› no está en el interior del dominio ‹› de la curva",
    ),
    (
        "knot vector in ‹›: «»",
        "sucesión de nudos en ‹›: «»",
    ),
    (
        "the linear system is singular (no unique solution): ‹›",
        "el sistema lineal es singular (no tiene solución única): ‹›",
    ),
    (
        "no data points: a fit needs at least one point",
        "no hay datos: un ajuste necesita al menos un punto",
    ),
    (
        "«» needs at least ‹› data points, found ‹›",
        "«» necesita al menos ‹› puntos de datos, se encontraron ‹›",
    ),
    (
        "the data grid has ‹› rows and ‹› columns, but ‹› parameters $u_i$ and ‹› parameters $v_j$ were given: row i of the data is $c(u_i, v_0)$, ..., $c(u_i, v_n)$, so give one $u_i$ per row and one $v_j$ per column",
        "la malla de datos tiene ‹› filas y ‹› columnas, pero se dieron ‹› parámetros $u_i$ y ‹› parámetros $v_j$: la fila i de los datos es $c(u_i, v_0)$, ..., $c(u_i, v_n)$, así que dé un $u_i$ por fila y un $v_j$ por columna",
    ),
    // what needs the data points, translated in turn
    (
        "least squares by «»",
        "el ajuste por mínimos cuadrados con «»",
    ),
    (
        "a B-spline surface of bidegree ‹› with ‹› x ‹› control points",
        "una superficie B-spline de bigrado ‹› con ‹› x ‹› puntos de control",
    ),
    (
        "a patch of bidegree ‹› (‹› unknown control points)",
        "un parche de bigrado ‹› (‹› puntos de control incógnita)",
    ),
    (
        "least squares of degree ‹› (‹› unknown control points)",
        "el ajuste por mínimos cuadrados de grado ‹› (‹› puntos de control incógnita)",
    ),
    (
        "least squares with ‹› unknown control points (degree ‹›)",
        "el ajuste por mínimos cuadrados con ‹› puntos de control incógnita (grado ‹›)",
    ),
    (
        "interpolation by a patch of bidegree ‹› with scattered parameters (‹› control points)",
        "la interpolación por un parche de bigrado ‹› con parámetros dispersos (‹› puntos de control)",
    ),
    (
        "a Bessel end tangent (the parabola through three points)",
        "una tangente extrema de Bessel (la parábola por tres puntos)",
    ),
    (
        "a cubic spline interpolant",
        "un spline cúbico interpolante",
    ),
    (
        "a Bessel end in ‹› (the parabola through three parameters ‹›)",
        "un extremo de Bessel en ‹› (la parábola por tres parámetros ‹›)",
    ),
    (
        "a cubic spline in ‹›",
        "un spline cúbico en ‹›",
    ),
    (
        "the length of segment ‹› to ‹› is rational and the first's is in √‹›: their ratio, and so the parameters, are in no quadratic field (the parameters are exact when the lengths are rational multiples of one square root)",
        "la longitud del segmento ‹› a ‹› es racional y la del primero está en √‹›: su cociente, y con él los parámetros, no está en ningún cuerpo cuadrático (los parámetros son exactos cuando las longitudes son múltiplos racionales de una misma raíz cuadrada)",
    ),
    (
        "the length of segment ‹› to ‹› is in √‹› and the first's is rational: their ratio, and so the parameters, are in no quadratic field (the parameters are exact when the lengths are rational multiples of one square root)",
        "la longitud del segmento ‹› a ‹› está en √‹› y la del primero es racional: su cociente, y con él los parámetros, no está en ningún cuerpo cuadrático (los parámetros son exactos cuando las longitudes son múltiplos racionales de una misma raíz cuadrada)",
    ),
    (
        "the length of segment ‹› to ‹› is in √‹› and the first's is in √‹›: their ratio, and so the parameters, are in no quadratic field (the parameters are exact when the lengths are rational multiples of one square root)",
        "la longitud del segmento ‹› a ‹› está en √‹› y la del primero en √‹›: su cociente, y con él los parámetros, no está en ningún cuerpo cuadrático (los parámetros son exactos cuando las longitudes son múltiplos racionales de una misma raíz cuadrada)",
    ),
    (
        "the polynomial has degree ‹› in ‹›, more than the degree ‹› of the Bernstein basis",
        "el polinomio tiene grado ‹› en ‹›, más que el grado ‹› de la base de Bernstein",
    ),
    (
        "the denominator vanishes ‹›",
        "el denominador se anula ‹›",
    ),
    // --- fragments: what was found, what was expected ---
    ("a list of ‹›", "una lista de ‹›"),
    ("the number ‹›", "el número ‹›"),
    ("the string ‹›", "la cadena ‹›"),
    ("an object", "un objeto"),
    ("a string", "una cadena"),
    ("a number", "un número"),
    ("a list", "una lista"),
    ("true or false", "true o false"),
    ("an integer r or a list [r, s]", "un entero r o una lista [r, s]"),
    ("a number t or a pair [u, v]", "un número t o un par [u, v]"),
    ("a point [x, y, z]", "un punto [x, y, z]"),
    ("a non-negative integer", "un entero no negativo"),
    ("an expression", "una expresión"),
    ("a list of points", "una lista de puntos"),
    ("a parametric surface", "una superficie paramétrica"),
    ("a Bézier surface", "una superficie de Bézier"),
    ("a rational Bézier surface", "una superficie de Bézier racional"),
    ("a B-spline surface", "una superficie B-spline"),
    ("a NURBS surface", "una superficie NURBS"),
    // --- more of the reading ---
    (
        "the number ‹› has a fraction part; write it as a string (‹›) so it is read exactly",
        "el número ‹› tiene parte decimal; escríbalo como cadena (‹›) para leerlo exactamente",
    ),
    (
        "‹› weights for ‹› control points",
        "‹› pesos para ‹› puntos de control",
    ),
    (
        "a curve of degree ‹› with ‹› control points needs ‹› knots (the notes' convention, without end knots) or ‹› (with one more knot at each end, as in The NURBS Book); found ‹›",
        "una curva de grado ‹› con ‹› puntos de control necesita ‹› nudos (el convenio de los apuntes, sin nudos extremos) o ‹› (con un nudo más en cada extremo, como en el libro de Piegl y Tiller); se dieron ‹›",
    ),
    (
        "knot ‹› appears ‹› times, but a curve of degree ‹› allows at most ‹› (the notes' convention, without end knots)",
        "el nudo ‹› aparece ‹› veces, pero una curva de grado ‹› admite como mucho ‹› (el convenio de los apuntes, sin nudos extremos)",
    ),
    (
        "the domain ‹› of the knot vector is empty: its ends must differ",
        "el dominio ‹› de la sucesión de nudos es vacío: sus extremos han de ser distintos",
    ),
    (
        "numbers with $‹›$ and $‹›$ cannot be mixed: an expression runs in one field $a + b√d$",
        "no se pueden mezclar números con $‹›$ y con $‹›$: una expresión se calcula en un solo cuerpo $a + b√d$",
    ),
    (
        "row ‹› of the weights has ‹› entries but row 0 has ‹›",
        "la fila ‹› de los pesos tiene ‹› elementos, pero la fila 0 tiene ‹›",
    ),
    (
        "row ‹› of the control mesh has ‹› points but row 0 has ‹›",
        "la fila ‹› de la malla de control tiene ‹› puntos, pero la fila 0 tiene ‹›",
    ),
    ("‹›: not a result of this problem (‹› gives ‹›)", "‹›: no es un resultado de este problema (‹› da ‹›)"),
    ("‹›: «»", "‹›: «»"),
    // --- more of the problem layer and of the engine ---
    ("expected another kind of curve", "se esperaba otra clase de curva"),
    (
        "expected a grid of points (rows of points) for the parameters u and v",
        "se esperaba una malla de puntos (filas de puntos) para los parámetros u y v",
    ),
    (
        "expected two knot vectors [[u knots], [v knots]], found a list of ‹›",
        "se esperaban dos sucesiones de nudos [[nudos en u], [nudos en v]], se encontró una lista de ‹›",
    ),
    (
        "expected two integers [m, n] for a patch, found the number ‹›",
        "se esperaban dos enteros [m, n] para un parche, se encontró el número ‹›",
    ),
    (
        "expected a list [r, s], found the number ‹›",
        "se esperaba una lista [r, s], se encontró el número ‹›",
    ),
    (
        "expected a number t (the first parameter is a number), found a list",
        "se esperaba un número t (el primer parámetro es un número), se encontró una lista",
    ),
    (
        "expected two numbers [u, v], found a number",
        "se esperaban dos números [u, v], se encontró un número",
    ),
    (
        "derivatives of rational and B-spline curves are given by `evaluate`-ing their closed form; not available as a curve yet",
        "las derivadas de curvas racionales y B-spline se obtienen evaluando (`evaluate`) su parametrización; aún no están disponibles como curva",
    ),
    (
        "the center of a circle needs at least two coordinates",
        "el centro de una circunferencia necesita al menos dos coordenadas",
    ),
    (
        "points of dimension ‹› here, but row 0 has dimension ‹›",
        "aquí hay puntos de dimensión ‹›, pero la fila 0 tiene dimensión ‹›",
    ),
    ("item ‹›: «»", "elemento ‹›: «»"),
    ("at ‹›: «»", "en ‹›: «»"),
    (
        "the developability test takes polynomial curves (expressions or Bézier curves)",
        "el test de desarrollabilidad necesita curvas polinómicas (expresiones o curvas de Bézier)",
    ),
    (
        "the blossom of a curve of degree ‹› takes ‹› arguments, but ‹› were given",
        "la forma polar de una curva de grado ‹› toma ‹› argumentos, pero se dieron ‹›",
    ),
    (
        "subdivision parameter t = ‹› must lie strictly inside the domain ‹›",
        "el parámetro de subdivisión t = ‹› ha de estar en el interior del dominio ‹›",
    ),
    (
        "the denominator w(t) of the rational curve vanishes at t = ‹›: c(t) is a point at infinity",
        "el denominador w(t) de la curva racional se anula en t = ‹›: c(t) es un punto del infinito",
    ),
    (
        "homogeneous control points need at least one coordinate: the weight, written last",
        "los puntos de control homogéneos necesitan al menos una coordenada: el peso, escrito el último",
    ),
    (
        "knot ‹› cannot be removed ‹› time(s): it has multiplicity ‹›",
        "el nudo ‹› no se puede eliminar ‹› vez (veces): tiene multiplicidad ‹›",
    ),
    (
        "knot ‹› cannot be removed (after ‹› removal(s)) without changing the curve",
        "el nudo ‹› no se puede eliminar (tras ‹› eliminación(es)) sin cambiar la curva",
    ),
    (
        "the derivative is not a B-spline curve: «»",
        "la derivada no es una curva B-spline: «»",
    ),
    (
        "parameter u_‹› = ‹› is outside the domain ‹› of the knot vector",
        "el parámetro u_‹› = ‹› está fuera del dominio ‹› de la sucesión de nudos",
    ),
    ("in ‹› (‹›): «»", "en ‹› (‹›): «»"),
    (
        "not a single Bézier patch in ‹›: «»",
        "no es un solo parche de Bézier en ‹›: «»",
    ),
    (
        "no value given for the variable ‹›",
        "no se ha dado valor a la variable ‹›",
    ),
    (
        "the polynomial depends on ‹›, but the Bernstein basis is in ‹› only",
        "el polinomio depende de ‹›, pero la base de Bernstein solo es en ‹›",
    ),
    (
        "the interval [‹›, ‹›] has length zero: cannot reparametrize onto it",
        "el intervalo [‹›, ‹›] tiene longitud cero: no se puede reparametrizar sobre él",
    ),
    (
        "the power $‹›$, above the exponent limit of ‹›",
        "la potencia $‹›$, por encima del límite de exponentes de ‹›",
    ),
    (
        "a coefficient: a number of more than ‹› digits",
        "un coeficiente: un número de más de ‹› cifras",
    ),
    (
        "expression too large to expand: «»",
        "expresión demasiado grande para desarrollarla: «»",
    ),
    ("‹› is empty", "‹› está vacío"),
    (
        "‹›: expected dimension ‹›, found ‹›",
        "‹›: se esperaba dimensión ‹›, se encontró ‹›",
    ),
    (
        "row ‹› has ‹› entries but row 0 has ‹›: a matrix needs rows of equal length",
        "la fila ‹› tiene ‹› elementos, pero la fila 0 tiene ‹›: las filas de una matriz han de tener la misma longitud",
    ),
    (
        "the two variables of a tensor-product Bernstein basis must differ, both are ‹›",
        "las dos variables de una base de Bernstein de producto tensorial han de ser distintas; ambas son ‹›",
    ),
    ("a patch of bidegree ‹›", "un parche de bigrado ‹›"),
    ("the graph of bidegree ‹›", "la gráfica de bigrado ‹›"),
    ("the elevated patch of bidegree ‹›", "el parche elevado de bigrado ‹›"),
    ("the elevated curve", "la curva elevada"),
    ("the surface of revolution", "la superficie de revolución"),
    ("the curve with the knot inserted", "la curva con el nudo insertado"),
    ("the surface with the knot inserted", "la superficie con el nudo insertado"),
    ("the derivative as a surface", "la derivada como superficie"),
    ("the first number that needs √d", "el primer número que necesita √d"),
    ("the operation", "la operación"),
    // --- the command line ---
    (
        "cannot read ‹›: No such file or directory (os error 2)",
        "no se puede leer ‹›: el archivo no existe",
    ),
    ("cannot read standard input: ‹›", "no se puede leer la entrada estándar: ‹›"),
    ("cannot read ‹›: ‹›", "no se puede leer ‹›: ‹›"),
    (
        "standard input: not valid JSON at line ‹›, column ‹›, in problem ‹› of the batch (the \
         problems before it are answered): ‹›",
        "entrada estándar: JSON no válido en la línea ‹›, columna ‹›, en el problema ‹› del lote \
         (los problemas anteriores están respondidos): ‹›",
    ),
    (
        "‹›: not valid JSON at line ‹›, column ‹›, in problem ‹› of the batch (the problems \
         before it are answered): ‹›",
        "‹›: JSON no válido en la línea ‹›, columna ‹›, en el problema ‹› del lote (los \
         problemas anteriores están respondidos): ‹›",
    ),
    (
        "standard input: not valid JSON at line ‹›, column ‹›: ‹›",
        "entrada estándar: JSON no válido en la línea ‹›, columna ‹›: ‹›",
    ),
    (
        "‹›: not valid JSON at line ‹›, column ‹›: ‹›",
        "‹›: JSON no válido en la línea ‹›, columna ‹›: ‹›",
    ),
    (
        "standard input is not UTF-8 (it looks like ‹›): save it as UTF-8",
        "la entrada estándar no está en UTF-8 (parece ‹›): guárdela en UTF-8",
    ),
    (
        "‹› is not UTF-8 (it looks like ‹›): save it as UTF-8",
        "‹› no está en UTF-8 (parece ‹›): guárdelo en UTF-8",
    ),
    (
        "standard input is not UTF-8: byte ‹› at line ‹›, column ‹› (it looks like ‹›): save it as UTF-8",
        "la entrada estándar no está en UTF-8: byte ‹› en la línea ‹›, columna ‹› (parece ‹›): guárdela en UTF-8",
    ),
    (
        "‹› is not UTF-8: byte ‹› at line ‹›, column ‹› (it looks like ‹›): save it as UTF-8",
        "‹› no está en UTF-8: byte ‹› en la línea ‹›, columna ‹› (parece ‹›): guárdelo en UTF-8",
    ),
    (
        "the file is not UTF-8: byte ‹› at line ‹›, column ‹› (it looks like ‹›): save it as UTF-8",
        "el archivo no está en UTF-8: byte ‹› en la línea ‹›, columna ‹› (parece ‹›): guárdelo en UTF-8",
    ),
    (
        "no example is called ‹› (see cagd examples --list)",
        "ningún ejemplo se llama ‹› (vea cagd examples --list)",
    ),
    (
        "unknown topic ‹›; the topics are: ‹›",
        "tema desconocido ‹›; los temas son: ‹›",
    ),
    (
        "‹› problems asked for; a set has at most ‹› problems",
        "se piden ‹› problemas; una colección tiene como mucho ‹› problemas",
    ),
    (
        "could not draw problem ‹› of topic ‹› with friendly numbers in ‹› attempts (last: ‹›); try another seed",
        "no se pudo sortear el problema ‹› del tema ‹› con números sencillos en ‹› intentos (el último: ‹›); pruebe otra semilla",
    ),
    (
        "‹› takes the path of a file, found an empty one",
        "‹› lleva la ruta de un archivo, y se encontró una vacía",
    ),
    (
        "‹› takes the path of a folder, found an empty one",
        "‹› lleva la ruta de una carpeta, y se encontró una vacía",
    ),
    (
        "the problem set is not written, as its figures cannot be: «»",
        "la colección no se escribe, porque sus figuras no se pueden escribir: «»",
    ),
    (
        "‹› ‹› and ‹› ‹› are the same file: give each output a file of its own",
        "‹› ‹› y ‹› ‹› son el mismo archivo: dé a cada salida un archivo propio",
    ),
    (
        "‹› ‹› is the input file: give the output another name",
        "‹› ‹› es el archivo de entrada: dé otro nombre a la salida",
    ),
    ("cannot create ‹›: ‹›", "no se puede crear ‹›: ‹›"),
    ("cannot write ‹›: ‹›", "no se puede escribir ‹›: ‹›"),
    // --- remarks of the keys ---
    (
        "the knots are printed as the data gives them, with one more knot at each end than the notes' convention (Piegl and Tiller's)",
        "los nudos se dan como en los datos, con un nudo más en cada extremo que en el convenio de los apuntes (el de Piegl y Tiller)",
    ),
    // --- errata found by computing (formula fixtures) ---
    ("(‹›) at (‹›)", "(‹›) en (‹›)"),
    (
        "the formula as printed, ‹›, gives ‹› there; the engine derives ‹›",
        "la fórmula tal como está impresa, ‹›, da ahí ‹›; el cálculo da ‹›",
    ),
    // --- remarks on the reading ---
    (
        "‹› is read exactly as ‹›; if ‹› is meant, write ‹›",
        "‹› se lee exactamente como ‹›; si se quiere decir ‹›, escriba ‹›",
    ),
    // --- normals (cagd-surface) ---
    (
        "degenerate at ‹›: «»; the limit direction of the normal along $‹›$ is $‹›$",
        "degenerado en ‹›: «»; la dirección límite del vector normal a lo largo de $‹›$ es $‹›$",
    ),
    ("degenerate at ‹›: «»", "degenerado en ‹›: «»"),
    (
        "the vertices $‹›$ and $‹›$ coincide, so a difference of (25) is the zero vector",
        "los vértices $‹›$ y $‹›$ coinciden, así que una diferencia de (25) es el vector nulo",
    ),
    (
        "the vertices $‹›$, $‹›$, $‹›$ are collinear, so the differences of (25) are parallel",
        "los vértices $‹›$, $‹›$, $‹›$ están alineados, así que las diferencias de (25) son paralelas",
    ),
    (
        "the patch has degree 0 in ‹›: it has no tangent direction in ‹›",
        "el parche tiene grado 0 en ‹›: no tiene dirección tangente en ‹›",
    ),
    (
        "‹› must be a curve in ‹›, but it uses ‹›",
        "‹› ha de ser una curva en ‹›, pero usa ‹›",
    ),
    // --- triangle column: triangular patches (restrict, isocurve, reverse, graph, rational,
    // reduce_degree, gaussian_curvature) and the reversal of surfaces ---
    (
        "K has the sign of the numerator G: positive where the surface is elliptic, negative where it is hyperbolic, zero where it is parabolic or flat",
        "K tiene el signo del numerador G: positivo donde la superficie es elíptica, negativo donde es hiperbólica, nulo donde es parabólica o plana",
    ),
    (
        "‹› rows of weights for a net of ‹› rows (one weight per control point, in the same rows)",
        "‹› filas de pesos para una red de ‹› filas (un peso por punto de control, en las mismas filas)",
    ),
    (
        "row ‹› of the weights holds ‹› numbers (one per point of row ‹› of the net), found ‹›",
        "la fila ‹› de los pesos tiene ‹› números (uno por punto de la fila ‹› de la red), hay ‹›",
    ),
    (
        "the weight w_{‹›} is zero: weights must be nonzero",
        "el peso w_{‹›} es nulo: los pesos han de ser no nulos",
    ),
    (
        "a rational triangular patch has no `‹›` here: its derivatives are quotients (the quotient rule mixes the weights in), not a net of this form; take its `closed_form`, a quotient",
        "una superficie triangular racional no tiene aquí `‹›`: sus derivadas son cocientes (la regla del cociente mezcla los pesos), no una red de esta forma; pida su `closed_form`, un cociente",
    ),
    (
        "the weight (the denominator Σ w_{ijk} B_{ijk}) is zero here: the rational patch has no point there",
        "el peso (el denominador Σ w_{ijk} B_{ijk}) es nulo aquí: la superficie racional no tiene punto ahí",
    ),
    (
        "a triangular patch is restricted to a sub-triangle: give `vertices`, three points [u, v] (or [r, s, t]) of its domain, not intervals",
        "una superficie triangular se restringe a un subtriángulo: dé `vertices`, tres puntos [u, v] (o [r, s, t]) de su dominio, no intervalos",
    ),
    (
        "expected the three vertices a, b, c of the sub-triangle, found ‹› points",
        "se esperaban los tres vértices a, b, c del subtriángulo, hay ‹› puntos",
    ),
    (
        "`w` = 1 - u - v fixes an iso-line of a triangular patch: give `triangle` (a tensor-product `surface` takes `u` or `v`)",
        "`w` = 1 - u - v fija una isolínea de una superficie triangular: dé `triangle` (una superficie producto tensorial `surface` admite `u` o `v`)",
    ),
    (
        "missing (give `u`, `v` or `w` = 1 - u - v: the iso-line where it is constant)",
        "falta (dé `u`, `v` o `w` = 1 - u - v: la isolínea en la que es constante)",
    ),
    (
        "give one of `u`, `v`, `w` (an iso-line), not two: two fix a point (`evaluate`)",
        "dé uno de `u`, `v`, `w` (una isolínea), no dos: dos fijan un punto (`evaluate`)",
    ),
    (
        "expected a permutation of [1, 2, 3] (the old vertices in their new order), found ‹›",
        "se esperaba una permutación de [1, 2, 3] (los vértices antiguos en su nuevo orden), hay ‹›",
    ),
    (
        "expected the three vertices [x, y] of a triangle, found ‹› points of dimensions ‹›",
        "se esperaban los tres vértices [x, y] de un triángulo, hay ‹› puntos de dimensiones ‹›",
    ),
    (
        "the three vertices are collinear: they bound no triangle",
        "los tres vértices están alineados: no limitan ningún triángulo",
    ),
    (
        "expected one integer n (a triangular patch has one degree), found a list of 2",
        "se esperaba un entero n (una superficie triangular tiene un solo grado), hay una lista de 2",
    ),
    (
        "f has total degree ‹›, more than the degree ‹› asked for: its graph is a triangular patch of degree ‹› or more",
        "f tiene grado total ‹›, mayor que el grado ‹› pedido: su gráfica es una superficie triangular de grado ‹› o mayor",
    ),
    (
        "a patch of degree ‹› cannot be reduced by ‹›",
        "una superficie de grado ‹› no puede reducirse en ‹›",
    ),
    (
        "the closed form has total degree ‹›, more than ‹›: no patch of degree ‹› is the same surface, so there is no exact reduction (a least-squares reduction of triangular nets is not available)",
        "la forma cerrada tiene grado total ‹›, mayor que ‹›: ninguna superficie de grado ‹› es la misma, así que no hay reducción exacta (la reducción por mínimos cuadrados de redes triangulares no está disponible)",
    ),
    (
        "the closed form (homogeneous: of (w b, w)) has total degree ‹›, more than ‹›: no patch of degree ‹› is the same surface, so there is no exact reduction (a least-squares reduction of triangular nets is not available)",
        "la forma cerrada (homogénea: de (w b, w)) tiene grado total ‹›, mayor que ‹›: ninguna superficie de grado ‹› es la misma, así que no hay reducción exacta (la reducción por mínimos cuadrados de redes triangulares no está disponible)",
    ),
    (
        "missing (give \"u\" to reverse the rows of the mesh, c̃(u, v) = c(a + b - u, v), or \"v\" to reverse each row, c̃(u, v) = c(u, c + d - v))",
        "falta (dé \"u\" para invertir el orden de las filas de la malla, c̃(u, v) = c(a + b - u, v), o \"v\" para invertir cada fila, c̃(u, v) = c(u, c + d - v))",
    ),
];

/// The parts of a format: literal text (with its `$` marks) and holes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Part<'a> {
    Lit(&'a str),
    Hole,
    Sentence,
}

fn parts(format: &str) -> Vec<Part<'_>> {
    let mut out = Vec::new();
    let mut rest = format;
    while let Some(i) = rest.find(['‹', '«']) {
        let (lit, tail) = rest.split_at(i);
        if !lit.is_empty() {
            out.push(Part::Lit(lit));
        }
        if let Some(t) = tail.strip_prefix("‹›") {
            out.push(Part::Hole);
            rest = t;
        } else if let Some(t) = tail.strip_prefix("«»") {
            out.push(Part::Sentence);
            rest = t;
        } else {
            // a lone mark is literal
            let n = tail.chars().next().map_or(1, char::len_utf8);
            let (mark, t) = tail.split_at(n);
            out.push(Part::Lit(mark));
            rest = t;
        }
    }
    if !rest.is_empty() {
        out.push(Part::Lit(rest));
    }
    out
}

/// Matches `msg` against the parts (their `$` marks ignored), returning the captures.
fn capture<'m>(ps: &[Part<'_>], msg: &'m str, caps: &mut Vec<&'m str>) -> bool {
    match ps.split_first() {
        None => msg.is_empty(),
        Some((Part::Lit(l), rest)) => {
            let l = l.replace('$', "");
            match msg.strip_prefix(l.as_str()) {
                Some(m) => capture(rest, m, caps),
                None => false,
            }
        }
        Some((_, rest)) => {
            // the shortest capture first; a hole is never empty
            let next = rest.first().and_then(|p| match p {
                Part::Lit(l) => Some(l.replace('$', "")),
                _ => None,
            });
            let ends: Vec<usize> = match &next {
                None if rest.is_empty() => vec![msg.len()],
                None => msg.char_indices().map(|(i, _)| i).skip(1).collect(),
                Some(l) => msg.match_indices(l.as_str()).map(|(i, _)| i).collect(),
            };
            for end in ends {
                if end == 0 {
                    continue;
                }
                let Some(cap) = msg.get(..end) else { continue };
                caps.push(cap);
                if msg.get(end..).is_some_and(|m| capture(rest, m, caps)) {
                    return true;
                }
                caps.pop();
            }
            false
        }
    }
}

/// Builds a sentence from a format and its captures.
fn build(format: &str, caps: &[&str], lang: Lang) -> Sentence {
    let (mut text, mut latex) = (String::new(), String::new());
    // the mathematics between two `$`, converted whole when it closes
    let mut math: Option<String> = None;
    let mut k = 0;
    let mut next = || {
        let c = caps.get(k).copied().unwrap_or_default();
        k += 1;
        c
    };
    for p in parts(format) {
        match p {
            Part::Lit(l) => {
                for (i, piece) in l.split('$').enumerate() {
                    if i > 0 {
                        math = match math.take() {
                            Some(m) => {
                                latex += &format!("${}$", math_latex(&m));
                                None
                            }
                            None => Some(String::new()),
                        };
                    }
                    text += piece;
                    match &mut math {
                        Some(m) => m.push_str(piece),
                        None => latex += &crate::escape_latex(piece),
                    }
                }
            }
            Part::Hole => {
                let c = next();
                text += c;
                match &mut math {
                    Some(m) => m.push_str(c),
                    None => latex += &text_latex(c),
                }
            }
            Part::Sentence => {
                let s = sentence(next(), lang);
                text += &s.text;
                latex += &s.latex;
            }
        }
    }
    if let Some(m) = math {
        latex += &format!("${}$", math_latex(&m));
    }
    Sentence { text, latex }
}

/// A sentence of the engine in the language asked, as text and as LaTeX: through the
/// catalogue when its format is there, else as it is (its math-looking words in math mode).
pub fn sentence(msg: &str, lang: Lang) -> Sentence {
    // the flag a front end names after a limit's message: `... (raise it with --max-batch)`
    if let Some((m, flag)) = msg
        .strip_suffix(')')
        .and_then(|m| m.rsplit_once(" (raise it with "))
    {
        let s = sentence(m, lang);
        let raise = match lang {
            Lang::En => "raise it with",
            Lang::Es => "súbalo con",
        };
        return Sentence {
            text: format!("{} ({raise} {flag})", s.text),
            latex: format!(
                "{} ({raise} \\texttt{{{}}})",
                s.latex,
                crate::escape_latex(flag)
            ),
        };
    }
    // of the formats that match, the most specific: the most words of its own
    let own = |f: &str| {
        f.chars()
            .filter(|c| !matches!(c, '‹' | '›' | '«' | '»' | '$'))
            .count()
    };
    let mut best: Option<(usize, &str, &str, Vec<&str>)> = None;
    for (en, es) in SENTENCES {
        let mut caps = Vec::new();
        if capture(&parts(en), msg, &mut caps) && best.as_ref().is_none_or(|b| own(en) > b.0) {
            best = Some((own(en), en, es, caps));
        }
    }
    if let Some((_, en, es, caps)) = best {
        let format = match lang {
            Lang::En => en,
            Lang::Es => es,
        };
        return build(format, &caps, lang);
    }
    Sentence {
        text: msg.to_string(),
        latex: text_latex(msg),
    }
}

/// Text of unknown make for LaTeX's text mode: its math-looking words typeset, the rest
/// escaped ([`crate::tex::words`], the one escaper).
pub fn text_latex(s: &str) -> String {
    crate::tex::words(s)
}

/// The engine's plain-text mathematics as LaTeX (math mode), through the whitelist typesetter
/// [`crate::tex::math`]: `Δ^{1,0} c~_{0,1}` → `\Delta ^{1,0} \tilde{c}_{0,1}`, `√2/2` →
/// `\sqrt{2}/2`, `c_1,m-1` → `c_{1,m-1}`, sets in braces as `\{...\}`.
///
/// ```
/// use cagd_keys::catalogue::math_latex;
/// assert_eq!(math_latex("Δ^{1,0} c~_{0,1}"), "\\Delta ^{1,0} \\tilde{c}_{0,1}");
/// assert_eq!(math_latex("√2/2"), "\\sqrt{2}/2");
/// assert_eq!(math_latex("c_1,2^{1,0}"), "c_{1,2}^{1,0}");
/// assert_eq!(math_latex("{c_1m, c_2m}"), "\\{c_{1m}, c_{2m}\\}");
/// ```
pub fn math_latex(s: &str) -> String {
    crate::tex::math(s)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_sentence_with_an_inner_sentence() {
        let s = sentence(
            "cannot read the problem: at column 3: division by zero",
            Lang::Es,
        );
        assert_eq!(
            s.text,
            "no se puede leer el problema: en la columna 3: división por cero"
        );
    }

    #[test]
    fn continuity_in_math() {
        let s = sentence("C^1, not C^2", Lang::Es);
        assert_eq!(s.text, "C^1, pero no C^2");
        assert_eq!(s.latex, "$C^{1}$, pero no $C^{2}$");
    }

    /// Each Spanish format has the holes of its English one, in the same kinds and order, and
    /// closes every `$` it opens.
    #[test]
    fn the_formats_agree() {
        fn holes(f: &str) -> Vec<Part<'_>> {
            parts(f)
                .into_iter()
                .filter(|p| !matches!(p, Part::Lit(_)))
                .collect()
        }
        for (en, es) in SENTENCES {
            assert_eq!(holes(en), holes(es), "{en} / {es}");
            assert_eq!(en.matches('$').count() % 2, 0, "{en}");
            assert_eq!(es.matches('$').count() % 2, 0, "{es}");
        }
    }

    #[test]
    fn unknown_sentences_pass_through() {
        let s = sentence("something new", Lang::Es);
        assert_eq!(s.text, "something new");
    }
}
