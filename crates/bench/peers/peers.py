"""The tasks T1-T6 of cagd-exact's performance issue in SymPy and in python-flint.

Reads the inputs, exact answers and timings written by `peers-data` (cagd-bench), runs the same
tasks in SymPy (`sympy.Matrix` of `Rational`, the API a teacher uses) and in python-flint (the
best formulation found: `fmpq_mat` products for T1/T2/T3/T5, `fmpq_mat.solve` for T4/T6),
checks that every exact answer equals cagd-exact's, and writes docs/performance.md.

Run through run.sh, which makes the virtual environment and builds the Rust side.
"""

import argparse
import json
import math
import os
import platform
import re
import statistics
import subprocess
import tempfile
import sys
import time
from fractions import Fraction

from problems import problem_json

import flint
import sympy
from flint import fmpq, fmpq_mat, fmpq_poly, fmpz

try:  # the Python module (crates/python), when run.sh installed it in this interpreter
    import cagd_exact
except ImportError:
    cagd_exact = None

BUDGET = 1.0  # seconds of repeats for fast peers
SLOW = 2.0  # a peer slower than this runs once


def timed(f, budget=BUDGET):
    """Median time of f() over repeats (once when it is slow), and its last result."""
    t0 = time.perf_counter()
    result = f()
    first = time.perf_counter() - t0
    if first > SLOW:
        return first, result
    times = [first]
    start = time.perf_counter()
    while len(times) < 3 or (time.perf_counter() - start < budget and len(times) < 50):
        t0 = time.perf_counter()
        result = f()
        times.append(time.perf_counter() - t0)
    return statistics.median(times), result


def split(text):
    p, _, q = text.partition("/")
    return int(p), int(q or 1)


# ---------------------------------------------------------------- the inputs, in each library


class Lib:
    """The few operations the tasks need, in one library."""

    def __init__(self, name, num, mat, zeros, transpose, solve, get, polymul):
        self.name = name
        self.num = num  # (p, q) -> exact rational
        self.mat = mat  # list of rows -> matrix
        self.zeros = zeros
        self.transpose = transpose
        self.solve = solve  # (A, B) -> X with A X = B
        self.get = get  # (M, i, j) -> entry
        self.polymul = polymul  # coefficient lists -> product coefficient list


def _poly_mul_lists(a, b):
    out = [a[0] * 0] * (len(a) + len(b) - 1)
    for i, x in enumerate(a):
        for j, y in enumerate(b):
            out[i + j] += x * y
    return out


SYMPY = Lib(
    "SymPy",
    lambda p, q: sympy.Rational(p, q),
    lambda rows: sympy.Matrix(rows),
    lambda r, c: sympy.zeros(r, c),
    lambda m: m.T,
    lambda a, b: a.LUsolve(b),
    lambda m, i, j: m[i, j],
    _poly_mul_lists,
)


def _flint_polymul(a, b):
    prod = fmpq_poly(a) * fmpq_poly(b)
    coeffs = prod.coeffs()
    return [fmpq(c) for c in coeffs] + [fmpq(0)] * (len(a) + len(b) - 1 - len(coeffs))


FLINT = Lib(
    "FLINT",
    lambda p, q: fmpq(p, q),
    lambda rows: fmpq_mat(rows),
    lambda r, c: fmpq_mat(r, c),
    lambda m: m.transpose(),
    lambda a, b: a.solve(b),
    lambda m, i, j: m[i, j],
    _flint_polymul,
)


def binomial(n, k):
    return math.comb(n, k)


def bernstein_row(lib, n, t):
    """B_0^n(t), ..., B_n^n(t)."""
    one = lib.num(1, 1)
    s = one - t
    tp = [one]
    sp = [one]
    for _ in range(n):
        tp.append(tp[-1] * t)
        sp.append(sp[-1] * s)
    return [binomial(n, i) * tp[i] * sp[n - i] for i in range(n + 1)]


def coordinate_matrices(lib, mesh):
    return [lib.mat([[lib.num(*split(p[k])) for p in row] for row in mesh]) for k in range(3)]


def elevation_matrix(lib, n, r):
    return lib.mat(
        [
            [
                lib.num(binomial(n, j) * binomial(r, i - j), binomial(n + r, i))
                if 0 <= i - j <= r
                else lib.num(0, 1)
                for j in range(n + 1)
            ]
            for i in range(n + r + 1)
        ]
    )


def restriction_matrix(lib, n, a, b):
    """Row i: the coefficients of ((1 - a) + a x)^(n - i) ((1 - b) + b x)^i."""
    one = lib.num(1, 1)
    rows = []
    for i in range(n + 1):
        poly = [one]
        for _ in range(n - i):
            poly = lib.polymul(poly, [one - a, a])
        for _ in range(i):
            poly = lib.polymul(poly, [one - b, b])
        rows.append(poly)
    return lib.mat(rows)


def power_matrix(lib, n):
    return lib.mat(
        [
            [
                lib.num((-1) ** (k - i) * binomial(n, k) * binomial(k, i), 1) if i <= k else lib.num(0, 1)
                for i in range(n + 1)
            ]
            for k in range(n + 1)
        ]
    )


# ---------------------------------------------------------------- the tasks


def t1(lib, task, inp):
    n = task["n"]
    coords = inp["coords"]
    params = inp["params"]

    def run():
        bu = [bernstein_row(lib, n, u) for u, _ in params]
        bv = [bernstein_row(lib, n, v) for _, v in params]
        mu = lib.mat(bu)
        out = []
        for c in coords:
            x = mu * c
            out.append([sum((lib.get(x, p, j) * bv[p][j] for j in range(n + 1)), lib.num(0, 1)) for p in range(len(params))])
        return [out[k][p] for p in range(len(params)) for k in range(3)]

    return run


def nrows(m):
    return m.nrows() if hasattr(m, "nrows") else m.rows


def sandwich(lib, left, coords, right):
    """left · C_k · rightᵀ for each coordinate, flattened row by row, x, y, z."""
    rt = lib.transpose(right)
    results = [left * c * rt for c in coords]
    rows, cols = nrows(left), nrows(right)
    return [lib.get(results[k], i, j) for i in range(rows) for j in range(cols) for k in range(3)]


def t2(lib, task, inp):
    n, r = task["n"], task["extra"]
    coords = inp["coords"]

    def run():
        e = elevation_matrix(lib, n, r)
        return sandwich(lib, e, coords, e)

    return run


def t3(lib, task, inp):
    n = task["n"]
    coords = inp["coords"]
    a, b, c, d = lib.num(1, 3), lib.num(3, 4), lib.num(1, 5), lib.num(1, 2)

    def run():
        return sandwich(lib, restriction_matrix(lib, n, a, b), coords, restriction_matrix(lib, n, c, d))

    return run


def t4(lib, task, inp):
    n = task["n"]
    coords = inp["coords"]
    size = n + 1

    def run():
        b = lib.mat([bernstein_row(lib, n, lib.num(i, n)) for i in range(size)])
        # first pass, B X = A for the three coordinates at once (A_x | A_y | A_z)
        stacked = lib.mat([[lib.get(coords[k], i, j) for k in range(3) for j in range(size)] for i in range(size)])
        x = lib.solve(b, stacked)
        # second pass, C B_Vᵗ = X, i.e. B_V Cᵗ = Xᵗ, for the three coordinates at once
        xt = lib.mat([[lib.get(x, i, k * size + j) for k in range(3) for i in range(size)] for j in range(size)])
        ct = lib.solve(b, xt)
        return [lib.get(ct, j, k * size + i) for i in range(size) for j in range(size) for k in range(3)]

    return run


def t5(lib, task, inp):
    n = task["n"]
    coords = inp["coords"]

    def run():
        m = power_matrix(lib, n)
        mt = lib.transpose(m)
        results = [m * c * mt for c in coords]
        return [lib.get(results[k], i, j) for k in range(3) for i in range(n + 1) for j in range(n + 1)]

    return run


