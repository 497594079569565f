"""Closed forms and expressions of cagd-exact as SymPy expressions (used by ``Answer.sympy``).

The engine prints a closed form in its grammar (docs/format.md): ``(u, v, -u^3*v + u^3)``,
``3*sqrt2/4*u``, and a rational one as ``(numerator)/(denominator)``. This rewrites the few
spellings SymPy reads otherwise (``^``, ``sqrt2``) and parses the result exactly.
"""

import re

_ROOT = re.compile(r"sqrt\s*(\d+)")
_VARIABLES = "u v w t s x y z".split()


def _parse(text):
    import sympy

    names = {v: sympy.Symbol(v) for v in _VARIABLES}
    names["sqrt"] = sympy.sqrt
    code = _ROOT.sub(r"sqrt(\1)", text).replace("√", "sqrt").replace("^", "**")
    value = sympy.parse_expr(code, local_dict=names, evaluate=True)
    if isinstance(value, tuple):
        value = sympy.Tuple(*value)
    return value


def sympy_expr(text):
    """``text`` as a SymPy expression (a ``Tuple`` for a point or map, a ``Matrix`` divided
    by the denominator for a rational map); words that are not an expression stay a string."""
    import sympy

    rational = re.fullmatch(r"\((.*)\)/\((.*)\)", text.strip(), re.S)
    try:
        if rational and "," in rational.group(1):
            numerator = _parse("(" + rational.group(1) + ")")
            return sympy.Matrix(list(numerator)) / _parse(rational.group(2))
        return _parse(text)
    except (SyntaxError, TypeError, ValueError, sympy.SympifyError, AttributeError):
        return text
