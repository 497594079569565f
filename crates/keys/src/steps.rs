//! The worked solution of an answer (its typed [`Step`]s) as text, LaTeX and Markdown, in
//! English or in the notes' Spanish: each formula with its sentence and the notes' equation
//! number, the substitutions, the tables (De Casteljau schemes, De Boor tables, basis values),
//! and a short legend for readers of Farin or The NURBS Book where the names differ.

use crate::{latex, text, Lang};
use cagd_problem::steps::{Entries, Fact, Formula, Line, MatrixSummary, Step, Table, TableTitle};
use cagd_problem::Number;
use cagd_problem::{Exact, Verdict};
use cagd_scalar::{FieldOps, Print};

/// A formula: its sentence in English and Spanish, and the formula in text and LaTeX.
struct Said {
    en: &'static str,
    es: &'static str,
    text: &'static str,
    latex: &'static str,
}

const fn said(en: &'static str, es: &'static str, text: &'static str, latex: &'static str) -> Said {
    Said {
        en,
        es,
        text,
        latex,
    }
}

/// What the key says of each formula.
fn said_of(f: Formula) -> Said {
    use Formula::*;
    match f {
        DeCasteljau => said(
            "De Casteljau's algorithm, for r = 1, ..., n",
            "Algoritmo de De Casteljau, para r = 1, ..., n",
            "c_i^r = (1 - t) c_i^{r-1} + t c_{i+1}^{r-1},  c(t) = c_0^n",
            r"c_i^r = (1 - t)\, c_i^{r-1} + t\, c_{i+1}^{r-1}, \quad c(t) = c_0^n",
        ),
        DeCasteljauRational => said(
            "De Casteljau's algorithm on the homogeneous points (w_i c_i, w_i), then division by the weight",
            "Algoritmo de De Casteljau sobre los puntos homogéneos (w_i c_i, w_i) y división por el peso",
            "(w c)_i^r = (1 - t) (w c)_i^{r-1} + t (w c)_{i+1}^{r-1},  c(t) = (w c)_0^n / w_0^n",
            r"(wc)_i^r = (1 - t)\, (wc)_i^{r-1} + t\, (wc)_{i+1}^{r-1}, \quad c(t) = \frac{(wc)_0^n}{w_0^n}",
        ),
        BernsteinSum => said(
            "Bézier curve in the Bernstein basis",
            "Curva de Bézier en la base de Bernstein",
            "c(t) = Σ_i c_i B_i^n(t),  B_i^n(t) = C(n, i) t^i (1 - t)^(n-i)",
            r"c(t) = \sum_{i=0}^n c_i B_i^n(t), \quad B_i^n(t) = \binom{n}{i} t^i (1-t)^{n-i}",
        ),
        DeBoor => said(
            "De Boor's algorithm, for r = 1, ..., p",
            "Algoritmo de De Boor, para r = 1, ..., p",
            "d_i^r = (1 - α_i^r) d_{i-1}^{r-1} + α_i^r d_i^{r-1},  α_i^r = (t - u_{i-1})/(u_{i+p-r} - u_{i-1})",
            r"d_i^r = (1 - \alpha_i^r)\, d_{i-1}^{r-1} + \alpha_i^r\, d_i^{r-1}, \quad \alpha_i^r = \frac{t - u_{i-1}}{u_{i+p-r} - u_{i-1}}",
        ),
        BSplineSum => said(
            "B-spline curve in the basis of B-splines",
            "Curva B-spline en la base de B-splines",
            "c(t) = Σ_i d_i N_i^p(t)",
            r"c(t) = \sum_i d_i N_i^p(t)",
        ),
        Substitution => said(
            "Substitution of the parameters in the parametrization",
            "Sustitución de los parámetros en la parametrización",
            "c(u, v)|_(u, v)",
            r"c(u, v)\big|_{(u, v)}",
        ),
        SubstitutionCurve => said(
            "Substitution of the parameter in the parametrization",
            "Sustitución del parámetro en la parametrización",
            "c(t)|_t",
            r"c(t)\big|_{t}",
        ),
        DeCasteljauSurface => said(
            "De Casteljau's algorithm on a patch: first along u in each column, then along v",
            "Algoritmo de De Casteljau en una superficie: primero en u en cada columna, después en v",
            "c_{i,j}^{r,0} = (1 - u) c_{i,j}^{r-1,0} + u c_{i+1,j}^{r-1,0},  c_{0,j}^{m,s} = (1 - v) c_{0,j}^{m,s-1} + v c_{0,j+1}^{m,s-1},  c(u, v) = c_{0,0}^{m,n}",
            r"c_{i,j}^{r,0} = (1-u)\, c_{i,j}^{r-1,0} + u\, c_{i+1,j}^{r-1,0}, \quad c_{0,j}^{m,s} = (1-v)\, c_{0,j}^{m,s-1} + v\, c_{0,j+1}^{m,s-1}, \quad c(u,v) = c_{0,0}^{m,n}",
        ),
        BernsteinSurface => said(
            "Bézier patch in the tensor-product Bernstein basis",
            "Superficie de Bézier en la base producto tensorial de Bernstein",
            "c(u, v) = Σ_i Σ_j c_{i,j} B_i^m(u) B_j^n(v)",
            r"c(u, v) = \sum_{i=0}^m \sum_{j=0}^n c_{i,j} B_i^m(u) B_j^n(v)",
        ),
        RationalSurface => said(
            "Rational Bézier patch",
            "Superficie de Bézier racional",
            "c(u, v) = Σ Σ w_{i,j} c_{i,j} B_i^m(u) B_j^n(v) / Σ Σ w_{i,j} B_i^m(u) B_j^n(v)",
            r"c(u, v) = \frac{\sum_{i=0}^m \sum_{j=0}^n w_{i,j} c_{i,j} B_i^m(u) B_j^n(v)}{\sum_{i=0}^m \sum_{j=0}^n w_{i,j} B_i^m(u) B_j^n(v)}",
        ),
        BSplineSurface => said(
            "B-spline patch: De Boor's algorithm along u in each column, then along v",
            "Superficie B-spline: algoritmo de De Boor en u en cada columna, después en v",
            "c(u, v) = Σ_i Σ_j d_{i,j} N_i^m(u) N_j^n(v)",
            r"c(u, v) = \sum_i \sum_j d_{i,j} N_i^m(u) N_j^n(v)",
        ),
        NurbsSurface => said(
            "NURBS patch: De Boor's algorithm on the homogeneous points, then division by the weight",
            "Superficie NURBS: algoritmo de De Boor sobre los puntos homogéneos y división por el peso",
            "c(u, v) = Σ Σ w_{i,j} d_{i,j} N_i^m(u) N_j^n(v) / Σ Σ w_{i,j} N_i^m(u) N_j^n(v)",
            r"c(u, v) = \frac{\sum_i \sum_j w_{i,j} d_{i,j} N_i^m(u) N_j^n(v)}{\sum_i \sum_j w_{i,j} N_i^m(u) N_j^n(v)}",
        ),
        ElevateCurve => said(
            "Degree elevation, from n to n + 1",
            "Elevación del grado, de n a n + 1",
            "c_i^{(1)} = i/(n+1) c_{i-1} + (1 - i/(n+1)) c_i,  i = 0, ..., n + 1",
            r"c_i^{(1)} = \frac{i}{n+1}\, c_{i-1} + \left(1 - \frac{i}{n+1}\right) c_i, \quad i = 0, \dots, n+1",
        ),
        ElevateBSpline => said(
            "Degree elevation of a B-spline: each Bézier piece is elevated and the knots keep their continuity (each knot gains one multiplicity)",
            "Elevación del grado de una B-spline: se eleva cada tramo de Bézier y los nudos conservan su continuidad (cada nudo aumenta su multiplicidad en uno)",
            "p -> p + 1,  m(u_i) -> m(u_i) + 1",
            r"p \to p + 1, \quad m(u_i) \to m(u_i) + 1",
        ),
        ElevateU => said(
            "Degree elevation along u, applied to each column j of the mesh",
            "Elevación del grado en u, aplicada a cada columna j de la malla de control",
            "c_{i,j}^{1,0} = (1 - i/(m+1)) c_{i,j} + i/(m+1) c_{i-1,j}",
            r"c_{i,j}^{1,0} = \left(1 - \frac{i}{m+1}\right) c_{i,j} + \frac{i}{m+1}\, c_{i-1,j}",
        ),
        ElevateUAtOnce => said(
            "Degree elevation along u by r at once ((14) applied r times), on each column j of the mesh",
            "Elevación del grado en u de r grados a la vez ((14) aplicada r veces), en cada columna j de la malla de control",
            "c_{i,j}^{r,0} = Σ_k C(m,k) C(r,i-k)/C(m+r,i) c_{k,j}",
            r"c_{i,j}^{r,0} = \sum_{k} \frac{\binom{m}{k}\binom{r}{i-k}}{\binom{m+r}{i}}\, c_{k,j}",
        ),
        ElevateVAtOnce => said(
            "Degree elevation along v by s at once ((15) applied s times), on each row i of the mesh",
            "Elevación del grado en v de s grados a la vez ((15) aplicada s veces), en cada fila i de la malla de control",
            "c_{i,j}^{r,s} = Σ_l C(n,l) C(s,j-l)/C(n+s,j) c_{i,l}^{r,0}",
            r"c_{i,j}^{r,s} = \sum_{l} \frac{\binom{n}{l}\binom{s}{j-l}}{\binom{n+s}{j}}\, c_{i,l}^{r,0}",
        ),
        ElevateV => said(
            "Degree elevation along v, applied to each row i of the mesh",
            "Elevación del grado en v, aplicada a cada fila i de la malla de control",
            "c_{i,j}^{0,1} = (1 - j/(n+1)) c_{i,j} + j/(n+1) c_{i,j-1}",
            r"c_{i,j}^{0,1} = \left(1 - \frac{j}{n+1}\right) c_{i,j} + \frac{j}{n+1}\, c_{i,j-1}",
        ),
        RestrictCurve => said(
            "Restriction to [a, b] by the polar form (blossom)",
            "Restricción a [a, b] mediante la forma polar",
            "c̃_i = c[a^<n-i>, b^<i>],  i = 0, ..., n",
            r"\tilde{c}_i = c[a^{\langle n-i \rangle}, b^{\langle i \rangle}], \quad i = 0, \dots, n",
        ),
        RestrictSurface => said(
            "Restriction to [a, b] × [c, d] by the polar form: first along u (the mesh ĉ), then along v",
            "Restricción a [a, b] × [c, d] mediante la forma polar: primero en u (la malla ĉ), después en v",
            "c̃_{i,j} = c[a^<m-i>, b^<i>; c^<n-j>, d^<j>]",
            r"\tilde{c}_{i,j} = c[a^{\langle m-i \rangle}, b^{\langle i \rangle}; c^{\langle n-j \rangle}, d^{\langle j \rangle}]",
        ),
        DerivativeCurve => said(
            "Derivative of order r of a Bézier curve by forward differences",
            "Derivada de orden r de una curva de Bézier mediante diferencias progresivas",
            "c^(r)(t) = n!/(n-r)! Σ_i Δ^r c_i B_i^{n-r}(t)",
            r"c^{(r)}(t) = \frac{n!}{(n-r)!} \sum_{i=0}^{n-r} \Delta^r c_i B_i^{n-r}(t)",
        ),
        DerivativeMap => said(
            "Derivative of the parametrization, term by term",
            "Derivada de la parametrización, término a término",
            "∂^{r+s} c / ∂u^r ∂v^s",
            r"\frac{\partial^{r+s} c}{\partial u^r \partial v^s}",
        ),
        DerivativeSurface => said(
            "Partial derivative of a Bézier patch by forward differences",
            "Derivada parcial de una superficie de Bézier mediante diferencias progresivas",
            "∂^{r+s} c(u, v)/∂u^r ∂v^s = m! n!/((m-r)! (n-s)!) Σ_i Σ_j Δ^{r,s} c_{i,j} B_i^{m-r}(u) B_j^{n-s}(v)",
            r"\frac{\partial^{r+s} c(u, v)}{\partial u^r \partial v^s} = \frac{m!\, n!}{(m-r)!\,(n-s)!} \sum_{i=0}^{m-r} \sum_{j=0}^{n-s} \Delta^{r,s}c_{i,j} B_i^{m-r}(u) B_j^{n-s}(v)",
        ),
        DerivativeBorder0 => said(
            "On the border u = 0 only the first rows of the mesh act",
            "En el borde u = 0 sólo intervienen las primeras filas de la malla",
            "∂^r c/∂u^r (0, v) = m!/(m-r)! Σ_j Δ^{r,0} c_{0,j} B_j^n(v)",
            r"\left. \frac{\partial^r c(u, v)}{\partial u^r} \right|_{u=0} = \frac{m!}{(m-r)!} \sum_{j=0}^n \Delta^{r,0}c_{0,j} B_j^n(v)",
        ),
        DerivativeBorder1 => said(
            "On the border u = 1 only the last rows of the mesh act",
            "En el borde u = 1 sólo intervienen las últimas filas de la malla",
            "∂^r c/∂u^r (1, v) = m!/(m-r)! Σ_j Δ^{r,0} c_{m-r,j} B_j^n(v)",
            r"\left. \frac{\partial^r c(u, v)}{\partial u^r} \right|_{u=1} = \frac{m!}{(m-r)!} \sum_{j=0}^n \Delta^{r,0}c_{m-r,j} B_j^n(v)",
        ),
        DerivativeRational => said(
            "Derivative of the rational patch c = p/w by the quotient rule",
            "Derivada de la superficie racional c = p/w por la regla del cociente",
            "c_u = (p_u w - p w_u)/w^2",
            r"c_u = \frac{p_u\, w - p\, w_u}{w^2}",
        ),
        Boehm => said(
            "Knot insertion (Boehm's algorithm), with k the span of t",
            "Inserción de nudos (algoritmo de Boehm), siendo k el tramo de t",
            "d̂_i = (1 - α_i) d_{i-1} + α_i d_i,  α_i = (t - u_{i-1})/(u_{i+p-1} - u_{i-1}),  i = k-p+1, ..., k",
            r"\hat{d}_i = (1 - \alpha_i)\, d_{i-1} + \alpha_i\, d_i, \quad \alpha_i = \frac{t - u_{i-1}}{u_{i+p-1} - u_{i-1}}, \quad i = k-p+1, \dots, k",
        ),
        Normal => said(
            "Normal vector: the cross product of the partial derivatives",
            "Vector normal: producto vectorial de las derivadas parciales",
            "n(u, v) = c_u(u, v) × c_v(u, v)",
            r"n(u, v) = c_u(u, v) \times c_v(u, v)",
        ),
        CornerNormal => said(
            "At the corners, the differences of the mesh",
            "En las esquinas, las diferencias de la malla de control",
            "n(0, 0) = m n Δ^{1,0}c_{0,0} × Δ^{0,1}c_{0,0}",
            r"n(0, 0) = mn\, \Delta^{1,0}c_{0,0} \times \Delta^{0,1}c_{0,0}",
        ),
        JoinC0 => said(
            "C^0 join: the common border",
            "Unión C^0: el borde común",
            "c_{m,j} = c̃_{0,j},  j = 0, ..., n",
            r"c_{m,j} = \tilde{c}_{0,j}, \quad j = 0, \dots, n",
        ),
        JoinC1 => said(
            "C^1 join: the first differences across the border",
            "Unión C^1: las primeras diferencias a través del borde",
            "Δ^{1,0} c_{m-1,j} / Δu_0 = Δ^{1,0} c̃_{0,j} / Δu_1",
            r"\frac{\Delta^{1,0} c_{m-1,j}}{\Delta u_0} = \frac{\Delta^{1,0} \tilde{c}_{0,j}}{\Delta u_1}",
        ),
        JoinCr => said(
            "C^r join: the differences of order r across the border",
            "Unión C^r: las diferencias de orden r a través del borde",
            "Δ^{r,0} c_{m-r,j} / (Δu_0)^r = Δ^{r,0} c̃_{0,j} / (Δu_1)^r",
            r"\frac{\Delta^{r,0} c_{m-r,j}}{(\Delta u_0)^r} = \frac{\Delta^{r,0} \tilde{c}_{0,j}}{(\Delta u_1)^r}",
        ),
        InterpolateSurface => said(
            "Interpolation of the data points a_{i,j} = c(u_i, v_j): two passes, first the rows of A, then the columns",
            "Interpolación de los puntos a_{i,j} = c(u_i, v_j): dos pasos, primero las filas de A, después las columnas",
            "B_U C B_V^t = A,  C̃ = A (B_V^t)^{-1},  C = B_U^{-1} C̃",
            r"B_U\, C\, B_V^t = A, \quad \tilde{C} = A\, (B_V^t)^{-1}, \quad C = B_U^{-1} \tilde{C}",
        ),
        InterpolateCurve => said(
            "Interpolation of the data points a_k = c(t_k): the Bernstein system",
            "Interpolación de los puntos a_k = c(t_k): el sistema de Bernstein",
            "B C = A,  B_{k,i} = B_i^n(t_k)",
            r"B\, C = A, \quad B_{k,i} = B_i^n(t_k)",
        ),
        InterpolateSpline => said(
            "C^2 cubic spline interpolation: the system of the control points D, its first and last rows the end conditions (natural: c''(t_0) = c''(t_N) = 0; Bessel: the tangents of the parabolas through the first and the last three points)",
            "Interpolación por splines cúbicos C^2: el sistema de los puntos de control D, cuyas filas primera y última son las condiciones en los extremos (natural: c''(t_0) = c''(t_N) = 0; Bessel: las tangentes de las parábolas por los tres primeros y los tres últimos puntos)",
            "N D = A,  N_{k,j} = N_j^3(t_k)",
            r"N D = A, \quad N_{k,j} = N_j^3(t_k)",
        ),
        InterpolateBicubic => said(
            "Bicubic spline interpolation: the curve method on the rows of data points (the mesh d̃), then on its columns",
            "Interpolación por splines bicúbicos: el método de curvas en las filas de puntos (la malla d̃), después en sus columnas",
            "c(u_i, v_j) = a_{i,j}",
            r"c(u_i, v_j) = a_{i,j}",
        ),
        LeastSquaresSurface => said(
            "Least squares: the normal equations of the collocation system",
            "Mínimos cuadrados: las ecuaciones normales del sistema de colocación",
            "B C = A,  B^t B C = B^t A",
            r"B\, C = A, \quad B^t B\, C = B^t A",
        ),
        LeastSquaresCurve => said(
            "Least squares: the normal equations, with B_{k,i} = B_i^n(t_k)",
            "Mínimos cuadrados: las ecuaciones normales, con B_{k,i} = B_i^n(t_k)",
            "B^t B C = B^t A",
            r"B^t B\, C = B^t A",
        ),
        ClosedFormCurve => said(
            "Closed form: the Bernstein polynomials expanded",
            "Parametrización: desarrollo de los polinomios de Bernstein",
            "c(t) = Σ_i c_i B_i^n(t)",
            r"c(t) = \sum_{i=0}^n c_i B_i^n(t)",
        ),
        ClosedFormRationalCurve => said(
            "Closed form of a rational curve",
            "Parametrización de una curva racional",
            "c(t) = Σ_i w_i c_i B_i^n(t) / Σ_i w_i B_i^n(t)",
            r"c(t) = \frac{\sum_{i=0}^n w_i c_i B_i^n(t)}{\sum_{i=0}^n w_i B_i^n(t)}",
        ),
        Graph => said(
            "Graph of f as a Bézier patch: ĉ_{i,j} are the Bernstein coefficients of f",
            "Gráfica de f como superficie de Bézier: ĉ_{i,j} son los coeficientes de f en la base de Bernstein",
            "c_{i,j} = (i/m, j/n, ĉ_{i,j}),  f(u, v) = Σ Σ ĉ_{i,j} B_i^m(u) B_j^n(v)",
            r"c_{i,j} = \left(\frac{i}{m}, \frac{j}{n}, \hat{c}_{i,j}\right), \quad f(u, v) = \sum_{i=0}^m \sum_{j=0}^n \hat{c}_{i,j} B_i^m(u) B_j^n(v)",
        ),
        Circle => said(
            "Circle of N arcs of angle 2π/N: each arc is a rational quadratic with weights {1, w, 1}, w the cosine of half the angle",
            "Circunferencia de N arcos de ángulo 2π/N: cada arco es una cuadrática racional de pesos {1, w, 1}, siendo w el coseno de la mitad del ángulo",
            "w = cos(π/N)",
            r"w = \cos\frac{\pi}{N}",
        ),
        Translational => said(
            "Translational surface",
            "Superficie traslacional",
            "c(u, v) = c_1(u) + d_1(v) - a",
            r"c(u, v) = c_1(u) + d_1(v) - a",
        ),
        TranslationalMesh => said(
            "Mesh of the translational surface",
            "Malla de control de la superficie traslacional",
            "c_{i,j} = c_{1i} + d_{1j} - a,  w_{i,j} = w_{1i} ω_{1j}",
            r"c_{i,j} = c_{1i} + d_{1j} - a, \quad w_{i,j} = w_{1i}\, \omega_{1j}",
        ),
        Ruled => said(
            "Ruled surface",
            "Superficie reglada",
            "c(u, v) = (1 - v) c_1(u) + v c_2(u),  u, v ∈ [0, 1]",
            r"c(u, v) = (1 - v)\, c_1(u) + v\, c_2(u), \quad u, v \in [0, 1]",
        ),
        RuledMesh => said(
            "Mesh of bidegree (m, 1): the rows are the polygons of c_1 and c_2 (of the same degree)",
            "Malla de bigrado (m, 1): las filas son los polígonos de c_1 y c_2 (del mismo grado)",
            "c_{i,0} = c_{1i},  c_{i,1} = c_{2i}",
            r"c_{i,0} = c_{1i}, \quad c_{i,1} = c_{2i}",
        ),
        Developable => said(
            "Developability test",
            "Criterio de desarrollabilidad",
            "c_uv · (c_u × c_v) ≡ 0",
            r"c_{uv} \cdot (c_u \times c_v) \equiv 0",
        ),
        DevelopableRuled => said(
            "For a ruled surface (1 - v) c_1(u) + v c_2(u)",
            "Para una superficie reglada (1 - v) c_1(u) + v c_2(u)",
            "c_2'(u) · (c_1'(u) × (c_2(u) - c_1(u))) ≡ 0",
            r"c_{2u}(u) \cdot (c_{1u}(u) \times (c_2(u) - c_1(u))) \equiv 0",
        ),
        CoonsRuled => said(
            "The ruled surfaces of the two pairs of curves",
            "Las superficies regladas de los dos pares de curvas",
            "c_c(u, v) = (1 - v) c_1(u) + v c_2(u),  c_d(u, v) = (1 - u) d_1(v) + u d_2(v)",
            r"c_c(u, v) = (1 - v)\, c_1(u) + v\, c_2(u), \quad c_d(u, v) = (1 - u)\, d_1(v) + u\, d_2(v)",
        ),
        CoonsBilinear => said(
            "The bilinear patch of the corners a, b, c, d",
            "La superficie bilineal de las esquinas a, b, c, d",
            "c_cd(u, v) = (1 - u)((1 - v) a + v c) + u((1 - v) b + v d)",
            r"c_{cd}(u, v) = (1 - u)((1 - v)\, a + v\, c) + u((1 - v)\, b + v\, d)",
        ),
        Coons => said(
            "Coons patch",
            "Superficie de Coons",
            "c = c_c + c_d - c_cd",
            r"c(u, v) = c_c(u, v) + c_d(u, v) - c_{cd}(u, v)",
        ),
        CoonsMesh => said(
            "Mesh of the Bézier Coons patch: c_c, c_d and c_cd elevated to the same bidegree (m, n)",
            "Malla de la superficie de Coons de Bézier: c_c, c_d y c_cd elevadas al mismo bigrado (m, n)",
            "c_{i,j} = c_{c i,j} + c_{d i,j} - c_{cd i,j},  c_{c i,j} = (n-j)/n c_{1i} + j/n c_{2i},  c_{d i,j} = (m-i)/m d_{1j} + i/m d_{2j}",
            r"c_{i,j} = c_{c\,i,j} + c_{d\,i,j} - c_{cd\,i,j}, \quad c_{c\,i,j} = \tfrac{n-j}{n} c_{1i} + \tfrac{j}{n} c_{2i}, \quad c_{d\,i,j} = \tfrac{m-i}{m} d_{1j} + \tfrac{i}{m} d_{2j}",
        ),
        CoonsCubic => said(
            "Coons patch with the cubic blending functions F_0(s) = 1 - 3s^2 + 2s^3, F_1(s) = 3s^2 - 2s^3 in place of 1 - s and s",
            "Superficie de Coons con las funciones de mezcla cúbicas F_0(s) = 1 - 3s^2 + 2s^3, F_1(s) = 3s^2 - 2s^3 en lugar de 1 - s y s",
            "c = c_c + c_d - c_cd",
            r"c(u, v) = c_c(u, v) + c_d(u, v) - c_{cd}(u, v)",
        ),
        Revolution => said(
            "Surface of revolution of the curve (f(u), 0, g(u)) of the XZ plane about the Z axis",
            "Superficie de revolución de la curva (f(u), 0, g(u)) del plano XZ en torno al eje Z",
            "c(u, v) = (f(u) cos v, f(u) sin v, g(u))",
            r"c(u, v) = (f(u) \cos v, f(u) \sin v, g(u))",
        ),
        RevolutionMesh => said(
            "Mesh of revolution: row i is the polygon of the circle C_i described by the vertex c_i; the weights of row i are w_i times the circle's normalized weights ω_j",
            "Malla de revolución: la fila i es el polígono de la circunferencia C_i que describe el vértice c_i; los pesos de la fila i son w_i por los pesos normalizados ω_j de la circunferencia",
            "c_{i,j} = (C_i)_j,  w_{i,j} = w_i ω_j",
            r"c_{i,j} = (C_i)_j, \quad w_{i,j} = w_i\, \omega_j",
        ),
        DeCasteljauTriangle => said(
            "De Casteljau's algorithm on the triangular net, at the barycentric point (r, s, t) = (1 - u - v, u, v), for l = 1, ..., n",
            "Algoritmo de De Casteljau sobre la red triangular, en el punto de coordenadas baricéntricas (r, s, t) = (1 - u - v, u, v), para l = 1, ..., n",
            "b_{i,j,k}^l = r b_{i+1,j,k}^{l-1} + s b_{i,j+1,k}^{l-1} + t b_{i,j,k+1}^{l-1},  b(r, s, t) = b_{0,0,0}^n",
            r"b_{i,j,k}^l = r\, b_{i+1,j,k}^{l-1} + s\, b_{i,j+1,k}^{l-1} + t\, b_{i,j,k+1}^{l-1}, \quad b(r, s, t) = b_{0,0,0}^n",
        ),
        BernsteinTriangle => said(
            "Closed form of the triangular patch: the Bernstein sum with r = 1 - u - v, s = u, t = v",
            "Forma cerrada de la superficie triangular: la suma de Bernstein con r = 1 - u - v, s = u, t = v",
            "b(u, v) = Σ_{i+j+k=n} b_{i,j,k} n!/(i! j! k!) r^i s^j t^k",
            r"b(u, v) = \sum_{i+j+k=n} b_{i,j,k} \frac{n!}{i!\,j!\,k!} r^i s^j t^k",
        ),
        ElevateTriangle => said(
            "Degree elevation of a triangular patch, once for each degree",
            "Elevación del grado de una superficie triangular, una vez por grado",
            "b_{i,j,k}^{(1)} = (i b_{i-1,j,k} + j b_{i,j-1,k} + k b_{i,j,k-1})/(n + 1)",
            r"b_{i,j,k}^{(1)} = \frac{i\, b_{i-1,j,k} + j\, b_{i,j-1,k} + k\, b_{i,j,k-1}}{n + 1}",
        ),
        DerivativeTriangle => said(
            "Directional derivative of a triangular patch along d = (d_1, d_2, d_3) = (-du - dv, du, dv): one De Casteljau step with d, times n",
            "Derivada direccional de una superficie triangular en la dirección d = (d_1, d_2, d_3) = (-du - dv, du, dv): un paso de De Casteljau con d, por n",
            "D_d b = n Σ_{i+j+k=n-1} (d_1 b_{i+1,j,k} + d_2 b_{i,j+1,k} + d_3 b_{i,j,k+1}) B_{i,j,k}^{n-1}",
            r"D_d b = n \sum_{i+j+k=n-1} \left(d_1 b_{i+1,j,k} + d_2 b_{i,j+1,k} + d_3 b_{i,j,k+1}\right) B_{i,j,k}^{n-1}",
        ),
        BlossomTriangle => said(
            "Blossom of a triangular patch: De Casteljau with the point x_l at level l",
            "Forma polar de una superficie triangular: De Casteljau con el punto x_l en el nivel l",
            "b_{i,j,k}^l = r_l b_{i+1,j,k}^{l-1} + s_l b_{i,j+1,k}^{l-1} + t_l b_{i,j,k+1}^{l-1},  b[x_1, ..., x_n] = b_{0,0,0}^n",
            r"b_{i,j,k}^l = r_l\, b_{i+1,j,k}^{l-1} + s_l\, b_{i,j+1,k}^{l-1} + t_l\, b_{i,j,k+1}^{l-1}, \quad b[x_1, \dots, x_n] = b_{0,0,0}^n",
        ),
        SubdivideTriangle => said(
            "Split of a triangular patch at x into the patches over (x, e2, e3), (e1, x, e3), (e1, e2, x), read off the De Casteljau levels at x",
            "División de una superficie triangular en x en las superficies sobre (x, e2, e3), (e1, x, e3), (e1, e2, x), leídas en los niveles de De Casteljau en x",
            "c_{i,j,k} = b_{0,j,k}^i(x),  b_{i,0,k}^j(x),  b_{i,j,0}^k(x)",
            r"c_{i,j,k} = b_{0,j,k}^i(x),\ b_{i,0,k}^j(x),\ b_{i,j,0}^k(x)",
        ),
        BoundaryTriangle => said(
            "Boundary curves of a triangular patch: the control points on each edge of the net",
            "Curvas borde de una superficie triangular: los puntos de control de cada lado de la red",
            "t = 0: b_{n-l,l,0};  r = 0: b_{0,n-l,l};  s = 0: b_{l,0,n-l}",
            r"t = 0: b_{n-l,l,0}; \quad r = 0: b_{0,n-l,l}; \quad s = 0: b_{l,0,n-l}",
        ),
        BlossomCurve => said(
            "Blossom (polar form) of the curve: De Casteljau with t_r at level r",
            "Forma polar de la curva: De Casteljau con t_r en el nivel r",
            "c_i^r = (1 - t_r) c_i^{r-1} + t_r c_{i+1}^{r-1},  c[t_1, ..., t_n] = c_0^n",
            r"c_i^r = (1 - t_r)\, c_i^{r-1} + t_r\, c_{i+1}^{r-1}, \quad c[t_1, \dots, t_n] = c_0^n",
        ),
        BlossomSurface => said(
            "Polar form of the patch: the blossom of each row in v, then of the resulting column in u",
            "Forma polar de la superficie: la forma polar de cada fila en v y luego de la columna resultante en u",
            "c[u_1, ..., u_m; v_1, ..., v_n] = c[v_1, ..., v_n][u_1, ..., u_m]",
            r"c[u_1, \dots, u_m; v_1, \dots, v_n] = c[v_1, \dots, v_n][u_1, \dots, u_m]",
        ),
        SubdivideCurve => said(
            "Subdivision at t: the sides of the De Casteljau triangle are the two new polygons",
            "Subdivisión en t: los lados del triángulo de De Casteljau son los dos nuevos polígonos",
            "c_0^0, c_0^1, ..., c_0^n;  c_0^n, c_1^{n-1}, ..., c_n^0",
            r"c_0^0, c_0^1, \dots, c_0^n; \quad c_0^n, c_1^{n-1}, \dots, c_n^0",
        ),
        SubdivideSurface => said(
            "Subdivision at (u0, v0) into four patches: each is the restriction (13) to its sub-rectangle",
            "Subdivisión en (u0, v0) en cuatro superficies: cada una es la restricción (13) a su subrectángulo",
            "c̃_{i,j} = c[a^<m-i>, b^<i>; c^<n-j>, d^<j>]",
            r"\tilde{c}_{i,j} = c[a^{\langle m-i \rangle}, b^{\langle i \rangle}; c^{\langle n-j \rangle}, d^{\langle j \rangle}]",
        ),
        BoundarySurface => said(
            "Boundary curves: the first and last rows and columns of the mesh are their control polygons",
            "Curvas borde: la primera y la última fila y columna de la malla son sus polígonos de control",
            "c(0, v) = Σ c_{0,j} B_j^n(v),  c(1, v) = Σ c_{m,j} B_j^n(v),  c(u, 0) = Σ c_{i,0} B_i^m(u),  c(u, 1) = Σ c_{i,n} B_i^m(u)",
            r"c(0, v) = \sum_j c_{0,j} B_j^n(v), \quad c(1, v) = \sum_j c_{m,j} B_j^n(v), \quad c(u, 0) = \sum_i c_{i,0} B_i^m(u), \quad c(u, 1) = \sum_i c_{i,n} B_i^m(u)",
        ),
        Isocurve => said(
            "Iso-parametric curve: De Casteljau (De Boor) on every column at u0, or on every row at v0",
            "Curva isoparamétrica: De Casteljau (De Boor) en cada columna en u0, o en cada fila en v0",
            "c(u0, v) = Σ_j (Σ_i c_{i,j} B_i^m(u0)) B_j^n(v)",
            r"c(u_0, v) = \sum_j \Big(\sum_i c_{i,j} B_i^m(u_0)\Big) B_j^n(v)",
        ),
        Extract => said(
            "Bézier extraction: every breakpoint inserted (Boehm) up to multiplicity p; each span then carries the Bézier points of its piece",
            "Extracción de Bézier: cada nudo interior se inserta (Boehm) hasta multiplicidad p; cada tramo lleva entonces los puntos de Bézier de su pieza",
            "mult(u_k) = p  ⇒  [u_{k-1}, u_k]: d_{(k-1)p}, ..., d_{kp} = b_0, ..., b_p",
            r"[u_{k-1}, u_k]: \ d_{(k-1)p}, \dots, d_{kp} = b_0, \dots, b_p",
        ),
        RemoveKnot => said(
            "Knot removal: the points of the curve without the knot are solved from Boehm's relations; the removal is exact only when they hold for every point",
            "Eliminación de nudos: los puntos de la curva sin el nudo se despejan de las relaciones de Boehm; la eliminación es exacta solo si se cumplen para todos los puntos",
            "d_i = (1 - α_i) d̃_{i-1} + α_i d̃_i",
            r"d_i = (1 - \alpha_i)\, \tilde{d}_{i-1} + \alpha_i\, \tilde{d}_i",
        ),
        Reverse => said(
            "Reversal: the control points in the opposite order (the knots u ↦ a + b - u, in the opposite order)",
            "Inversión del sentido: los puntos de control en orden inverso (los nudos u ↦ a + b - u, en orden inverso)",
            "c̃_i = c_{n-i},  c̃(t) = c(a + b - t)",
            r"\tilde{c}_i = c_{n-i}, \quad \tilde{c}(t) = c(a + b - t)",
        ),
        ReduceExact => said(
            "Exact degree reduction: the curve is of the lower degree, so the elevation is inverted exactly",
            "Reducción exacta del grado: la curva es del grado menor, así que la elevación se invierte exactamente",
            "E c̃ = c",
            r"E\, \tilde{c} = c",
        ),
        ReduceLeastSquares => said(
            "Degree reduction by least squares: the polygon of lower degree whose elevation is nearest the given polygon",
            "Reducción del grado por mínimos cuadrados: el polígono de grado menor cuya elevación está más cerca del polígono dado",
            "E^t E c̃ = E^t c",
            r"E^t E\, \tilde{c} = E^t c",
        ),
        PiecewiseSurface => said(
            "Piece by piece: every breakpoint inserted until it has multiplicity p in u and q in v; on each rectangle of spans [u_k, u_{k+1}] x [v_l, v_{l+1}] the (p + 1) x (q + 1) block of the mesh is a Bézier patch (rational for NURBS), written in the surface's own u and v",
            "Por trozos: cada nudo interior se inserta hasta multiplicidad p en u y q en v; en cada rectángulo de intervalos [u_k, u_{k+1}] x [v_l, v_{l+1}] el bloque (p + 1) x (q + 1) de la malla es una superficie de Bézier (racional si es NURBS), escrita en los parámetros u y v de la superficie",
            "c(u, v) = Σ_i Σ_j b_{i,j}^{k,l} B_i^p((u - u_k)/(u_{k+1} - u_k)) B_j^q((v - v_l)/(v_{l+1} - v_l)),  (u, v) ∈ [u_k, u_{k+1}] x [v_l, v_{l+1}]",
            r"c(u, v) = \sum_i \sum_j b_{i,j}^{k,l} B_i^p\!\left(\tfrac{u - u_k}{u_{k+1} - u_k}\right) B_j^q\!\left(\tfrac{v - v_l}{v_{l+1} - v_l}\right), \quad (u, v) \in [u_k, u_{k+1}] \times [v_l, v_{l+1}]",
        ),
        DerivativeBSplineSurface => said(
            "Derivative of a B-spline surface: the derivative rule of B-spline curves on each column (in u) or row (in v); a B-spline of one degree less",
            "Derivada de una superficie B-spline: la regla de la derivada de las curvas B-spline en cada columna (en u) o fila (en v); una B-spline de un grado menos",
            "∂c/∂u = Σ_i Σ_j Δ_u d_{i,j} N_i^{p-1}(u) N_j^q(v),  Δ_u d_{i,j} = p (d_{i+1,j} - d_{i,j}) / (u_{i+p} - u_i)",
            r"\frac{\partial c}{\partial u} = \sum_i \sum_j \Delta_u d_{i,j} N_i^{p-1}(u) N_j^q(v), \quad \Delta_u d_{i,j} = \frac{p\,(d_{i+1,j} - d_{i,j})}{u_{i+p} - u_i}",
        ),
        SplinePatchesJoin => said(
            "Two surfaces joined along a border u = ξ: the second moved along u to begin where the first ends; on each stretch of the border where a piece of each meets, the derivatives ∂^k c/∂u^k of both pieces at u = ξ compared for k = 0, 1, ...",
            "Dos superficies unidas por un borde u = ξ: la segunda se traslada en u para que empiece donde acaba la primera; en cada tramo del borde donde se encuentran un trozo de cada una, se comparan las derivadas ∂^k c/∂u^k de los dos trozos en u = ξ para k = 0, 1, ...",
            "C^r:  ∂^k c/∂u^k (ξ, v) = ∂^k c~/∂u^k (ξ, v),  k = 0, ..., r",
            r"C^r: \quad \frac{\partial^k c}{\partial u^k}(\xi, v) = \frac{\partial^k \tilde{c}}{\partial u^k}(\xi, v), \quad k = 0, \dots, r",
        ),
        KnotLineContinuity => said(
            "Across a knot line u = ξ where ξ has multiplicity μ the surface is C^{p-μ}; the order is checked exactly on the pieces: the derivatives ∂^k c/∂u^k of both neighbours at u = ξ compared for k = 0, 1, ...",
            "A través de una línea nodal u = ξ de multiplicidad μ la superficie es C^{p-μ}; el orden se comprueba exactamente en los trozos: se comparan las derivadas ∂^k c/∂u^k de los dos vecinos en u = ξ para k = 0, 1, ...",
            "u = ξ, C^{p-μ}:  ∂^k c^-/∂u^k (ξ, v) = ∂^k c^+/∂u^k (ξ, v),  k = 0, ..., p - μ",
            r"C^{p-\mu} \text{ en } u = \xi: \quad \frac{\partial^k c^-}{\partial u^k}(\xi, v) = \frac{\partial^k c^+}{\partial u^k}(\xi, v), \quad k = 0, \dots, p - \mu",
        ),
        DerivativeBSplineCurve => said(
            "Derivative of a B-spline curve: a B-spline of degree p - 1 on the knots without the first and the last",
            "Derivada de una curva B-spline: una B-spline de grado p - 1 sobre los nudos sin el primero y el último",
            "c'(t) = Σ_i Δd_i N_i^{p-1}(t),  Δd_i = p (d_{i+1} - d_i) / (u_{i+p} - u_i)",
            r"c'(t) = \sum_i \Delta d_i N_i^{p-1}(t), \quad \Delta d_i = \frac{p\,(d_{i+1} - d_i)}{u_{i+p} - u_i}",
        ),
        DerivativeRationalCurve => said(
            "Derivative of a rational curve c = p/w by the quotient rule",
            "Derivada de una curva racional c = p/w por la regla del cociente",
            "c'(t) = (p'(t) w(t) - p(t) w'(t)) / w(t)^2",
            r"c'(t) = \frac{p'(t)\, w(t) - p(t)\, w'(t)}{w(t)^2}",
        ),
        PiecewiseCurve => said(
            "Piece by piece: every breakpoint inserted until it has multiplicity p; on each span [u_k, u_{k+1}] the p + 1 points form a Bézier curve (rational for NURBS), written in the curve's own t",
            "Por trozos: cada nudo interior se inserta hasta multiplicidad p; en cada intervalo [u_k, u_{k+1}] los p + 1 puntos forman una curva de Bézier (racional si es NURBS), escrita en el parámetro t de la curva",
            "c(t) = Σ_i b_i^k B_i^p((t - u_k)/(u_{k+1} - u_k)),  t ∈ [u_k, u_{k+1}]",
            r"c(t) = \sum_i b_i^k B_i^p\!\left(\tfrac{t - u_k}{u_{k+1} - u_k}\right), \quad t \in [u_k, u_{k+1}]",
        ),
        CurveJoinC => said(
            "C^r join of two curves: the derivatives of the first at its end equal those of the second at its start, each in its own parameter",
            "Unión C^r de dos curvas: las derivadas de la primera en su final son iguales a las de la segunda en su comienzo, cada una en su parámetro",
            "c_1^{(k)}(b) = c_2^{(k)}(a),  k = 0, ..., r",
            r"c_1^{(k)}(b) = c_2^{(k)}(a), \quad k = 0, \dots, r",
        ),
        CurveJoinG => said(
            "Geometric continuity: G^1 when the tangents are parallel and point the same way, G^2 when moreover the second derivatives satisfy the chain rule of a reparametrization",
            "Continuidad geométrica: G^1 si las tangentes son paralelas y del mismo sentido, G^2 si además las derivadas segundas cumplen la regla de la cadena de una reparametrización",
            "G^1: c_2'(a) = α c_1'(b), α > 0;  G^2: c_2''(a) = α² c_1''(b) + β c_1'(b)",
            r"G^1: c_2'(a) = \alpha\, c_1'(b),\ \alpha > 0; \quad G^2: c_2''(a) = \alpha^2 c_1''(b) + \beta\, c_1'(b)",
        ),
        Developable8 => said(
            "A surface is developable where its Gaussian curvature vanishes: with n a normal vector",
            "Una superficie es desarrollable donde su curvatura de Gauss es nula: con n un vector normal",
            "0 = | c_uu · n   c_uv · n ; c_uv · n   c_vv · n |",
            r"0 = \begin{vmatrix} c_{uu} \cdot n & c_{uv} \cdot n \\ c_{uv} \cdot n & c_{vv} \cdot n \end{vmatrix}",
        ),
        GaussianNumerator => said(
            "The numerator of the Gaussian curvature, with n = c_u × c_v: L = c_uu · n, M = c_uv · n, N = c_vv · n; for a rational patch c = p/w, through the homogeneous P = (p, w), where det(P, P_u, P_v, P_xy) = -w⁴ (c_xy · n)",
            "El numerador de la curvatura de Gauss, con n = c_u × c_v: L = c_uu · n, M = c_uv · n, N = c_vv · n; para una superficie racional c = p/w, mediante la forma homogénea P = (p, w), donde det(P, P_u, P_v, P_xy) = -w⁴ (c_xy · n)",
            "K = G / (w⁸ |n|⁴),  G = w⁸ (L N - M²) = det(P, P_u, P_v, P_uu) det(P, P_u, P_v, P_vv) - det(P, P_u, P_v, P_uv)²",
            r"K = \frac{G}{w^8 |n|^4}, \quad G = w^8 (L N - M^2) = \det(P, P_u, P_v, P_{uu}) \det(P, P_u, P_v, P_{vv}) - \det(P, P_u, P_v, P_{uv})^2",
        ),
        AveragedKnots => said(
            "B-spline interpolation of degree p: the knots averaged from the parameters (The NURBS Book, eq. (9.8)), then the collocation system N D = A",
            "Interpolación B-spline de grado p: los nudos promediados de los parámetros (Piegl y Tiller, ec. (9.8)), y el sistema de colocación N D = A",
            "u_{j+p} = (t_j + ... + t_{j+p-1}) / p,  j = 1, ..., n - p;  Σ_i d_i N_i^p(t_k) = a_k",
            r"u_{j+p} = \frac{1}{p} \sum_{i=j}^{j+p-1} t_i, \quad j = 1, \dots, n - p; \qquad \sum_i d_i N_i^p(t_k) = a_k",
        ),
        EndDerivativeKnots => said(
            "B-spline interpolation of degree p with the end derivatives D_0, D_n (The NURBS Book, §9.2.2): n + 3 control points, the knots averaged from the parameters (eq. (9.22)), and the system N D = A whose second and second-to-last rows give the end derivatives (eqs. (9.19)-(9.20))",
            "Interpolación B-spline de grado p con las derivadas en los extremos D_0, D_n (Piegl y Tiller, §9.2.2): n + 3 puntos de control, los nudos promediados de los parámetros (ec. (9.22)), y el sistema N D = A cuyas filas segunda y penúltima dan las derivadas en los extremos (ecs. (9.19)-(9.20))",
            "u_{j+p+1} = (t_j + ... + t_{j+p-1}) / p,  j = 0, ..., n - p + 1;  Σ_i d_i N_i^p(t_k) = a_k;  d_1 - d_0 = (u_{p+1} - t_0)/p D_0,  d_{n+2} - d_{n+1} = (t_n - u_{n+2})/p D_n",
            r"u_{j+p+1} = \frac{1}{p} \sum_{i=j}^{j+p-1} t_i, \quad j = 0, \dots, n - p + 1; \qquad \sum_i d_i N_i^p(t_k) = a_k; \qquad d_1 - d_0 = \frac{u_{p+1} - t_0}{p} D_0, \quad d_{n+2} - d_{n+1} = \frac{t_n - u_{n+2}}{p} D_n",
        ),
        ConicShape => said(
            "Conic arc: a rational quadratic with the weights (1, w, 1); the shape factor w² says which conic: an ellipse below 1, a parabola at 1, a hyperbola above",
            "Arco de cónica: una cuadrática racional con pesos (1, w, 1); el factor de forma w² dice qué cónica: elipse por debajo de 1, parábola en 1, hipérbola por encima",
            "c(t) = (B_0^2 c_0 + w B_1^2 c_1 + B_2^2 c_2) / (B_0^2 + w B_1^2 + B_2^2),  k = w_1^2/(w_0 w_2)",
            r"c(t) = \frac{B_0^2(t)\, c_0 + w\, B_1^2(t)\, c_1 + B_2^2(t)\, c_2}{B_0^2(t) + w\, B_1^2(t) + B_2^2(t)}, \quad k = \frac{w_1^2}{w_0 w_2}",
        ),
        TangentDevelopable => said(
            "Tangent developable: the surface ruled by the tangent lines of the curve, whose normal vanishes on the curve itself, the edge of regression",
            "Superficie tangente: la superficie reglada por las rectas tangentes de la curva, cuya normal se anula sobre la propia curva, la arista de retroceso",
            "c(u, v) = c(u) + v c'(u),  c_u × c_v = v c''(u) × c'(u)",
            r"c(u, v) = c(u) + v\, c'(u), \quad c_u \times c_v = v\, c''(u) \times c'(u)",
        ),
        ArcLength => said(
            "Arc length: exact when c'·c' is the square of a polynomial σ (Pythagorean hodograph; a line), as the integral of |σ|",
            "Longitud de arco: exacta cuando c'·c' es el cuadrado de un polinomio σ (hodógrafa pitagórica; una recta), como la integral de |σ|",
            "L = ∫_a^b |c'(t)| dt = ∫_a^b |σ(t)| dt,  c'·c' = σ²",
            r"L = \int_a^b |c'(t)|\, dt = \int_a^b |\sigma(t)|\, dt, \quad c' \cdot c' = \sigma^2",
        ),
        RestrictTriangle => said(
            "Restriction of a triangular patch to the sub-triangle (a, b, c): the control points are values of the blossom",
            "Restricción de una superficie triangular al subtriángulo (a, b, c): los puntos de control son valores de la forma polar",
            "c_{i,j,k} = b[a^<i>, b^<j>, c^<k>],  c(ρ, σ, τ) = b(ρ a + σ b + τ c)",
            r"c_{i,j,k} = b[a^{\langle i \rangle}, b^{\langle j \rangle}, c^{\langle k \rangle}], \quad c(\rho, \sigma, \tau) = b(\rho a + \sigma b + \tau c)",
        ),
        IsocurveTriangle => said(
            "Iso-line of a triangular patch: the segment p q of the domain where u (v, or w = 1 - u - v) is constant carries a Bézier curve of degree n, whose control points are values of the blossom",
            "Isolínea de una superficie triangular: sobre el segmento p q del dominio en el que u (v, o w = 1 - u - v) es constante la superficie es una curva de Bézier de grado n, cuyos puntos de control son valores de la forma polar",
            "c_l = b[p^<n-l>, q^<l>],  c(λ) = b((1 - λ) p + λ q)",
            r"c_l = b[p^{\langle n-l \rangle}, q^{\langle l \rangle}], \quad c(\lambda) = b((1 - \lambda)\, p + \lambda\, q)",
        ),
        ReverseTriangle => said(
            "Relabelling of the vertices of a triangular patch: new vertex m is the old vertex σ_m, and each control point moves with its multi-index",
            "Cambio de nombre de los vértices de una superficie triangular: el nuevo vértice m es el antiguo vértice σ_m, y cada punto de control se mueve con su multiíndice",
            "c_{i,j,k} = b[e_{σ1}^<i>, e_{σ2}^<j>, e_{σ3}^<k>]  (σ = (1, 3, 2): c_{i,j,k} = b_{i,k,j})",
            r"c_{i,j,k} = b[e_{\sigma_1}^{\langle i \rangle}, e_{\sigma_2}^{\langle j \rangle}, e_{\sigma_3}^{\langle k \rangle}] \quad (\sigma = (1, 3, 2):\ c_{i,j,k} = b_{i,k,j})",
        ),
        ReverseSurface => said(
            "Reversal of a patch in one direction: the rows of the mesh (in u) or each row (in v) in the opposite order, with the weights; the knots of that direction u ↦ a + b - u, in the opposite order",
            "Inversión del sentido de una superficie en una dirección: las filas de la malla (en u) o cada fila (en v) en orden inverso, con los pesos; los nudos de esa dirección u ↦ a + b - u, en orden inverso",
            "u: c̃_{i,j} = c_{m-i,j}, c̃(u, v) = c(a + b - u, v);  v: c̃_{i,j} = c_{i,n-j}, c̃(u, v) = c(u, c + d - v)",
            r"u\!: \tilde{c}_{i,j} = c_{m-i,j},\ \tilde{c}(u, v) = c(a + b - u, v); \quad v\!: \tilde{c}_{i,j} = c_{i,n-j},\ \tilde{c}(u, v) = c(u, c + d - v)",
        ),
        GraphTriangle => said(
            "Graph of f(x, y) over the triangle (A, B, C) as a triangular patch: the domain point of b_{i,j,k} is (i A + j B + k C)/n, and its height the Bernstein coefficient of f(A + u (B - A) + v (C - A))",
            "Gráfica de f(x, y) sobre el triángulo (A, B, C) como superficie triangular: el punto del dominio de b_{i,j,k} es (i A + j B + k C)/n, y su altura el coeficiente de Bernstein de f(A + u (B - A) + v (C - A))",
            "b_{i,j,k} = ((i A + j B + k C)/n, f̂_{i,j,k}),  f(x(u, v)) = Σ f̂_{i,j,k} B_{i,j,k}^n",
            r"b_{i,j,k} = \left(\frac{i A + j B + k C}{n}, \hat{f}_{i,j,k}\right), \quad f(x(u, v)) = \sum \hat{f}_{i,j,k} B_{i,j,k}^n",
        ),
        RationalTriangle => said(
            "Rational triangular patch: the algorithm runs on the homogeneous points (w b, w) of the net, and each point is divided by its last coordinate (the values below are homogeneous)",
            "Superficie triangular racional: el algoritmo se aplica a los puntos homogéneos (w b, w) de la red, y cada punto se divide por su última coordenada (los valores siguientes son homogéneos)",
            "b(r, s, t) = Σ w_{i,j,k} b_{i,j,k} B_{i,j,k}^n / Σ w_{i,j,k} B_{i,j,k}^n",
            r"b(r, s, t) = \frac{\sum w_{i,j,k}\, b_{i,j,k} B_{i,j,k}^n}{\sum w_{i,j,k} B_{i,j,k}^n}",
        ),
        ReduceTriangle => said(
            "Exact degree reduction of a triangular patch: its closed form (homogeneous for a rational patch) has total degree at most n - r, so it is a patch of degree n - r, whose net is the Bernstein coefficients of that degree",
            "Reducción exacta del grado de una superficie triangular: su forma cerrada (homogénea si es racional) tiene grado total a lo sumo n - r, así que es una superficie de grado n - r, cuya red son los coeficientes de Bernstein de ese grado",
            "b(u, v) = Σ_{i+j+k=n-r} b̃_{i,j,k} B_{i,j,k}^{n-r}",
            r"b(u, v) = \sum_{i+j+k=n-r} \tilde{b}_{i,j,k} B_{i,j,k}^{n-r}",
        ),
        ArcLengthRational => said(
            "Arc length of a rational curve c = p/w: c'·c' = N/w⁴ with N = |p' w - p w'|²; exact when N = σ² and σ/w² has a rational antiderivative g/w",
            "Longitud de arco de una curva racional c = p/w: c'·c' = N/w⁴ con N = |p' w - p w'|²; exacta cuando N = σ² y σ/w² tiene una primitiva racional g/w",
            "L = ∫_a^b |σ(t)|/w(t)² dt = |g(b)/w(b) - g(a)/w(a)|,  g' w - g w' = σ",
            r"L = \int_a^b \frac{|\sigma(t)|}{w(t)^2}\, dt = \left|\frac{g(b)}{w(b)} - \frac{g(a)}{w(a)}\right|, \quad g' w - g w' = \sigma",
        ),
        _ => said("Formula", "Fórmula", "", ""),
    }
}