def t6(lib, task, inp):
    n = task["n"]
    params = inp["params"]
    data = inp["points"]

    def run():
        rows = []
        for u, v in params:
            bu = bernstein_row(lib, n, u)
            bv = bernstein_row(lib, n, v)
            rows.append([x * y for x in bu for y in bv])
        b = lib.mat(rows)
        bt = lib.transpose(b)
        c = lib.solve(bt * b, bt * data)
        unknowns = (n + 1) ** 2
        return [lib.get(c, i, k) for i in range(unknowns) for k in range(3)]

    return run


TASKS = {"T1": t1, "T2": t2, "T3": t3, "T4": t4, "T5": t5, "T6": t6}


def prepare(lib, task):
    raw = task["input"]
    num = lambda s: lib.num(*split(s))
    return {
        "coords": coordinate_matrices(lib, raw["mesh"]),
        "params": [(num(u), num(v)) for u, v in raw["params"]],
        "points": lib.mat([[num(x) for x in p] for p in raw["points"]]) if raw["points"] else None,
    }


def check(values, expected):
    if len(values) != len(expected):
        return False
    for x, e in zip(values, expected):
        p, q = split(e)
        if isinstance(x, fmpq):
            if x != fmpq(p, q):
                return False
        elif sympy.Rational(x) != sympy.Rational(p, q):
            return False
    return True


# ---------------------------------------------------------------- the same tasks as `cagd solve` processes


def frac(x):
    """A number of an answer (a JSON integer or a string p/q) as an exact Fraction."""
    return Fraction(x) if isinstance(x, int) else Fraction(x.replace(" ", ""))


_TERM = re.compile(r"([+-]?)\s*([0-9]+(?:/[0-9]+)?)?\*?((?:[uv](?:\^[0-9]+)?\*?)*)$")


def closed_form_coefficients(text, n):
    """The coefficients of u^k v^l (k, l = 0..n) of each coordinate of a printed closed form
    `(p_x, p_y, p_z)` (docs/format.md: the JSON printer form), in the order of Task::flatten."""
    body = text.strip()
    if not (body.startswith("(") and body.endswith(")")):
        raise ValueError(f"not a tuple: {text[:80]}")
    out = []
    for comp in body[1:-1].split(","):
        coeffs = {}
        # split at the + and - between terms (a term is a coefficient and powers of u and v)
        for term in re.findall(r"[+-]?\s*[^+-]+", comp.strip()):
            m = _TERM.match(term.strip())
            if not m:
                raise ValueError(f"cannot read the term {term!r}")
            sign, coeff, mono = m.groups()
            c = Fraction(coeff) if coeff else Fraction(1)
            powers = {"u": 0, "v": 0}
            for factor in filter(None, mono.split("*")):
                var, _, e = factor.partition("^")
                powers[var] += int(e or 1)
            key = (powers["u"], powers["v"])
            coeffs[key] = coeffs.get(key, 0) + (-c if sign == "-" else c)
        if any(c and (k > n or l > n) for (k, l), c in coeffs.items()):
            raise ValueError(f"a term of degree above ({n}, {n}) in {comp.strip()[:80]}")
        out.extend(coeffs.get((k, l), Fraction(0)) for k in range(n + 1) for l in range(n + 1))
    return out


def process_answer(task, doc):
    """The numbers of `cagd solve --format json`'s answer in the order of Task::flatten."""
    if not doc.get("ok"):
        raise ValueError(doc.get("error", "not ok"))
    result = doc["result"]
    if task["label"] == "T1":
        return [frac(x) for p in result["points"] for x in p]
    if task["label"] == "T5":
        return closed_form_coefficients(result["closed_form"], task["n"])
    return [frac(x) for row in result["surface"]["bezier"] for p in row for x in p]


def same_answer(values, expected):
    return len(values) == len(expected) and all(v == Fraction(e) for v, e in zip(values, expected))


def run_process(cmd):
    """One run of cmd, its output to /dev/null: wall time, as Python sees it (fork, exec, the
    whole run, the exit)."""
    t0 = time.perf_counter()
    done = subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    seconds = time.perf_counter() - t0
    if done.returncode != 0:
        raise RuntimeError(f"{' '.join(cmd)} exited with {done.returncode}")
    return seconds


def timed_process(cmd, budget=BUDGET):
    """Median wall time of the process cmd over repeats (at least 5, at most 100)."""
    run_process(cmd)  # warm the page cache
    times = []
    start = time.perf_counter()
    while len(times) < 5 or (time.perf_counter() - start < budget and len(times) < 100):
        times.append(run_process(cmd))
    return statistics.median(times), min(times), len(times)


def timed_side_by_side(f, cmd, budget=3 * BUDGET):
    """FLINT's f() and the process cmd, alternately (so that both see the same load), at least 7
    times each: the median of each, the minimum of each, the number of runs, and f's last result."""
    result = f()
    run_process(cmd)
    ft, pt = [], []
    start = time.perf_counter()
    while len(ft) < 7 or (time.perf_counter() - start < budget and len(ft) < 50):
        t0 = time.perf_counter()
        result = f()
        ft.append(time.perf_counter() - t0)
        pt.append(run_process(cmd))
    return {
        "flint": statistics.median(ft),
        "flint_min": min(ft),
        "process": statistics.median(pt),
        "process_min": min(pt),
        "runs": len(ft),
        "result": result,
    }


