//! What the worked solution says of each [`Formula`]: its sentence in English and Spanish, the
//! formula in text and LaTeX, and the notes' equation number.

use crate::Lang;
use cagd_contract::steps::Formula;

/// A formula: its sentence in English and Spanish, and the formula in text and LaTeX.
pub(super) struct Said {
    pub(super) en: &'static str,
    pub(super) es: &'static str,
    pub(super) text: &'static str,
    pub(super) latex: &'static str,
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
pub(super) fn said_of(f: Formula) -> Said {
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
            "Restriction to [a, b] × [c, d] by the polar form: first each row in v, restricted to [c, d] (the mesh ĉ), then each column of ĉ in u, restricted to [a, b]",
            "Restricción a [a, b] × [c, d] mediante la forma polar: primero cada fila en v, restringida a [c, d] (la malla ĉ), después cada columna de ĉ en u, restringida a [a, b]",
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
            "Mesh of bidegree (m, 1): its two columns, j = 0 and j = 1, are the polygons of c_1 and c_2 (of the same degree m)",
            "Malla de bigrado (m, 1): sus dos columnas, j = 0 y j = 1, son los polígonos de c_1 y c_2 (del mismo grado m)",
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
            "Parametrización de la superficie triangular: la suma de Bernstein con r = 1 - u - v, s = u, t = v",
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
            "Piece by piece: every breakpoint inserted until it has multiplicity p in u and q in v; on each rectangle of spans [u_k, u_{k+1}] × [v_l, v_{l+1}] the (p + 1) × (q + 1) block of the mesh is a Bézier patch (rational for NURBS), written in the surface's own u and v",
            "Por trozos: cada nudo interior se inserta hasta multiplicidad p en u y q en v; en cada rectángulo de intervalos [u_k, u_{k+1}] × [v_l, v_{l+1}] el bloque (p + 1) × (q + 1) de la malla es una superficie de Bézier (racional si es NURBS), escrita en los parámetros u y v de la superficie",
            "c(u, v) = Σ_i Σ_j b_{i,j}^{k,l} B_i^p((u - u_k)/(u_{k+1} - u_k)) B_j^q((v - v_l)/(v_{l+1} - v_l)),  (u, v) ∈ [u_k, u_{k+1}] × [v_l, v_{l+1}]",
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
            "C^r:  ∂^k c/∂u^k (ξ, v) = ∂^k c̃/∂u^k (ξ, v),  k = 0, ..., r",
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
            "Reducción exacta del grado de una superficie triangular: su parametrización (homogénea si es racional) tiene grado total a lo sumo n - r, así que es una superficie de grado n - r, cuya red son los coeficientes de Bernstein de ese grado",
            "b(u, v) = Σ_{i+j+k=n-r} b̃_{i,j,k} B_{i,j,k}^{n-r}",
            r"b(u, v) = \sum_{i+j+k=n-r} \tilde{b}_{i,j,k} B_{i,j,k}^{n-r}",
        ),
        ArcLengthRational => said(
            "Arc length of a rational curve c = p/w: c'·c' = N/w⁴ with N = |p' w - p w'|²; exact when N = σ² and σ/w² has a rational antiderivative g/w",
            "Longitud de arco de una curva racional c = p/w: c'·c' = N/w⁴ con N = |p' w - p w'|²; exacta cuando N = σ² y σ/w² tiene una primitiva racional g/w",
            "L = ∫_a^b |σ(t)|/w(t)² dt = |g(b)/w(b) - g(a)/w(a)|,  g' w - g w' = σ",
            r"L = \int_a^b \frac{|\sigma(t)|}{w(t)^2}\, dt = \left|\frac{g(b)}{w(b)} - \frac{g(a)}{w(a)}\right|, \quad g' w - g w' = \sigma",
        ),
        FindSpan => said(
            "The span of each parameter t (The NURBS Book, algorithm A2.1), its index i counted in the knots as written; at the right end b of the domain, the last non-empty span",
            "El tramo de cada parámetro t (Piegl y Tiller, algoritmo A2.1), su índice i contado en los nudos tal como se dan; en el extremo derecho b del dominio, el último tramo no vacío",
            "u_i ≤ t < u_{i+1}",
            r"u_i \le t < u_{i+1}",
        ),
        UniformKnots => said(
            "Uniform knot vector of n control points and degree p: n + p + 1 equally spaced knots (The NURBS Book's convention; the notes' drops the first and the last)",
            "Sucesión de nudos uniforme de n puntos de control y grado p: n + p + 1 nudos equiespaciados (convenio de Piegl y Tiller; el de los apuntes quita el primero y el último)",
            "u_i = a + i (b - a)/(n + p),  i = 0, ..., n + p",
            r"u_i = a + i\, \frac{b - a}{n + p}, \quad i = 0, \dots, n + p",
        ),
        OpenUniformKnots => said(
            "Open uniform knot vector of n control points and degree p: each end p + 1 times (The NURBS Book's convention; p times in the notes'), the interior knots equally spaced",
            "Sucesión de nudos uniforme con extremos repetidos, de n puntos de control y grado p: cada extremo p + 1 veces (convenio de Piegl y Tiller; p veces en el de los apuntes), los nudos interiores equiespaciados",
            "u_0 = ... = u_p = a,  u_{p+j} = a + j (b - a)/(n - p),  u_n = ... = u_{n+p} = b",
            r"u_0 = \dots = u_p = a, \quad u_{p+j} = a + j\, \frac{b - a}{n - p}, \quad u_n = \dots = u_{n+p} = b",
        ),
        NormalizeKnots => said(
            "Reparametrization onto [0, 1]: each knot mapped affinely, the control points and weights kept; the new curve at s is the old one at a + s (b - a)",
            "Reparametrización sobre [0, 1]: cada nudo por la aplicación afín, los puntos de control y los pesos se conservan; la nueva curva en s es la antigua en a + s (b - a)",
            "ũ_i = (u_i - a)/(b - a),  c̃(s) = c(a + s (b - a))",
            r"\tilde{u}_i = \frac{u_i - a}{b - a}, \quad \tilde{c}(s) = c(a + s\, (b - a))",
        ),
        _ => said("Formula", "Fórmula", "", ""),
    }
}

/// `notes, ch. 5, (14)` / `apuntes, tema 5, (14)`.
pub(super) fn equation_label(f: Formula, lang: Lang) -> Option<String> {
    f.equation().map(|e| match lang {
        Lang::En => format!("notes, ch. {}, ({})", e.chapter, e.number),
        Lang::Es => format!("apuntes, tema {}, ({})", e.chapter, e.number),
    })
}