/// Which readers' legend a formula needs.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Legend {
    Bezier,
    BSpline,
    Patch,
}

fn legend_of(f: Formula) -> Option<Legend> {
    use Formula::*;
    match f {
        DeCasteljau
        | DeCasteljauRational
        | BernsteinSum
        | ElevateCurve
        | RestrictCurve
        | DerivativeCurve
        | ClosedFormCurve
        | ClosedFormRationalCurve
        | InterpolateCurve
        | LeastSquaresCurve => Some(Legend::Bezier),
        DeBoor
        | BSplineSum
        | Boehm
        | ElevateBSpline
        | InterpolateSpline
        | Circle
        | BSplineSurface
        | NurbsSurface
        | InterpolateBicubic
        | PiecewiseSurface
        | DerivativeBSplineSurface
        | KnotLineContinuity
        | SplinePatchesJoin
        | DerivativeBSplineCurve
        | PiecewiseCurve => Some(Legend::BSpline),
        DeCasteljauSurface | BernsteinSurface | RationalSurface | ElevateU | ElevateV
        | ElevateUAtOnce | ElevateVAtOnce | RestrictSurface | DerivativeSurface
        | DerivativeBorder0 | DerivativeBorder1 | CornerNormal | JoinC0 | JoinC1 | JoinCr
        | Graph => Some(Legend::Patch),
        _ => None,
    }
}