def peak_rss(cmd):
    """The peak resident memory, in bytes, of one run of cmd, as GNU time reports it (%M, from
    wait4 on its own child). Python's own rusage of a child would count the interpreter it was
    forked from (the high-water mark survives exec); None without /usr/bin/time."""
    if not os.path.exists("/usr/bin/time"):
        return None
    with tempfile.NamedTemporaryFile("r") as out:
        done = subprocess.run(["/usr/bin/time", "-f", "%M", "-o", out.name] + cmd,
                              stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        if done.returncode not in (0, 1):
            raise RuntimeError(f"{' '.join(cmd)} exited with {done.returncode}")
        return int(out.read().split()[-1]) * 1024


def run_process_rss(cmd):
    """One run of cmd, output to /dev/null: wall time (as run_process, any exit code of cagd
    solve's: 1 says a problem failed) and peak memory (a second run, under GNU time)."""
    t0 = time.perf_counter()
    done = subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    seconds = time.perf_counter() - t0
    if done.returncode not in (0, 1):
        raise RuntimeError(f"{' '.join(cmd)} exited with {done.returncode}")
    return seconds, peak_rss(cmd)


def run_process_cpu(cmd):
    """One run of cmd, output to /dev/null: (wall time, CPU time of the child, user + system,
    from its own rusage: what it cost whatever else the machine was running)."""
    t0 = time.perf_counter()
    child = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    _, status, usage = os.wait4(child.pid, 0)
    seconds = time.perf_counter() - t0
    child.returncode = os.waitstatus_to_exitcode(status)
    if child.returncode not in (0, 1):
        raise RuntimeError(f"{' '.join(cmd)} exited with {child.returncode}")
    return seconds, usage.ru_utime + usage.ru_stime


def timed_batch(cmd, copies, budget=BUDGET):
    """The time per problem of a batch process of `copies` problems: the median of at least 3
    runs (1 when a run takes over 2 s), divided by `copies`; wall time, and CPU time."""
    runs = [run_process_cpu(cmd)]
    start = time.perf_counter()
    if runs[0][0] < 2.0:
        while len(runs) < 3 or (time.perf_counter() - start < budget and len(runs) < 20):
            runs.append(run_process_cpu(cmd))
    seconds = statistics.median(t for t, _ in runs)
    cpu = statistics.median(c for _, c in runs)
    return {"per_problem": seconds / copies, "cpu_per_problem": cpu / copies, "seconds": seconds, "runs": len(runs)}


def timed_batch_beside(f, cmd, copies, budget=3 * BUDGET):
    """A batch process of `copies` problems and FLINT's f(), alternately, so that both see the same
    load (this machine's speed moves by up to 1.5x for tens of seconds at a time): each round one run
    of the batch, then f() repeated for about as long. Per problem, the median wall and CPU time of
    the batch (at least 5 runs, 1 when a run takes over 2 s), and the median time of one f() beside
    it."""
    f()
    run_process_cpu(cmd)
    runs, flint = [], []
    start = time.perf_counter()
    while not runs or (runs[0][0] < 2.0 and (len(runs) < 5 or (time.perf_counter() - start < budget and len(runs) < 20))):
        runs.append(run_process_cpu(cmd))
        one = flint[-1] if flint else runs[-1][0] / copies
        reps = max(1, min(copies, round(runs[-1][0] / max(one, 1e-7))))
        t0 = time.perf_counter()
        for _ in range(reps):
            f()
        flint.append((time.perf_counter() - t0) / reps)
    seconds = statistics.median(t for t, _ in runs)
    cpu = statistics.median(c for _, c in runs)
    return {"per_problem": seconds / copies, "cpu_per_problem": cpu / copies, "seconds": seconds, "runs": len(runs),
            "flint": statistics.median(flint)}


def write_batch(path, problem, copies):
    with open(path, "w") as f:
        json.dump([problem] * copies, f)


BATCH = 100  # problems per batch of one task
STEPS_FEW = 10  # problems per batch with --steps where a batch of BATCH takes over a second


def timed_in_process(f, problem, budget=3 * BUDGET):
    """FLINT's f(), `cagd_exact.solve(problem)` from the dict, and `Problem.solve()` of the
    problem read once, alternately in this interpreter (so that all three see the same load), at
    least 7 times each: the median and minimum of each, the number of runs, and the last answers
    of both cagd_exact calls (answer objects; their numbers are converted only when read, after
    the timing)."""
    read = cagd_exact.read(problem)
    f(), cagd_exact.solve(problem), read.solve()
    times = {"flint": [], "dict": [], "read": []}
    start = time.perf_counter()
    while len(times["flint"]) < 7 or (time.perf_counter() - start < budget and len(times["flint"]) < 50):
        t0 = time.perf_counter()
        f()
        t1 = time.perf_counter()
        from_dict = cagd_exact.solve(problem)
        t2 = time.perf_counter()
        from_read = read.solve()
        t3 = time.perf_counter()
        times["flint"].append(t1 - t0)
        times["dict"].append(t2 - t1)
        times["read"].append(t3 - t2)
    out = {k: statistics.median(v) for k, v in times.items()}
    out.update({f"{k}_min": min(v) for k, v in times.items()})
    # what reading the whole answer out costs afterwards (not in the times above)
    printing = []
    for _ in range(5):
        t0 = time.perf_counter()
        from_dict.to_json()
        printing.append(time.perf_counter() - t0)
    out["to_json"] = statistics.median(printing)
    out["runs"] = len(times["flint"])
    out["answers"] = (from_dict, from_read)
    return out


def check_in_process(task, answers):
    """Both cagd_exact answers, as `cagd solve --format json` would print them, equal the
    library's exactly."""
    try:
        return all(same_answer(process_answer(task, a.to_json()), task["answer"]) for a in answers)
    except (ValueError, KeyError, TypeError, ZeroDivisionError) as e:
        print(f"{task['name']}: cannot read cagd_exact's answer: {e}", file=sys.stderr)
        return False


def solve_command(cagd_bin, path):
    return [cagd_bin, "solve", path, "--format", "json"]


def check_process(cagd_bin, task, path):
    """Runs `cagd solve FILE --format json` once and compares its answer, exactly, with the
    library's (peers-data's)."""
    done = subprocess.run(solve_command(cagd_bin, path), capture_output=True, text=True)
    if done.returncode != 0:
        print(f"{task['name']}: cagd solve exited with {done.returncode}: {done.stderr[:300]}", file=sys.stderr)
        return False
    try:
        values = process_answer(task, json.loads(done.stdout))
    except (ValueError, KeyError, TypeError, ZeroDivisionError) as e:
        print(f"{task['name']}: cannot read the answer of cagd solve: {e}", file=sys.stderr)
        return False
    return same_answer(values, task["answer"])


# ---------------------------------------------------------------- the report


def fmt_time(s):
    if s is None:
        return "—"
    if s >= 1:
        return f"{s:.2f} s"
    if s >= 1e-3:
        return f"{s * 1e3:.2f} ms"
    return f"{s * 1e6:.0f} µs"


def fmt_ratio(x):
    if x is None:
        return "—"
    if x >= 100:
        return f"{x:,.0f}x"
    if x >= 10:
        return f"{x:.0f}x"
    return f"{x:.2f}x"


def exponent(points):
    """Slope of log(time) against log(n) by least squares."""
    pts = [(math.log(n), math.log(t)) for n, t in points if t and t > 0]
    if len(pts) < 2:
        return None
    mx = sum(x for x, _ in pts) / len(pts)
    my = sum(y for _, y in pts) / len(pts)
    sxx = sum((x - mx) ** 2 for x, _ in pts)
    if sxx == 0:
        return None
    return sum((x - mx) * (y - my) for x, y in pts) / sxx


EXPECTED = {
    "T1": ("n^2 (times the growth of the numbers)", "Bernstein values once per parameter, then a contraction with the mesh: (n+1)^2 multiply-adds per point and coordinate"),
    "T2": ("n^3", "E C E^T with the elevation matrix E"),
    "T3": ("n^3", "R_u C R_v^T with the blossom (restriction) matrices"),
    "T4": ("n^3 (times the growth of the numbers)", "C = B^-1 A B^-T with B^-1 written from the Lagrange polynomials"),
    "T5": ("n^3", "M C M^T with the integer Bernstein-to-monomial matrix"),
    "T6": ("n^6 (the (n+1)^2 unknowns: cubic elimination) times the growth of the numbers", "normal equations on integers, Cramer's rule modulo primes"),
}

SYMPY_NOTE = (
    "SymPy's `Matrix` products and `LUsolve` on `Rational` entries run here on FLINT ground types, "
    "so this SymPy is only 5-20x slower than FLINT itself: 100x faster than it means 5-20x faster "
    "than FLINT. (The issue's own SymPy figures, 10-100x slower than these, came from slower "
    "formulations; see the last table.)"
)

SMALL = (
    "At n = 3 the whole task takes microseconds and most of it is allocating the answer: every "
    "coordinate is a `BigRational` (two heap allocations), and SymPy needs only a fraction of a "
    "millisecond for products of 4 x 4 matrices, so 100x would mean some 40 ns per output number."
)

WHY_SYMPY = {
    "T1": "each point is one call of the public `BezierSurface::eval` (domain check, Bernstein numerators, three reduced `BigRational`s), while SymPy multiplies one 100 x (n+1) Bernstein matrix.",
    "T2": "the product runs in machine integers; what remains is building the answer, (n+k+1)^2 points of three reduced `BigRational`s (two heap allocations per number): 100x SymPy would mean about 80 ns per output number at n = 20, k = 5 (2,028 numbers) and under 40 ns at n = 3.",
    "T3": "the restriction returns both steps (the row step ĉ is part of the answer): twice the output. " + SMALL,
    "T4": SMALL,
    "T5": "the closed form is a `Poly` (a sorted map from monomials to coefficients) with 3(n+1)^2 terms, where SymPy and FLINT return a matrix. " + SMALL,
    "T6": "at small n the work is big-integer work in num-bigint: the normal equations from 50-200 rows of Bernstein numerators, a fraction-free solve, and 3(n+1)^2 answers, rationals of 300 to 4,000 bits, reduced with gcds; SymPy's `LUsolve` on FLINT ground types does the same work in GMP, with less than 100x of interpreter overhead on top.",
}

WHY_FLINT = {
    "T1": "each point is one API call with its own setup.",
    "T2": "the answer's `BigRational`s dominate.",
    "T3": "both steps are computed and reduced.",
    "T4": "from n ≈ 20 the entries of B^-1 outgrow machine integers and the products run in num-bigint, slower than GMP.",
    "T5": "the answer is a `Poly`.",
    "T6": "the normal matrix BᵗB has entries of about 270 bits (the common denominator of B is lcm(q_k s_k)^n) and a determinant of about 13,000 bits at n = 6. cagd-exact solves the integer system modulo primes just below 2^62 (each row reduced into 128-bit accumulators, one reduction per three updates), stopping as soon as a rational reconstruction of the solution checks exactly (checkpoints growing by half, at most Hadamard's bound of ~220 primes), on both cores, and reduces the answers with a Lehmer gcd on num-bigint; FLINT uses p-adic (Dixon) lifting and GMP.",
}


PROCESS_NOTE = (
    "Where the time of the process goes (callgrind: shares of the instructions of the whole process, measured "
    "when this column was added, on these inputs): for T4 n=30, solving 39% (`interpolate_bezier_surface`), the closed form 29% "
    "(`mesh_closed_form`: `interpolate` and `approximate` answer with the monomial form too, which FLINT's "
    "formulation does not compute), printing the answer 20% (the closed form's string 13%, the mesh 4%, "
    "pretty JSON 2%), reading the problem 8% (the number grammar 7%, JSON 0.4%). For T6 n=6 M=50, solving "
    "84% (normal equations 24%, the multimodular solve 53% on two threads), the closed form 6%, printing 8%, "
    "reading 2%. Sampled with perf, about a tenth of either process is the kernel (page faults, "
    "mostly), and malloc and free take 24% of T4's and 9% of T6's."
)


# The table (SymPy 1.14 on FLINT ground types, python-flint 0.9, best formulation of
# each, measured by the author on this machine).
REFERENCE = [
    ("T1 n=20", 18.8, 16.8e-3),
    ("T2 n=20 k=5", 0.235, 0.93e-3),
    ("T3 n=20", 1.35, 1.6e-3),
    ("T4 n=30", 6.27, 55.7e-3),
    ("T5 n=10", 4.14, 0.24e-3),
    ("T6 n=6 M=200", 8.91, 145e-3),
]


# The done-means for the whole process: these rows within 2x of FLINT.
PROCESS_TARGETS = ("T4 n=30", "T6 n=6 M=50")

# The batches whose peak memory is measured (copies of MEMORY_TASK).
MEMORY_TASK = "T2 n=3 k=1"
MEMORY_BATCHES = (100, 1000, 10000)

# The batch whose scaling with --threads is measured: copies of THREADS_TASK.
THREADS_TASK = "T2 n=10 k=5"
THREADS_COPIES = 1000

# Where the time of batches and of --steps goes (callgrind, measured when the columns were
# added); empty until measured.
BATCH_NOTE = """Where the time goes (callgrind instruction counts of `cagd solve BATCH --format json`, repeatable under load;
FLINT's own figures move by up to 2x between runs on this shared machine, e.g. T5 (3, 3) 27 µs beside the batch in
the run before this one, 45 µs in this one):

- **The smallest batches** (T2 (3, 3) k=1, T5 (3, 3) and (6, 6)) missed in the run before this one (1.55x,
  2.17x, 1.82x of FLINT beside the batch, which is hot as the batch's problems are). FLINT starts from its
  matrices already built; cagd-exact reads and writes every number as text, which at these sizes was half of a
  problem. Callgrind, instructions per problem of 100 copies, before → after this run's changes: T2 (3, 3) k=1
  256,000 → 148,000, T5 (3, 3) 282,000 → 110,000, T5 (6, 6) 800,000 → 298,000, T1 (3, 3) 2.42 M → 1.84 M.
  Now at 0.90x, 0.95x and 0.77x: the first two are near the line, and the run-to-run movement of FLINT's own
  figure is larger than their margin. Two runs of this script filtered to one task each, right after this one
  (`PEERS_FILTER="T5 n=3"`, then `"T2 n=3 k=1"`), gave 0.88x (38 µs against 43 µs) and 0.83x (44 µs against
  53 µs).
  - **Reading**: a number `±p` or `±p/q` is read in one pass over its bytes (`cagd_scalar::word_literal`, the
    grammar only for the rest); a problem whose first key is `op` is read in one pass into its operation's type;
    a shape's points are read where they stand; the batch splitter skips to the next quote, bracket or brace.
    T2 (3, 3) k=1: reading, splitting and building the patch 114,000 → 49,000 per problem.
  - **The closed form**: on machine integers, by forward differences over each coordinate's common
    denominator (`a_kl = C(m, k) C(n, l) Δ_u^k Δ_v^l c_00`), built in the answer's scalar; `Poly` keeps its
    terms in one sorted vector (no BTreeMap); a map of small rationals is printed as bytes. T5 (3, 3): the
    operation 134,000 → 30,000 per problem, its printing 33,000 → 18,000.
  - **Writing**: the pretty JSON of an answer is written straight into bytes (`crates/contract/src/pretty.rs`,
    tested byte for byte against serde_json's on every fixture), a rational's digits with no `String`. T2 (3,
    3) k=1: writing 38,500 → 21,500 per problem.
  - **Elevation**: machine-integer answers go back to the scalar without a big rational
    (`ExactRational::from_small_ratio`, reduced on words), a square mesh elevated alike in u and v builds its
    matrix once.
  - **The build**: the release profile links with fat LTO in one codegen unit (100 x T5 (3, 3) 21.25 M →
    19.64 M instructions before the other changes, T6 (2, 2)/50 398.6 M → 366.3 M).
- **T6 batches**: the library call alone is 0.6-0.8x FLINT's (first table), and the multimodular solve runs
  on two threads, so the wall time of a problem grows when the other core is busy (its CPU time, in the table,
  does not); the solve is cagd-fit's.
- **Single processes**: below a few milliseconds of work a process is mostly the floor below.
- **T6 (4, 4) with 50 points as one process** (1.84x here, 1.75x in the run before, 2.14x in the one before
  it, with FLINT's call at 5.87 ms, 7.91 ms and 5.19 ms): the nearest process row to the line. The same problem
  costs about 6.7 ms in a batch; alone, the process pays the floor and a cold start (about 440 page faults on one
  core, against 135 for the empty batch).
- **`--steps`**: a key works a big problem as a teacher does on the board, and computes only what it shows
  (`crates/ops/src/explain.rs`: `WORKED_LINES`, `WORKED_COMBINATIONS`, `WHOLE_MATRIX_ENTRIES`): a patch
  of more than 4 columns has its first point worked (the first column's De Casteljau scheme, the others' results,
  the scheme along v), a pass of elevation of more than 24 combinations its first column and row elevated by r at
  once, a matrix of more than 64 entries (B_U, B_V, B, BᵀB, BᵀA) its size, what its entries are and its first 2
  rows, on the fast paths' results (BᵀB and BᵀA's rows from the integer normal equations); De Casteljau's
  triangle runs on integers. Callgrind, per problem, before → after: T1 (20, 20) 13x → 1.35x, T2 (10, 10) k=5
  15.9x → 1.78x, T4 (30, 30) 5.1x → 1.0x, T6 (4, 4)/200 57x → 1.11x; every row at or below 2.3x (T2 (3, 3) k=1
  2.14x, T4 (6, 6) 2.29x: the notes' sizes keep every step).
- **The floor**: `cagd solve []` executed 859,000 instructions two runs ago (the dynamic loader applying
  8,421 relative relocations of a position-independent binary, clap building every subcommand, glibc's
  `pthread_getattr_np` for Rust's main-thread stack guard); the last run's binary, linked without PIE and
  parsing `solve` with its own clap command, 720,000, with 202 page faults (49 for `true`). Page faults
  cost 2.5 to 5 µs each on this machine (a C loop touching fresh pages), so they, not the instructions,
  made the floor. Now `cagd` is linked statically on x86_64 Linux (`crates/cli/link-static.sh`, set as
  the linker in `.cargo/config.toml`: no dynamic loader, no libc, libm and libgcc_s to map and bind) and
  allocates with mimalloc v2 (v3's start touched 30 more pages): 357,000 instructions and 135 page
  faults; what remains is mimalloc reading its options from the environment (124,000), clap (110,000),
  and the pages of a 12 MB binary and of the allocator's first segment. Alternated with `true`
  (minima): 1.66 ms before, 0.99 ms after, `true` 0.88 ms. Of the 135 page faults, about 45 are mimalloc
  extending the free lists of its first pages (one page per size class at least; `perf record -e
  page-faults`); a batch of 100 small problems adds about 85 more.
- **T6 (2, 2) with 200 points as one process**: the problem itself is cheap (about 0.9 ms in a batch);
  alone, the process also pays the floor and a cold start: the pages of the code it runs and of the
  memory it touches (mimalloc touches about 190 more pages than for the empty batch, glibc's malloc
  about 125). Besides the static link, β of the normal equations is now built from the parameters in
  machine integers (it was built in big integers, then converted back): 9.0 M to 7.6 M instructions for
  the process, 838.6 M to 744.6 M for 100 problems.
- **`--threads`**: two runs ago 2 threads were slower than 1: each chunk of 128 problems started fresh
  threads (with cold allocator caches) and waited for the slowest, glibc's malloc arenas contended when an answer
  made on a solver thread was freed on the main thread, and a T6 problem's multimodular solve started two
  more threads of its own on each solver thread. Now the solver threads live for the whole batch and take the
  next problem as they finish one (64 per thread answered ahead of the output at most, so memory stays flat),
  cagd-linalg's multimodular solve stays on its solver thread inside a batch, and mimalloc's per-thread heaps
  do not contend: on 1,000 x T2 (10, 10) k=5 the CPU time per problem with 2 threads is within 10% of one
  thread's (284 µs and 263 µs in a trial run of this script under a load average of 10; before, 2 threads cost
  0.49 s of CPU time against 0.46 s for one, and took longer in wall time too), and the wall time falls
  as far as the other processes leave the second core free (1.23x in that trial run)."""

# A problem whose solving costs nothing: what a `cagd solve` process costs by itself.
TRIVIAL_PROBLEM = {"op": "circle", "radius": 1, "arcs": 4}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--cagd", help="peers-data's output (not with --from-results)")
    ap.add_argument("--out", required=True)
    ap.add_argument("--cagd-bin", help="the release `cagd` binary: also time `cagd solve` as a whole process")
    ap.add_argument("--problems", help="where to write each task's `cagd solve` problem (with --cagd-bin)")
    ap.add_argument("--load-before")
    ap.add_argument("--ps-before")
    ap.add_argument("--from-results", help="rewrite the report from the results a run saved (no measuring)")
    args = ap.parse_args()
    if args.from_results:
        with open(args.from_results) as f:
            saved = json.load(f)
        # the machine's state before the run, as saved
        for key in ("load_before", "ps_before"):
            path = args.from_results + "." + key
            with open(path, "w") as f:
                f.write(saved.get(key) or "")
            setattr(args, key, path)
        write_report(args, saved["cagd"], saved["rows"], saved["all_identical"], saved["load_after"], saved["process"])
        return
    with open(args.cagd) as f:
        cagd = json.load(f)

    skip_sympy = os.environ.get("PEERS_SKIP_SYMPY") == "1"
    process = None
    if args.cagd_bin:
        problems = args.problems or os.path.join(os.path.dirname(os.path.abspath(args.out)), "problems")
        os.makedirs(problems, exist_ok=True)
        trivial = os.path.join(problems, "trivial.json")
        with open(trivial, "w") as f:
            json.dump(TRIVIAL_PROBLEM, f)
        spawn = timed_process(["true"])
        empty = timed_process(solve_command(args.cagd_bin, trivial))
        nothing = os.path.join(problems, "empty-batch.json")
        with open(nothing, "w") as f:
            f.write("[]")
        floor = timed_process(solve_command(args.cagd_bin, nothing))
        process = {"true": spawn, "trivial": empty, "floor": floor, "problems": problems}
        print(
            f"process: `true` {fmt_time(spawn[0])} (min {fmt_time(spawn[1])}), "
            f"`cagd solve` of a circle {fmt_time(empty[0])} (min {fmt_time(empty[1])})",
            file=sys.stderr,
        )
    rows = []
    all_identical = True
    for task in cagd["tasks"]:
        label = task["label"]
        make = TASKS[label]
        entry = {"task": task, "process": None}
        cmd = None
        if process:
            path = os.path.join(process["problems"], task["name"].replace(" ", "_") + ".json")
            with open(path, "w") as f:
                json.dump(problem_json(task), f)
            cmd = solve_command(args.cagd_bin, path)
            ok = check_process(args.cagd_bin, task, path)
            all_identical &= ok
            entry["process"] = {"identical": ok}
            batch = os.path.join(process["problems"], task["name"].replace(" ", "_") + f"-x{BATCH}.json")
            write_batch(batch, problem_json(task), BATCH)

        def time_batches(flint_call):
            # the batch beside FLINT, then --steps (where a batch of 100 takes seconds: 10 copies, the
            # start-up is then noise)
            entry["batch"] = timed_batch_beside(flint_call, solve_command(args.cagd_bin, batch), BATCH)
            steps_copies = BATCH if entry["batch"]["seconds"] < 1.0 else STEPS_FEW
            steps_batch = batch
            if steps_copies != BATCH:
                steps_batch = os.path.join(process["problems"], task["name"].replace(" ", "_") + f"-x{steps_copies}.json")
                write_batch(steps_batch, problem_json(task), steps_copies)
            entry["batch_steps"] = timed_batch(solve_command(args.cagd_bin, steps_batch) + ["--steps"], steps_copies)
            entry["batch_steps"]["copies"] = steps_copies
            entry["rss"] = peak_rss(cmd)
            print(
                f"{task['name']:<18} batch of {BATCH}: {fmt_time(entry['batch']['per_problem'])} per problem "
                f"(FLINT beside it {fmt_time(entry['batch']['flint'])}), "
                f"--steps {fmt_time(entry['batch_steps']['per_problem'])}; one problem peak RSS {(entry['rss'] or 0) / 2**20:.1f} MiB",
                file=sys.stderr,
            )
        for lib, key in ((FLINT, "flint"), (SYMPY, "sympy")):
            if key == "sympy" and skip_sympy:
                entry[key] = None
                continue
            inp = prepare(lib, task)
            extra = ""
            if key == "flint" and cmd:
                # FLINT and the whole process alternately, so that both see the same load
                r = timed_side_by_side(make(lib, task, inp), cmd)
                seconds, values = r["flint"], r["result"]
                entry["process"].update(seconds=r["process"], min=r["process_min"], flint_min=r["flint_min"], runs=r["runs"])
                extra = f"  process {fmt_time(r['process']):>10} (min {fmt_time(r['process_min'])}, FLINT min {fmt_time(r['flint_min'])}, {r['runs']} runs each)"
                time_batches(make(lib, task, inp))
            else:
                seconds, values = timed(make(lib, task, inp))
            ok = check(values, task["answer"])
            all_identical &= ok
            entry[key] = {"seconds": seconds, "identical": ok}
            print(
                f"{task['name']:<18} {lib.name:<6} {fmt_time(seconds):>10}  "
                f"cagd {fmt_time(task['exact_seconds']):>10}  {'identical' if ok else 'DIFFERENT'}{extra}",
                file=sys.stderr,
            )
        if cagd_exact is not None and os.environ.get("PEERS_PYTHON") != "0":
            r = timed_in_process(make(FLINT, task, prepare(FLINT, task)), problem_json(task))
            ok = check_in_process(task, r.pop("answers"))
            all_identical &= ok
            entry["python"] = dict(r, identical=ok)
            print(
                f"{task['name']:<18} Python {fmt_time(r['dict']):>10} (read once {fmt_time(r['read'])}), "
                f"FLINT {fmt_time(r['flint'])}: {r['dict'] / r['flint']:.2f}x, {r['read'] / r['flint']:.2f}x, "
                f"{r['runs']} runs  {'identical' if ok else 'DIFFERENT'}",
                file=sys.stderr,
            )
        if entry["process"] and not entry["process"]["identical"]:
            print(f"{task['name']:<18} cagd solve: the answer DIFFERS from the library's", file=sys.stderr)
        rows.append(entry)
    if process:
        # memory against the size of the batch: copies of one small problem
        small = next((e["task"] for e in rows if e["task"]["name"] == MEMORY_TASK), None)
        if small:
            process["memory"] = []
            for copies in MEMORY_BATCHES:
                path = os.path.join(process["problems"], f"memory-x{copies}.json")
                write_batch(path, problem_json(small), copies)
                seconds, rss = run_process_rss(solve_command(args.cagd_bin, path))
                process["memory"].append((copies, seconds, rss, os.path.getsize(path)))
                print(f"{MEMORY_TASK} x{copies}: {fmt_time(seconds)}, peak RSS {(rss or 0) / 2**20:.1f} MiB", file=sys.stderr)
        # scaling with --threads: the same batch on 1, 2, ... up to the cores, wall and CPU time
        task = next((e["task"] for e in rows if e["task"]["name"] == THREADS_TASK), None)
        if task:
            path = os.path.join(process["problems"], f"threads-x{THREADS_COPIES}.json")
            write_batch(path, problem_json(task), THREADS_COPIES)
            process["threads"] = []
            counts = sorted({1, 2, os.cpu_count() or 1})
            outputs = {subprocess.run(solve_command(args.cagd_bin, path) + ["--threads", str(n)], capture_output=True).stdout for n in counts}
            process["threads_identical"] = len(outputs) == 1
            for threads in counts:
                t = timed_batch(solve_command(args.cagd_bin, path) + ["--threads", str(threads)], THREADS_COPIES)
                process["threads"].append((threads, t["per_problem"], t["cpu_per_problem"], t["runs"]))
                print(f"{THREADS_TASK} x{THREADS_COPIES} --threads {threads}: {fmt_time(t['per_problem'])} per problem, CPU {fmt_time(t['cpu_per_problem'])}", file=sys.stderr)
    load_after = open("/proc/loadavg").read().split()[:3] if os.path.exists("/proc/loadavg") else []
    if process:
        # the measurements, to rewrite the report without measuring again (--from-results)
        with open(os.path.join(process["problems"], "results.json"), "w") as f:
            read = lambda path: open(path).read() if path else ""
            json.dump({"load_before": read(args.load_before), "ps_before": read(args.ps_before), "cagd": cagd, "rows": rows, "all_identical": all_identical, "load_after": load_after, "process": process}, f)
    write_report(args, cagd, rows, all_identical, load_after, process)
    if not all_identical:
        print("some answers differ from cagd-exact's: see the report", file=sys.stderr)
        sys.exit(1)


def write_report(args, cagd, rows, all_identical, load_after, process=None):
    load_before = open(args.load_before).read().split()[:3] if args.load_before else []
    ps_before = open(args.ps_before).read().strip() if args.ps_before else ""
    out = []
    w = out.append
    w("# Performance")
    w("")
    w("Written by `just bench-peers` (`crates/bench/peers/run.sh`) from one run on this machine; do not edit by hand.")
    w("cagd-exact runs each task through its public API (`BezierSurface::eval`, `elevate`, `restrict`, `closed_form`,")
    w("`cagd_fit::interpolate_bezier_surface`, `approximate_bezier_surface`) over `BigRational`; the same code over `f64`")
    w("gives the last column. SymPy runs `sympy.Matrix` of `Rational` (the API a teacher uses); FLINT runs python-flint's")
    w("best formulation found (`fmpq_mat` products for T1, T2, T3, T5, `fmpq_mat.solve` for T4, T6). Inputs: fixed-seed")
    w("small rationals (coordinates p/q, p in [-9, 9], q in 1..9; parameters the 29 values p/q in [0, 1], q ≤ 9).")
    w("Times are medians of repeated runs (one run for a peer slower than 2 s), including the setup of each task's")
    w("matrices but not the parsing of the input. The exact/f64 column compares the same public functions over")
    w("`f64`, which take the generic step-by-step algorithms (De Casteljau, curve elevation and restriction, Gaussian")
    w("elimination): where it is below 1x the exact integer formulation beats the generic floating-point one.")
    if process:
        w("The column `cagd solve` is the whole process on the same input written as a problem file (docs/format.md):")
        w("`cagd solve FILE --format json` of the release binary, from fork and exec to exit, reading the JSON (every")
        w("number read exactly: `±p` and `±p/q` in one pass, the rest through the grammar), solving without `--steps`,")
        w("and printing the answer (to /dev/null); it runs")
        w("alternately with FLINT's run of the same task, so that both see the same load (see the section below).")
    if any(e.get("python") for e in rows):
        w("The column `cagd_exact` (Python) is the Python module (crates/python) called in the same interpreter as")
        w("FLINT, `cagd_exact.solve(problem)` on the problem as a dict, alternately with FLINT (see the section below).")
    w("")
    verdict = "identical" if all_identical else "NOT identical (see the ✗ marks)"
    who = "SymPy, FLINT and the `cagd solve` process" if process else "SymPy and FLINT"
    if any(e.get("python") for e in rows):
        who += " and of `cagd_exact` from Python"
    w(f"**Every exact answer of {who} was compared with cagd-exact's, as exact rationals: {verdict}.**")
    w("")
    w("Targets: at least 100x faster than SymPy; at most 2x slower than FLINT (cagd/FLINT ≤ 2); as a whole process,")
    w(f"at most 2x slower than FLINT for {' and '.join(PROCESS_TARGETS)} (process/FLINT ≤ 2).")
    w("")
    w("| task | size | cagd-exact (library call) | `cagd solve` (process) | `cagd_exact` (Python) | SymPy | FLINT | SymPy/cagd | cagd/FLINT | process/FLINT | Python/FLINT | exact/f64 | targets |")
    w("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    sympy_misses, flint_misses, process_rows = {}, {}, []
    for e in rows:
        t = e["task"]
        c = t["exact_seconds"]
        s = e["sympy"]["seconds"] if e["sympy"] else None
        fl = e["flint"]["seconds"] if e["flint"] else None
        pr = e["process"].get("seconds") if e.get("process") else None
        vs_sympy = s / c if s else None
        vs_flint = c / fl if fl else None
        pr_flint = pr / fl if pr and fl else None
        f64 = c / t["f64_seconds"] if t["f64_seconds"] else None
        marks = []
        if vs_sympy is not None:
            marks.append("SymPy ✓" if vs_sympy >= 100 else "SymPy ✗")
        if vs_flint is not None:
            marks.append("FLINT ✓" if vs_flint <= 2 else "FLINT ✗")
        if pr_flint is not None and t["name"] in PROCESS_TARGETS:
            marks.append("process ✓" if pr_flint <= 2 else "process ✗")
            process_rows.append((t, e, pr_flint))
        if vs_sympy is not None and vs_sympy < 100:
            sympy_misses.setdefault(t["label"], []).append(t["name"])
        if vs_flint is not None and vs_flint > 2:
            flint_misses.setdefault(t["label"], []).append(t["name"])
        for key in ("sympy", "flint", "process"):
            if e.get(key) and not e[key]["identical"]:
                marks.append(f"{key} answer ✗")
        size = t["name"].split(" ", 1)[1]
        f64_note = "" if t.get("f64_error") is None else " (f64 failed)"
        py = e.get("python")
        if py:
            marks.append("Python ✓" if py["dict"] <= py["flint"] else "Python ✗")
            if not py["identical"]:
                marks.append("python answer ✗")
        w(
            f"| {t['label']} {t['describe']} | {size} | {fmt_time(c)} | {fmt_time(pr)} | {fmt_time(py and py['dict'])} | {fmt_time(s)} | {fmt_time(fl)} | "
            f"{fmt_ratio(vs_sympy)} | {fmt_ratio(vs_flint)} | {fmt_ratio(pr_flint)} | {fmt_ratio(py and py['dict'] / py['flint'])} | {fmt_ratio(f64)}{f64_note} | {', '.join(marks)} |"
        )
    w("")
    if process:
        write_process_section(w, process, process_rows)
        write_batch_section(w, process, rows)
    if any(e.get("python") for e in rows):
        write_python_section(w, rows)
    w("## Growth")
    w("")
    w("Measured exponent e of time ≈ c · n^e (least-squares fit of log time against log n over the sizes above).")
    w("")
    w("At small n fixed costs weigh (allocating the (n+1)^2 points of the answer, per-call setup), so the fitted exponent")
    w("is below the asymptotic one; the column 'last step' fits only the two largest sizes.")
    w("")
    w("| task | series | cagd-exact | cagd-exact, last step | SymPy | FLINT | expected (cagd-exact's algorithm) |")
    w("| --- | --- | --- | --- | --- | --- | --- |")
    series = {}
    for e in rows:
        t = e["task"]
        key = (t["label"], t["extra"])
        series.setdefault(key, []).append(e)
    for (label, extra), es in series.items():
        ns = [x["task"]["n"] for x in es]
        if len(set(ns)) < 2:
            continue
        name = {"T2": f"k = {extra}", "T6": f"M = {extra}"}.get(label, "")
        name = f"n = {', '.join(map(str, ns))}" + (f"; {name}" if name else "")

        def fit(key):
            pts = [(x["task"]["n"], x[key]["seconds"]) for x in es if x.get(key)]
            v = exponent(pts)
            return "—" if v is None else f"{v:.1f}"

        mine = exponent([(x["task"]["n"], x["task"]["exact_seconds"]) for x in es])
        last = exponent([(x["task"]["n"], x["task"]["exact_seconds"]) for x in es[-2:]])
        w(
            f"| {label} | {name} | {'—' if mine is None else f'{mine:.1f}'} | {'—' if last is None else f'{last:.1f}'} | {fit('sympy')} | {fit('flint')} | "
            f"{EXPECTED[label][0]}: {EXPECTED[label][1]} |"
        )
    w("")
    w("## Whole runs")
    w("")
    ex = cagd.get("examples")
    pr = cagd.get("problems")
    if ex:
        w(f"- `cagd examples` (`check` over the {ex['count']} fixtures of `fixtures/`): {fmt_time(ex['seconds'])}, {ex['passed']}/{ex['count']} pass.")
    if pr:
        w(f"- `cagd solve` on {pr['count']} generated problems (`cagd-exercises`, every topic, seed 2026): {fmt_time(pr['seconds'])}, {pr['solved']}/{pr['count']} solved.")
    w("")
    w("## Targets missed, and why")
    w("")
    if not sympy_misses and not flint_misses:
        w("None: every task and size meets both targets.")
    sizes = lambda names: ", ".join(n.split(" ", 1)[1] for n in names)
    for label, names in flint_misses.items():
        w(f"- **{label}, more than 2x FLINT** ({sizes(names)}): {WHY_FLINT[label]}")
    for label, names in sympy_misses.items():
        w(f"- **{label}, less than 100x SymPy** ({sizes(names)}): {WHY_SYMPY[label]}")
    if sympy_misses:
        w(f"- **SymPy in general**: {SYMPY_NOTE}")
    w("")
    w("## Against the issue's reference measurements")
    w("")
    w("The issue measured SymPy and FLINT on this kind of machine for one size of each task; the same sizes here:")
    w("")
    w("| task | issue: SymPy | issue: FLINT (best) | cagd-exact now | vs issue's SymPy | vs issue's FLINT |")
    w("| --- | --- | --- | --- | --- | --- |")
    by_name = {e["task"]["name"]: e["task"] for e in rows}
    for name, sym, fl in REFERENCE:
        t = by_name.get(name)
        if not t:
            continue
        c = t["exact_seconds"]
        w(f"| {name} | {fmt_time(sym)} | {fmt_time(fl)} | {fmt_time(c)} | {fmt_ratio(sym / c)} faster | {fmt_ratio(c / fl)} |")
    w("")
    w("## The machine and the run")
    w("")
    w(f"- Python {platform.python_version()}, SymPy {sympy.__version__} (ground types: {sympy.external.gmpy.GROUND_TYPES}), python-flint {flint.__version__}.")
    w(f"- {platform.machine()}, {os_cpus()} cores; load average before the run {' '.join(load_before) or '?'}, after {' '.join(load_after) or '?'}.")
    w("- cagd-exact is single-threaded except the multimodular solver of T6, which spreads its primes over the cores;")
    w("  another process holding a core (below) slows that one down most.")
    if ps_before:
        w("- What else was running when it started (top processes by CPU):")
        w("")
        w("```")
        for line in ps_before.splitlines():
            w(line)
        w("```")
    w("")
    # the hand-written sections from `cargo bench --bench class` on (checking a class; a class
    # on the page, `cagd serve` under load) are kept
    kept = ""
    if os.path.exists(args.out):
        with open(args.out) as f:
            old = f.read()
        at = old.find("\n## Checking a class")
        if at >= 0:
            kept = old[at + 1:]
    with open(args.out, "w") as f:
        f.write("\n".join(out))
        if kept:
            f.write("\n" + kept)


def write_process_section(w, process, process_rows):
    spawn, trivial = process["true"], process["trivial"]
    w("## The whole `cagd solve` process")
    w("")
    w("Each task's input is written as a `cagd solve` problem (T1 `evaluate`, T2 `elevate`, T3 `restrict`, T4")
    w("`interpolate` with `basis` `bezier` on the grid u = v = i/n, T5 `closed_form`, T6 `approximate` with `params` and")
    w("`degree`), and the answer the process prints is compared exactly with the library call's. Python times each")
    w("run with `subprocess.run` (output to /dev/null) and `time.perf_counter`, alternately with one run of FLINT's")
    w("formulation of the task in this interpreter (FLINT's figure stays the in-interpreter time, as in the issue).")
    w("")
    w(f"- Spawning a process that does nothing (`true`) the same way: {fmt_time(spawn[0])} (median of {spawn[2]}; minimum {fmt_time(spawn[1])}).")
    w(f"- `cagd solve` of a problem that costs nothing to solve (a circle of 4 arcs): {fmt_time(trivial[0])} (median of {trivial[2]}; minimum {fmt_time(trivial[1])}).")
    w("  Below a few milliseconds the process column is mostly this fixed cost, where FLINT's figure has none; the")
    w("  process/FLINT ratio of the small rows compares a process with a call inside an interpreter.")
    for t, e, ratio in process_rows:
        p = e["process"]
        fl = e["flint"]["seconds"]
        verdict = "within 2x ✓" if ratio <= 2 else "more than 2x ✗"
        w(
            f"- **{t['name']}** ({t['describe']}): `cagd solve` {fmt_time(p['seconds'])}, FLINT {fmt_time(fl)}: "
            f"{fmt_ratio(ratio)}, {verdict} (medians of {p['runs']} alternating runs; minima {fmt_time(p['min'])} and "
            f"{fmt_time(p['flint_min'])}: {fmt_ratio(p['min'] / p['flint_min'])}); the library call alone {fmt_time(t['exact_seconds'])}."
        )
    w("")
    w(PROCESS_NOTE)
    w("")


def write_batch_section(w, process, rows):
    w(f"## Batches, `--steps` and memory")
    w("")
    w(f"The same problem {BATCH} times in one batch file, `cagd solve BATCH --format json` (one thread), whole process")
    w(f"time divided by {BATCH}: the cost of a problem once the process is started (median of at least 5 runs, one when a")
    w("run takes over 2 s, each followed by FLINT's call repeated for about as long: the batch and FLINT are compared in")
    w("the same moments, as the processes are, since this machine's speed moves by up to 1.5x for tens of seconds at a time),")
    w("and the CPU time of that process (user + system, its own rusage) divided the same way,")
    w(f"which the other processes of a shared machine do not inflate; the same with `--steps` ({STEPS_FEW} copies, not {BATCH}, where the batch")
    w("of 100 takes over a second without steps: the start-up is then noise). Peak memory is the resident set (GNU time's %M) of the")
    w("single-problem process, for the largest size of each task. Targets (issue 14): per problem in a batch, at least as")
    w("fast as FLINT on T1-T5 and within 2x on T6; a single process within 2x of FLINT where FLINT takes over 2 ms;")
    w("`--steps` at most 3x the run without.")
    w("")
    w("| task | size | `cagd solve` (process) | per problem, batch of 100 | (its CPU time) | with `--steps` | steps/no steps | FLINT beside the batch | batch/FLINT | FLINT beside the process | process/FLINT | peak RSS | targets |")
    w("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    largest = {}
    for e in rows:
        largest[e["task"]["label"]] = e["task"]["name"]
    misses = []
    for e in rows:
        t = e["task"]
        if "batch" not in e:
            continue
        fl = e["flint"]["seconds"] if e["flint"] else None
        pr = e["process"].get("seconds")
        b, bs = e["batch"]["per_problem"], e["batch_steps"]["per_problem"]
        fb = e["batch"].get("flint")
        steps_ratio = bs / b
        batch_ratio = b / fb if fb else None
        pr_ratio = pr / fl if fl and pr else None
        marks = []
        if batch_ratio is not None:
            limit = 2.0 if t["label"] == "T6" else 1.0
            ok = batch_ratio <= limit
            marks.append("batch ✓" if ok else "batch ✗")
            if not ok:
                misses.append(f"{t['name']}: batch {fmt_ratio(batch_ratio)} of FLINT (target {limit:g}x)")
        if pr_ratio is not None and fl > 0.002:
            ok = pr_ratio <= 2
            marks.append("process ✓" if ok else "process ✗")
            if not ok:
                misses.append(f"{t['name']}: process {fmt_ratio(pr_ratio)} of FLINT (FLINT {fmt_time(fl)})")
        ok = steps_ratio <= 3
        marks.append("steps ✓" if ok else "steps ✗")
        if not ok:
            misses.append(f"{t['name']}: --steps {fmt_ratio(steps_ratio)} of the run without")
        rss = f"{e['rss'] / 2**20:.1f} MiB" if e.get("rss") and largest.get(t["label"]) == t["name"] else ""
        size = t["name"].split(" ", 1)[1]
        w(
            f"| {t['label']} {t['describe']} | {size} | {fmt_time(pr)} | {fmt_time(b)} | {fmt_time(e['batch'].get('cpu_per_problem'))} | {fmt_time(bs)} | {fmt_ratio(steps_ratio)} | "
            f"{fmt_time(fb)} | {fmt_ratio(batch_ratio)} | {fmt_time(fl)} | {fmt_ratio(pr_ratio)} | {rss} | {', '.join(marks)} |"
        )
    w("")
    floor, spawn = process["floor"], process["true"]
    w(f"- The floor: `cagd solve` of an empty batch (`[]`) {fmt_time(floor[0])} (median of {floor[2]}; minimum {fmt_time(floor[1])}), next to")
    w(f"  spawning `true` {fmt_time(spawn[0])} (minimum {fmt_time(spawn[1])}).")
    mem = process.get("memory")
    if mem:
        w(f"- Memory against the size of the batch ({MEMORY_TASK}, copies of one problem, one thread): "
          + "; ".join(f"{c:,} problems ({size / 2**20:.1f} MiB of JSON) {fmt_time(sec)}, peak RSS {rss / 2**20:.1f} MiB" for c, sec, rss, size in mem)
          + ". The batch is streamed: its top-level array is read one problem at a time (a problem that is not JSON")
        w("  is that problem's error), each read, solved and written in order, at most 64 problems per thread ahead of the output, so memory does not grow with the batch.")
    scaling = process.get("threads")
    if scaling:
        one = scaling[0][1]
        same = "output identical" if process.get("threads_identical") else "output DIFFERENT"
        w(f"- `--threads` ({THREADS_TASK}, {THREADS_COPIES:,} copies, {os.cpu_count()} cores, {same}): "
          + "; ".join(f"{n} thread{'s' if n > 1 else ''} {fmt_time(wall)} per problem (CPU {fmt_time(cpu)}, {one / wall:.2f}x one thread's speed; median of {runs})" for n, wall, cpu, runs in scaling)
          + ". Wall time scales only as far as the other processes of the machine leave its cores free; the CPU time per problem should not grow with the threads.")
    w("")
    if misses:
        w("Missed here (the reasons follow):")
        w("")
        for m in misses:
            w(f"- {m}")
    else:
        w("Every row meets the targets of this table.")
    w("")
    if BATCH_NOTE:
        w(BATCH_NOTE)
        w("")


def write_python_section(w, rows):
    w("## From Python, in the same interpreter")
    w("")
    w("The Python module (`pip install ./crates/python`, a release build) called in the interpreter that runs FLINT,")
    w("on the task's input written as the problem of the `cagd solve` column. Each round times, one after the other,")
    w("FLINT's formulation (its input matrices already built, as in the FLINT column), `cagd_exact.solve(problem)`")
    w("from the dict (converting the dict, reading every number exactly, solving without steps, and")
    w("wrapping the answer), and `Problem.solve()` of the problem read once by `cagd_exact.read` (solving and")
    w("wrapping only). The answer object keeps the engine's exact answer and converts it only when read, so neither")
    w("cagd_exact time includes printing numbers; after the timing, both answers' `to_json()` were compared exactly")
    w("with the library's. Medians (and minima) of the alternating rounds; the target is Python/FLINT ≤ 1. The last")
    w("column is what reading the whole answer out afterwards costs: `answer.to_json()` (every number printed to a")
    w("Python string), median of 5 calls; FLINT's figure has no such step (its answer stays `fmpq_mat`s).")
    w("")
    w("| task | size | FLINT | `solve(dict)` | `Problem.solve()` (read once) | dict/FLINT | read once/FLINT | rounds | minima: dict/FLINT | target | then `to_json()` |")
    w("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    misses = []
    for e in rows:
        py = e.get("python")
        if not py:
            continue
        t = e["task"]
        size = t["name"].split(" ", 1)[1]
        ok = py["dict"] <= py["flint"]
        if not ok:
            misses.append((t, py))
        w(
            f"| {t['label']} {t['describe']} | {size} | {fmt_time(py['flint'])} | {fmt_time(py['dict'])} | {fmt_time(py['read'])} | "
            f"{fmt_ratio(py['dict'] / py['flint'])} | {fmt_ratio(py['read'] / py['flint'])} | {py['runs']} | "
            f"{fmt_ratio(py['dict_min'] / py['flint_min'])} | {'✓' if ok else '✗'}{'' if py['identical'] else ', answer ✗'} | {fmt_time(py.get('to_json'))} |"
        )
    w("")
    if misses:
        w("Rows where `solve(dict)` is slower than FLINT, with its time split into reading the problem (the dict's")
        w("time less the read-once time) and solving it (the read-once time):")
        w("")
        for t, py in misses:
            reading = max(py["dict"] - py["read"], 0)
            w(
                f"- **{t['name']}**: {fmt_time(py['dict'])} = reading {fmt_time(reading)} + solving {fmt_time(py['read'])}, "
                f"FLINT {fmt_time(py['flint'])}: {fmt_ratio(py['dict'] / py['flint'])}; read once, "
                f"{fmt_ratio(py['read'] / py['flint'])}{' ✓' if py['read'] <= py['flint'] else ' ✗'}. {PYTHON_WHY.get(t['label'], '')}"
            )
        w("")
    else:
        w("On every row `cagd_exact.solve(dict)` is at least as fast as FLINT.")
        w("")


READING = (
    "FLINT's time excludes making its input (its `fmpq_mat`s are built before the timing, as in the FLINT column); "
    "from the dict, cagd_exact reads every number: the dict is written as JSON text in Rust and read straight into "
    "the typed problem (`Problem::read_text`), each number into the problem's field (`±p` and `±p/q` in one pass, "
    "the rest through the grammar)."
)

PYTHON_WHY = {
    "T2": READING,
    "T4": READING + " From n ≈ 20, `interpolate` is slower than FLINT's solve itself: it also answers with the closed form, which FLINT's formulation does not compute, and its entries outgrow machine integers (num-bigint against GMP).",
    "T5": READING + " Read once, the solve is below FLINT's time: what the dict adds is the reading of its 3(n+1)^2 numbers.",
    "T6": "`approximate` also answers with the closed form; the normal equations and the solve are big-integer work where GMP (FLINT) beats num-bigint (see the FLINT column); T6 uses both cores, so the load of the machine weighs on it most.",
}


def os_cpus():
    return os.cpu_count()


if __name__ == "__main__":
    main()
