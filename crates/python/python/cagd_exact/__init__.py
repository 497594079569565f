"""cagd-exact in Python: exact CAGD for teaching, in the same interpreter as SymPy.

Solve the JSON problems of ``cagd solve`` (docs/format.md) given as dicts, lists or JSON
strings, with numbers as ``int``, ``fractions.Fraction``, SymPy numbers or strings of the
grammar (``"5/6"``, ``"sqrt2/2"``)::

    import cagd_exact as cagd
    answer = cagd.solve({"op": "elevate", "curve": {"bezier": [[0, 0], [1, 2], [3, 3]]}, "by": 1})
    answer["curve"]           # {'bezier': [['0', '0'], ['1/3', '4/3'], ...]}  (the JSON form)
    answer.fractions()        # the same with fractions.Fraction
    answer.sympy()            # SymPy numbers, sqrt(2) for √2, closed forms as expressions
    answer                    # in Jupyter: the answer key, typeset (answer.show(lang="es"))
    answer.figure()           # in Jupyter: the SVG figure; .interactive() the 3D page

A problem solved again is read once: ``p = cagd.read(problem); p.solve()``. Errors raise
``CagdError`` with the command line's message (``str(e)``) and the field path (``e.field``).
"""

from ._native import (
    Answer,
    CagdError,
    Expression,
    Figure,
    Page,
    Problem,
    __version__,
    check,
    examples,
    expand,
    figure,
    generate,
    operations,
    read,
    solve,
    solve_batch,
    topics,
)

__all__ = [
    "Answer",
    "CagdError",
    "Expression",
    "Figure",
    "Page",
    "Problem",
    "__version__",
    "check",
    "examples",
    "expand",
    "figure",
    "generate",
    "operations",
    "read",
    "solve",
    "solve_batch",
    "topics",
]