fn legend_sentence(l: Legend, lang: Lang) -> &'static str {
    match (l, lang) {
        (Legend::Bezier, Lang::En) => {
            "Farin writes b_i for the control points c_i and b_i^r for c_i^r; The NURBS Book writes P_i."
        }
        (Legend::Bezier, Lang::Es) => {
            "Farin escribe b_i para los puntos de control c_i y b_i^r para c_i^r; Piegl y Tiller escriben P_i."
        }
        (Legend::BSpline, Lang::En) => {
            "The notes' knots are Farin's: The NURBS Book writes P_i for d_i and adds one knot at each end, so its u_i is the notes' u_{i-1}."
        }
        (Legend::BSpline, Lang::Es) => {
            "Los nudos de los apuntes son los de Farin: Piegl y Tiller escriben P_i para d_i y añaden un nudo en cada extremo, de modo que su u_i es el u_{i-1} de los apuntes."
        }
        (Legend::Patch, Lang::En) => {
            "Farin writes b_{i,j} for the mesh c_{i,j}; The NURBS Book writes P_{i,j} and bidegree (p, q) for (m, n)."
        }
        (Legend::Patch, Lang::Es) => {
            "Farin escribe b_{i,j} para la malla c_{i,j}; Piegl y Tiller escriben P_{i,j} y bigrado (p, q) para (m, n)."
        }
    }
}

fn words(lang: Lang, en: &str, es: &str) -> String {
    match lang {
        Lang::En => en.to_string(),
        Lang::Es => es.to_string(),
    }
}

/// `notes, ch. 5, (14)` / `apuntes, tema 5, (14)`.
fn equation_label(f: Formula, lang: Lang) -> Option<String> {
    f.equation().map(|e| match lang {
        Lang::En => format!("notes, ch. {}, ({})", e.chapter, e.number),
        Lang::Es => format!("apuntes, tema {}, ({})", e.chapter, e.number),
    })
}

fn table_title(t: TableTitle, lang: Lang) -> String {
    match t {
        TableTitle::DeCasteljau => words(lang, "De Casteljau scheme", "Esquema de De Casteljau"),
        TableTitle::DeBoor => words(lang, "De Boor scheme", "Esquema de De Boor"),
        TableTitle::Basis => words(lang, "Basis functions", "Funciones base"),
        TableTitle::Differences => words(lang, "Forward differences", "Diferencias progresivas"),
        TableTitle::Alphas => words(lang, "The ratios α_i", "Los cocientes α_i"),
        _ => words(lang, "Table", "Tabla"),
    }
}

/// A fact in words; symbols in `sym` form, values through `value`.
fn fact_words(
    f: &Fact,
    lang: Lang,
    sym: &dyn Fn(&str) -> String,
    value: &dyn Fn(&Exact) -> String,
) -> String {
    match f {
        Fact::Span(span) => {
            let cagd_problem::steps::Span {
                knots,
                t,
                k,
                left,
                right,
            } = span.as_ref();
            let span = format!(
                "{} ≤ {} < {}",
                sym(&format!("{knots}_{{{}}}", k.saturating_sub(1))),
                value(t),
                sym(&format!("{knots}_{{{k}}}"))
            );
            let values = format!("[{}, {})", value(left), value(right));
            match lang {
                Lang::En => format!("The parameter lies in the span {span}, that is {values}; k = {k}."),
                Lang::Es => format!("El parámetro está en el tramo {span}, es decir {values}; k = {k}."),
            }
        }
        Fact::Changed { first, last } => {
            let (a, b) = (sym(&format!("d_{{{first}}}")), sym(&format!("d_{{{last}}}")));
            match lang {
                Lang::En => format!("Only the points {a}, ..., {b} are new; the others are kept (renumbered after them)."),
                Lang::Es => format!("Sólo los puntos {a}, ..., {b} son nuevos; los demás se conservan (renumerados tras ellos)."),
            }
        }
        Fact::Insertion { step, of } => match lang {
            Lang::En => format!("Insertion {step} of {of}:"),
            Lang::Es => format!("Inserción {step} de {of}:"),
        },
        Fact::Homogeneous => words(
            lang,
            "The work is done on the homogeneous points (w c, w); the point is the quotient by the last coordinate.",
            "Se opera con los puntos homogéneos (w c, w); el punto es el cociente por la última coordenada.",
        ),
        Fact::AlongU => words(
            lang,
            "First pass, along u: the algorithm on each column j of the mesh.",
            "Primer paso, en u: el algoritmo en cada columna j de la malla de control.",
        ),
        Fact::AlongV => words(
            lang,
            "Second pass, along v: the algorithm on the points of the first pass.",
            "Segundo paso, en v: el algoritmo sobre los puntos del primer paso.",
        ),
        Fact::EachColumn => words(
            lang,
            "Along u: in each column j of the mesh, with the same knots and ratios.",
            "En u: en cada columna j de la malla de control, con los mismos nudos y cocientes.",
        ),
        Fact::EachRow => words(
            lang,
            "Along v: in each row i of the mesh, with the same knots and ratios.",
            "En v: en cada fila i de la malla de control, con los mismos nudos y cocientes.",
        ),
        Fact::Degree { from, to } => match lang {
            Lang::En => format!("From degree {from} to degree {to}:"),
            Lang::Es => format!("Del grado {from} al grado {to}:"),
        },
        Fact::At { params } => {
            let ps = params.iter().map(value).collect::<Vec<_>>().join(", ");
            match lang {
                Lang::En => format!("At the parameter ({ps}):"),
                Lang::Es => format!("En el parámetro ({ps}):"),
            }
        }
        Fact::Piece { index, interval } => {
            let interval = format!(
                "[{}]",
                interval.iter().map(value).collect::<Vec<_>>().join(", ")
            );
            match lang {
                Lang::En => format!("Bézier piece {index}, on {interval}:"),
                Lang::Es => format!("Tramo de Bézier {index}, en {interval}:"),
            }
        }
        Fact::Construction => words(
            lang,
            "The mesh is built by the construction's formula; its intermediate values follow.",
            "La malla de control se obtiene con la fórmula de la construcción; siguen sus valores intermedios.",
        ),
        Fact::SameForTheOthers { shown, more } => {
            let worked = match (lang, *shown) {
                (Lang::En, 1) => "the steps are worked for the first one".to_string(),
                (Lang::En, k) => format!("the steps are worked for the first {k}"),
                (Lang::Es, 1) => "se desarrollan los pasos del primero".to_string(),
                (Lang::Es, k) => format!("se desarrollan los pasos de los {k} primeros"),
            };
            match (lang, *more == 1) {
                (Lang::En, true) => format!("The other point is found in the same way ({worked})."),
                (Lang::En, false) => format!("The other {more} points are found in the same way ({worked})."),
                (Lang::Es, true) => format!("El otro punto se obtiene del mismo modo ({worked})."),
                (Lang::Es, false) => format!("Los otros {more} puntos se obtienen del mismo modo ({worked})."),
            }
        }
        Fact::SameInTheOtherLines { line, shown, more } => {
            let worked = match (lang, *shown) {
                (Lang::En, 1) => "the steps are shown for the first one".to_string(),
                (Lang::En, k) => format!("the steps are shown for the first {k}"),
                (Lang::Es, 1) => "se desarrollan los pasos de la primera".to_string(),
                (Lang::Es, k) => format!("se desarrollan los pasos de las {k} primeras"),
            };
            match (lang, line, *more == 1) {
                (Lang::En, Line::Column, true) => format!("The other column is worked in the same way ({worked})."),
                (Lang::En, Line::Column, false) => format!("The other {more} columns are worked in the same way ({worked})."),
                (Lang::En, Line::Row, true) => format!("The other row is worked in the same way ({worked})."),
                (Lang::En, Line::Row, false) => format!("The other {more} rows are worked in the same way ({worked})."),
                (Lang::Es, Line::Column, true) => format!("La otra columna se trata del mismo modo ({worked})."),
                (Lang::Es, Line::Column, false) => format!("Las otras {more} columnas se tratan del mismo modo ({worked})."),
                (Lang::Es, Line::Row, true) => format!("La otra fila se trata del mismo modo ({worked})."),
                (Lang::Es, Line::Row, false) => format!("Las otras {more} filas se tratan del mismo modo ({worked})."),
            }
        }
        _ => String::new(),
    }
}

/// What the entries of a matrix shown by its size are, in words; symbols through `sym`.
fn entries_words(e: Entries, lang: Lang, sym: &dyn Fn(&str) -> String) -> String {
    match (e, lang) {
        (Entries::Bernstein, Lang::En) => {
            "row i: the Bernstein polynomials at the i-th parameter".to_string()
        }
        (Entries::Bernstein, Lang::Es) => {
            "fila i: los polinomios de Bernstein en el parámetro i-ésimo".to_string()
        }
        (Entries::TensorBernstein, Lang::En) => format!(
            "row k: {} in column {}",
            sym("B_i^m(u_k) B_j^n(v_k)"),
            sym("i (n+1) + j")
        ),
        (Entries::TensorBernstein, Lang::Es) => format!(
            "fila k: {} en la columna {}",
            sym("B_i^m(u_k) B_j^n(v_k)"),
            sym("i (n+1) + j")
        ),
        (Entries::NormalMatrix, Lang::En) => format!(
            "entry (a, b) = {}, a symmetric matrix",
            sym("\\sum_k B_{k,a} B_{k,b}")
        ),
        (Entries::NormalMatrix, Lang::Es) => format!(
            "elemento (a, b) = {}, una matriz simétrica",
            sym("\\sum_k B_{k,a} B_{k,b}")
        ),
        (Entries::NormalRhs, Lang::En) => format!("row a = {}", sym("\\sum_k B_{k,a} a_k")),
        (Entries::NormalRhs, Lang::Es) => format!("fila a = {}", sym("\\sum_k B_{k,a} a_k")),
        _ => String::new(),
    }
}

/// A matrix shown by its size: `B is a 200 × 49 matrix (row k: ...); its first 2 rows:`.
fn matrix_words(m: &MatrixSummary, lang: Lang, sym: &dyn Fn(&str) -> String) -> String {
    let MatrixSummary {
        symbol,
        rows,
        cols,
        entries,
        first_rows,
    } = m;
    let shown = match first_rows {
        Exact::Matrix(r) => r.len(),
        _ => 0,
    };
    let what = entries_words(*entries, lang, sym);
    let symbol = sym(symbol);
    match (lang, shown) {
        (Lang::En, 1) => format!("{symbol} is a {rows} × {cols} matrix ({what}); its first row:"),
        (Lang::En, _) => {
            format!("{symbol} is a {rows} × {cols} matrix ({what}); its first {shown} rows:")
        }
        (Lang::Es, 1) => {
            format!("{symbol} es una matriz {rows} × {cols} ({what}); su primera fila:")
        }
        (Lang::Es, _) => {
            format!("{symbol} es una matriz {rows} × {cols} ({what}); sus {shown} primeras filas:")
        }
    }
}

/// The rows shown of a matrix in LaTeX: each a list free to break after its commas.
fn rows_latex(first_rows: &Exact) -> Vec<String> {
    match first_rows {
        Exact::Matrix(rows) => rows
            .iter()
            .map(|r| {
                format!(
                    "$({})$",
                    r.iter()
                        .map(Print::to_latex)
                        .collect::<Vec<_>>()
                        .join(",\\allowbreak ")
                )
            })
            .collect(),
        _ => Vec::new(),
    }
}

/// A symbol of the steps in plain text: `\alpha_{3}` → `α_3`, `c_{1,2}` stays.
///
/// ```
/// use cagd_keys::steps::symbol_text;
/// assert_eq!(symbol_text("\\hat{f}_{2,0,0}"), "f\u{302}_{2,0,0}");
/// assert_eq!(symbol_text("\\hat{\\omega} + \\hat{f}"), "\\hat{ω} + f\u{302}");
/// ```
pub fn symbol_text(s: &str) -> String {
    let mut t = s.to_string();
    // an accented letter, `\hat{c}` → ĉ, `\tilde{w}` → w̃ (the letter and a combining accent)
    // (an accent over anything else, `\hat{\alpha}`, stays as written, and the search goes on
    // after it)
    for (accent, mark) in [("\\hat{", '\u{302}'), ("\\tilde{", '\u{303}')] {
        let mut from = 0;
        while let Some(i) = t.get(from..).and_then(|r| r.find(accent)).map(|k| from + k) {
            let body = i + accent.len();
            let mut cs = t.get(body..).unwrap_or_default().chars();
            match (cs.next(), cs.next()) {
                (Some(x), Some('}')) if x.is_ascii_alphabetic() => {
                    // the precomposed letters where Unicode has them (ĉ, û)
                    let accented = match (x, mark) {
                        ('c', '\u{302}') => "ĉ".to_string(),
                        ('u', '\u{302}') => "û".to_string(),
                        _ => format!("{x}{mark}"),
                    };
                    t.replace_range(i..body + x.len_utf8() + 1, &accented);
                    from = i + accented.len();
                }
                _ => from = body,
            }
        }
    }
    for (from, to) in [
        ("\\alpha", "α"),
        ("\\mu", "μ"),
        ("\\sigma", "σ"),
        ("\\omega", "ω"),
        ("\\Delta", "Δ"),
        ("\\cdot", "·"),
        ("\\times", "×"),
        ("\\sum", "Σ"),
        ("\\, ", " "),
        ("\\,", " "),
        ("\\ ", " "),
    ] {
        t = t.replace(from, to);
    }
    // one-character indices lose their braces: `d_{3}` → `d_3`
    let mut out = String::with_capacity(t.len());
    let chars: Vec<char> = t.chars().collect();
    let mut k = 0;
    while let Some(&c) = chars.get(k) {
        if let (true, Some('{'), Some(&x), Some('}')) = (
            c == '_' || c == '^',
            chars.get(k + 1),
            chars.get(k + 2),
            chars.get(k + 3),
        ) {
            out.push(c);
            out.push(x);
            k += 4;
            continue;
        }
        out.push(c);
        k += 1;
    }
    out
}

/// A coefficient before a symbol or value: `1` left out, `-1` as a sign, a negative one
/// subtracted; `(sign, magnitude)` with the magnitude empty for 1.
fn coefficient(c: &Exact, lang: Lang, latex_form: bool) -> (bool, String) {
    let Exact::Number(q) = c else {
        return (false, text(c, lang));
    };
    let negative = q.compare(&Number::from_i64(0)) == Some(std::cmp::Ordering::Less);
    let magnitude = if negative { -q.clone() } else { q.clone() };
    let shown = if magnitude == Number::from_i64(1) {
        String::new()
    } else if latex_form {
        format!("{}\\,", magnitude.to_latex())
    } else {
        format!("{} ", magnitude.to_text())
    };
    (negative, shown)
}

/// `a x + b y - c z`, each term through `show`.
fn sum(
    terms: &[(Exact, String, Exact)],
    lang: Lang,
    latex_form: bool,
    show: &dyn Fn(&str, &Exact) -> String,
) -> String {
    let mut out = String::new();
    for (k, (c, s, v)) in terms.iter().enumerate() {
        let (negative, magnitude) = coefficient(c, lang, latex_form);
        let sign = match (k, negative) {
            (0, false) => "",
            (0, true) => "-",
            (_, false) => " + ",
            (_, true) => " - ",
        };
        out += &format!("{sign}{magnitude}{}", show(s, v));
    }
    out
}

/// Whether the combination is one term with coefficient 1 (a point kept as it was).
fn kept(terms: &[(Exact, String, Exact)]) -> bool {
    matches!(terms, [(Exact::Number(q), _, _)] if *q == Number::from_i64(1))
}

fn text_terms(terms: &[(Exact, String, Exact)], lang: Lang) -> String {
    if kept(terms) {
        return sum(terms, lang, false, &|s, _| symbol_text(s));
    }
    format!(
        "{} = {}",
        sum(terms, lang, false, &|s, _| symbol_text(s)),
        sum(terms, lang, false, &|_, v| text(v, lang))
    )
}

fn latex_terms(terms: &[(Exact, String, Exact)], lang: Lang) -> String {
    if kept(terms) {
        return sum(terms, lang, true, &|s, _| s.to_string());
    }
    format!(
        "{} = {}",
        sum(terms, lang, true, &|s, _| s.to_string()),
        sum(terms, lang, true, &|_, v| latex(v, lang))
    )
}

fn derivation(verdict: &Verdict) -> &[Step] {
    match &verdict.answer {
        Ok(a) => &a.derivation,
        Err(_) => &[],
    }
}

fn legends(steps: &[Step]) -> Vec<Legend> {
    let mut out = Vec::new();
    for s in steps {
        if let Step::Formula { formula, .. } = s {
            if let Some(l) = legend_of(*formula) {
                if !out.contains(&l) {
                    out.push(l);
                }
            }
        }
    }
    out
}

fn heading(lang: Lang) -> String {
    words(lang, "worked solution", "desarrollo")
}

fn legend_heading(lang: Lang) -> String {
    words(lang, "notation", "notación")
}

fn table_text(t: &Table, lang: Lang) -> String {
    let mut grid: Vec<Vec<String>> = Vec::with_capacity(t.rows.len() + 1);
    let mut head = vec![String::new()];
    head.extend(t.columns.iter().map(|c| symbol_text(c)));
    grid.push(head);
    for (label, cells) in &t.rows {
        let mut row = vec![symbol_text(label)];
        row.extend(
            cells
                .iter()
                .map(|c| c.as_ref().map(|x| text(x, lang)).unwrap_or_default()),
        );
        grid.push(row);
    }
    let cols = grid.iter().map(Vec::len).max().unwrap_or(0);
    let widths: Vec<usize> = (0..cols)
        .map(|j| {
            grid.iter()
                .map(|r| r.get(j).map_or(0, |s| s.chars().count()))
                .max()
                .unwrap_or(0)
        })
        .collect();
    let mut out = String::new();
    for row in &grid {
        let line: Vec<String> = row
            .iter()
            .zip(&widths)
            .map(|(s, w)| format!("{s}{}", " ".repeat(w.saturating_sub(s.chars().count()))))
            .collect();
        out += &format!("      {}\n", line.join(" | ").trim_end());
    }
    out
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
            _ => {}
        }
    }
    let legends = legends(steps);
    if !legends.is_empty() {
        out += &format!("  ({}: ", legend_heading(lang));
        out += &legends
            .iter()
            .map(|l| legend_sentence(*l, lang))
            .collect::<Vec<_>>()
            .join(" ");
        out += ")\n";
    }
    out
}

fn table_latex(t: &Table, lang: Lang) -> String {
    let cols = t.columns.len();
    let mut out = format!("\\[\\begin{{array}}{{c|{}}}\n", "c".repeat(cols));
    out += &format!(" & {} \\\\ \\hline\n", t.columns.join(" & "));
    for (label, cells) in &t.rows {
        let cells: Vec<String> = cells
            .iter()
            .map(|c| c.as_ref().map(|x| latex(x, lang)).unwrap_or_default())
            .collect();
        out += &format!("{label} & {} \\\\\n", cells.join(" & "));
    }
    out + "\\end{array}\\]\n"
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

/// Text inside LaTeX: the key's escaping, with `_`-subscripted symbols in math mode.
fn latex_words(s: &str) -> String {
    math_words(s, &crate::escape_latex)
}

/// Words with their symbols (a token with `_`, `^` or a Unicode symbol) in `$...$`, LaTeX
/// inside; the other words through `plain`.
fn math_words(s: &str, plain: &dyn Fn(&str) -> String) -> String {
    /// The symbols written in Unicode in the sentences, and their LaTeX.
    const MATH: [(&str, &str); 16] = [
        ("ĉ", "\\hat{c}"),
        ("d̂", "\\hat{d}"),
        ("c̃", "\\tilde{c}"),
        ("C̃", "\\tilde{C}"),
        ("d̃", "\\tilde{d}"),
        ("α", "\\alpha "),
        ("μ", "\\mu "),
        ("ξ", "\\xi "),
        ("ω", "\\omega "),
        ("Δ", "\\Delta "),
        ("π", "\\pi "),
        ("≤", "\\le "),
        ("×", "\\times "),
        ("·", "\\cdot "),
        ("Σ", "\\sum "),
        ("∈", "\\in "),
    ];
    let mut out = Vec::new();
    for token in s.split(' ') {
        let (lead, body, tail) = split_punctuation(token);
        let special = MATH.iter().any(|(u, _)| body.contains(u));
        if body.contains(['_', '^']) || special {
            let mut math = body.to_string();
            for (u, l) in MATH {
                math = math.replace(u, l);
            }
            out.push(format!("{lead}${}${tail}", math.trim_end()));
        } else {
            out.push(plain(token));
        }
    }
    out.join(" ")
}

/// A word as (opening parentheses, body, closing punctuation): a parenthesis stays in the
/// body when the body opens (closes) it, so `B_i^n(t_k)` keeps its own.
fn split_punctuation(token: &str) -> (&str, &str, &str) {
    let opens = |s: &str| s.matches('(').count();
    let closes = |s: &str| s.matches(')').count();
    let mut start = 0;
    while token[start..].starts_with('(') && opens(&token[start..]) > closes(&token[start..]) {
        start += 1;
    }
    let mut end = token.len();
    loop {
        let body = &token[start..end];
        let Some(last) = body.chars().last() else {
            break;
        };
        let strip =
            matches!(last, ',' | '.' | ';' | ':') || (last == ')' && closes(body) > opens(body));
        if !strip {
            break;
        }
        end -= last.len_utf8();
    }
    (&token[..start], &token[start..end], &token[end..])
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
                    latex_value(v, lang)
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
            _ => {}
        }
    }
    out += "\\end{itemize}\n";
    let legends = legends(steps);
    if !legends.is_empty() {
        out += &format!(
            "\\textit{{{}: {}}}\\\\\n",
            legend_heading(lang),
            legends
                .iter()
                .map(|l| latex_words(legend_sentence(*l, lang)))
                .collect::<Vec<_>>()
                .join(" ")
        );
    }
    out
}

/// A fact in LaTeX: its words escaped, its symbols and values in math mode.
fn fact_latex(
    f: &Fact,
    lang: Lang,
    sym: &dyn Fn(&str) -> String,
    value: &dyn Fn(&Exact) -> String,
) -> String {
    // The facts' own words carry no LaTeX specials but `≤`, `<`, `[`, `(`.
    fact_words(f, lang, sym, value)
        .replace('≤', "$\\le$")
        .replace(" < ", " $<$ ")
        .replace("α", "$\\alpha$")
}

fn table_markdown(t: &Table, lang: Lang) -> String {
    let mut out = format!(
        "| | {} |\n|---|{}\n",
        t.columns
            .iter()
            .map(|c| format!("${c}$"))
            .collect::<Vec<_>>()
            .join(" | "),
        "---|".repeat(t.columns.len())
    );
    for (label, cells) in &t.rows {
        let cells: Vec<String> = cells
            .iter()
            .map(|c| {
                c.as_ref()
                    .map(|x| format!("${}$", latex(x, lang)))
                    .unwrap_or_default()
            })
            .collect();
        out += &format!("| ${label}$ | {} |\n", cells.join(" | "));
    }
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
                    math_words(&words(lang, said.en, said.es), &crate::escape_html),
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
                    math_words(&table_title(*title, lang), &crate::escape_html),
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
            _ => {}
        }
    }
    out += "\n";
    let legends = legends(steps);
    if !legends.is_empty() {
        out += &format!(
            "*{}:* {}\n\n",
            legend_heading(lang),
            legends
                .iter()
                .map(|l| math_words(legend_sentence(*l, lang), &crate::escape_html))
                .collect::<Vec<_>>()
                .join(" ")
        );
    }
    out
}
