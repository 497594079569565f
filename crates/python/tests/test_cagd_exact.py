"""Tests of the Python module: exactness, errors, and agreement with `cagd solve`.

The comparisons with the command line run the `cagd` binary named by $CAGD_BIN (the CI sets
it, to the release build of .ci/main-job); without it they are skipped.
"""

import json
import os
import re
import subprocess
from fractions import Fraction
from pathlib import Path

import pytest

import cagd_exact as cagd

ROOT = Path(__file__).resolve().parents[3]

COONS = {
    "op": "coons",
    "c1": {"bezier": [[0, 0, 0], ["1/2", 0, 2], [1, 0, 3], [2, 0, 0]]},
    "c2": {"bezier": [[0, 3, 0], ["1/2", 3, 3], [1, 3, 1], [2, 4, 0]]},
    "d1": {"bezier": [[0, 0, 0], [0, 1, 3], [0, 3, 0]]},
    "d2": {"bezier": [[2, 0, 0], [2, 1, 2], [2, 4, 0]]},
}

OCTANT = {
    "op": "revolution",
    "curve": {"bezier": [[1, 0, 0], [1, 0, 1], [0, 0, 1]], "weights": [1, "sqrt2/2", 1]},
    "arcs": 1,
}


def cagd_bin():
    path = os.environ.get("CAGD_BIN")
    if not path:
        pytest.skip("CAGD_BIN is not set: no `cagd` binary to compare with")
    assert Path(path).is_file(), f"CAGD_BIN={path} does not exist"
    return path


def cli_solve(problems, *flags):
    """`cagd solve - --format json` of a problem or a batch: the parsed answers."""
    done = subprocess.run(
        [cagd_bin(), "solve", "-", "--format", "json", *flags],
        input=json.dumps(problems),
        capture_output=True,
        text=True,
    )
    assert done.returncode in (0, 1), done.stderr
    return json.loads(done.stdout)


def format_examples():
    """Every ```json problem block of docs/format.md."""
    text = (ROOT / "docs" / "format.md").read_text()
    blocks = re.findall(r"```json problem\n(.*?)```", text, re.S)
    assert len(blocks) >= 20, "docs/format.md lost its examples"
    return [json.loads(b) for b in blocks]


# ---------------------------------------------------------------- exact answers


def test_coons_mesh_is_exact():
    answer = cagd.solve(COONS)
    mesh = answer["surface"]["bezier"]
    assert mesh[1][1] == ["1/2", "5/6", "31/6"]
    assert answer.fractions()["surface"]["bezier"][1][1] == [Fraction(1, 2), Fraction(5, 6), Fraction(31, 6)]
    assert answer.op == "coons" and answer.field == "Q"
    assert len(mesh) == 4 and all(len(row) == 3 for row in mesh)


def test_numbers_in_every_exact_form_give_the_same_answer():
    sympy = pytest.importorskip("sympy")
    forms = [
        lambda p, q: f"{p}/{q}",
        lambda p, q: Fraction(p, q),
        lambda p, q: sympy.Rational(p, q),
    ]
    answers = []
    for form in forms:
        problem = json.loads(json.dumps(COONS))
        problem["c1"]["bezier"][1][0] = form(1, 2)
        problem["c2"]["bezier"][1][0] = form(1, 2)
        answers.append(cagd.solve(problem).to_json())
    assert answers[0] == answers[1] == answers[2]


def test_decimals_are_exact():
    from decimal import Decimal

    answer = cagd.solve({"op": "elevate", "curve": {"bezier": [[0, 0], [Decimal("0.125"), 2], [3, 3]]}, "by": 1})
    assert answer.fractions()["curve"]["bezier"][1][0] == Fraction(1, 12)


def test_big_integers_stay_exact():
    big = 2**70 + 1
    answer = cagd.solve({"op": "elevate", "curve": {"bezier": [[0, 0], [big, 2], [3, 3]]}, "by": 1})
    points = answer.fractions()["curve"]["bezier"]
    assert points[1][0] == Fraction(2 * big, 3)


def test_square_roots_come_out_as_sympy_numbers():
    sympy = pytest.importorskip("sympy")
    answer = cagd.solve(OCTANT)
    assert answer.field == "Q(√2)"
    weights = answer.sympy()["surface"]["weights"]
    assert weights[0][1] == sympy.sqrt(2) / 2
    assert weights[1][1] == sympy.Rational(1, 2)
    with pytest.raises(cagd.CagdError) as e:
        answer.fractions()
    assert e.value.field == "surface.weights[0][1]"
    assert "not rational" in str(e.value)


def test_sympy_numbers_go_in():
    sympy = pytest.importorskip("sympy")
    problem = json.loads(json.dumps(OCTANT))
    problem["curve"]["weights"] = [1, sympy.sqrt(2) / 2, sympy.Integer(1)]
    assert cagd.solve(problem).to_json() == cagd.solve(OCTANT).to_json()


def test_closed_form_as_sympy_expression():
    sympy = pytest.importorskip("sympy")
    answer = cagd.solve({"op": "closed_form", "surface": {"expr": "(u, v, u*v + 1/2)"}})
    u, v = sympy.symbols("u v")
    form = answer.sympy()["closed_form"]
    assert tuple(form) == (u, v, u * v + sympy.Rational(1, 2))


def test_read_once_solves_the_same():
    problem = cagd.read(COONS)
    assert problem.op == "coons"
    assert problem.solve().to_json() == cagd.solve(COONS).to_json()
    assert problem.solve(steps=True).steps.keys() >= {"c_c", "c_d", "c_cd"}
    assert cagd.solve(problem).to_json() == cagd.solve(COONS).to_json()


def test_json_string_and_list_inputs():
    text = json.dumps(COONS)
    assert cagd.solve(text).to_json() == cagd.solve(COONS).to_json()
    answers = cagd.solve_batch(json.dumps([COONS, OCTANT]))
    assert [a.op for a in answers] == ["coons", "revolution"]
    assert [a.op for a in cagd.solve([COONS, OCTANT])] == ["coons", "revolution"]


def test_every_example_of_the_notes_checks():
    examples = cagd.examples()
    assert len(examples) >= 20
    for example in examples:
        answer = cagd.solve(example)
        assert answer.checked and answer.passed, (example["name"], answer.mismatches)
    assert [e["name"] for e in cagd.examples("ch6-coons")] == [
        e["name"] for e in examples if e["name"].startswith("ch6-coons")
    ]


def test_check_finds_a_wrong_expected_answer():
    problem = dict(COONS, expected={"surface": {"bezier": [[[0, 0, 0]]]}})
    answer = cagd.check(problem)
    assert not answer.passed and answer.mismatches
    assert not cagd.check(COONS).passed  # nothing to check


def coons_with_cd_added():
    """COONS answered as a student who added c_cd: c_c + c_d + c_cd, mesh point by point."""
    listed = cagd.solve(COONS, steps=True).to_json()["result"]["steps"]
    steps = {s["name"]: s["value"]["bezier"] for s in listed}
    cc, cd, ccd = steps["c_c"], steps["c_d"], steps["c_cd"]
    mesh = [
        [
            [str(Fraction(a) + Fraction(b) + Fraction(c)) for a, b, c in zip(p, q, r)]
            for p, q, r in zip(*rows)
        ]
        for rows in zip(cc, cd, ccd)
    ]
    return dict(COONS, expected={"surface": {"bezier": mesh}})


def test_check_diagnoses_a_student_answer():
    answer = cagd.check(coons_with_cd_added())
    assert not answer.passed
    result = answer.assessment["results"][0]
    assert result["diagnoses"][0]["id"] == "coons.cd_added"
    assert result["diagnoses"][0]["whole"]
    assert answer.to_json()["assessment"] == answer.assessment
    right = cagd.check(dict(COONS, expected=cagd.solve(COONS).to_json()["result"]))
    assert right.passed and right.assessment["correct"] and right.assessment["score"] == "1"


def test_check_gives_the_json_of_the_command_line(tmp_path):
    problem = coons_with_cd_added()
    path = tmp_path / "ana.json"
    path.write_text(json.dumps(problem))
    out = subprocess.run(
        [cagd_bin(), "check", str(path), "--format", "json"], capture_output=True, text=True
    )
    assert out.returncode == 1
    [line] = json.loads(out.stdout)
    assert (line.pop("student"), line.pop("file"), line.pop("problem")) == ("ana", str(path), 1)
    assert line == cagd.check(problem).to_json()


def test_expand():
    e = cagd.expand("(1 - v)*(u, 0, u^3) + v*(u, 1, u^2)")
    assert str(e) == "(u, v, -u^3 v + u^3 + u^2 v)"
    assert e.json() == "(u, v, -u^3*v + u^3 + u^2*v)"
    assert e._repr_latex_().startswith("$\\left(")


def test_generate_is_deterministic_and_solvable():
    first = cagd.generate("coons", 3, seed=7)
    assert first == cagd.generate("coons", 3, seed=7)
    assert len(first) == 3
    assert all(a.passed for a in cagd.solve_batch(first))
    assert "coons" in cagd.topics()


# ---------------------------------------------------------------- errors


def test_errors_name_the_field():
    bad = json.loads(json.dumps(COONS))
    bad["c1"]["bezier"][1] = ["1/2", 0]
    with pytest.raises(cagd.CagdError) as e:
        cagd.solve(bad)
    assert e.value.field.startswith("c1")
    assert str(e.value).startswith("field `c1")
    assert isinstance(e.value, ValueError)


def test_a_float_is_refused_with_its_path():
    bad = json.loads(json.dumps(COONS))
    bad["d2"]["bezier"][1][2] = 0.5
    with pytest.raises(cagd.CagdError) as e:
        cagd.solve(bad)
    assert e.value.field == "d2.bezier[1][2]"


def test_a_sympy_float_is_refused():
    sympy = pytest.importorskip("sympy")
    bad = json.loads(json.dumps(COONS))
    bad["d2"]["bezier"][1][2] = sympy.Float(0.5)
    with pytest.raises(cagd.CagdError) as e:
        cagd.solve(bad)
    assert e.value.field == "d2.bezier[1][2]" and "Float" in str(e.value)


def test_an_unreadable_object_is_refused():
    with pytest.raises(cagd.CagdError) as e:
        cagd.solve({"op": "circle", "radius": object(), "arcs": 4})
    assert e.value.field == "radius"


def test_limits_are_keywords():
    problem = {"op": "elevate", "curve": {"bezier": [[0, 0], [1, 2], [3, 3]]}, "by": 60}
    with pytest.raises(cagd.CagdError) as e:
        cagd.solve(problem)
    assert e.value.limit == "max_degree" and "max_degree=N" in str(e.value)
    assert len(cagd.solve(problem, max_degree=64)["curve"]["bezier"]) == 63
    with pytest.raises(TypeError):
        cagd.solve(problem, max_degre=64)


def test_the_deadline_is_a_keyword_and_named_when_reached():
    slow = {"op": "elevate", "by": 3000,
            "curve": {"bezier": [[0, "1/3"], ["7/11", 2], ["5/13", "2/17"], [1, 1]]}}
    with pytest.raises(cagd.CagdError) as e:
        cagd.solve(slow, max_degree=3100, max_points=3100, max_seconds=0.5)
    assert e.value.limit == "max_seconds" and "max_seconds=N" in str(e.value)
    assert cagd.solve(COONS, max_seconds=0)  # 0: no deadline
    with pytest.raises(ValueError):
        cagd.solve(COONS, max_seconds=-1)


def test_a_batch_answers_the_others():
    bad = {"op": "coons", "c1": {"bezier": [[0, 0, 0]]}}
    answers = cagd.solve_batch([COONS, bad, OCTANT], errors="return")
    assert isinstance(answers[1], cagd.CagdError)
    assert answers[1].index == 1 and str(answers[1]).startswith("problem 2: ")
    assert answers[0].op == "coons" and answers[2].op == "revolution"
    with pytest.raises(cagd.CagdError):
        cagd.solve_batch([COONS, bad])
    threaded = cagd.solve_batch([COONS, OCTANT] * 4, threads=2)
    assert [a.to_json() for a in threaded] == [a.to_json() for a in cagd.solve_batch([COONS, OCTANT] * 4)]


# ---------------------------------------------------------------- display


def test_answer_keys_in_both_languages():
    answer = cagd.solve(COONS, steps=True)
    md = answer._repr_markdown_()
    assert "c_{cd}" in md or "c_cd" in md
    assert "\\frac{5}{6}" in md
    es = answer.show(lang="es")._repr_markdown_()
    assert es != md and ("resultado" in es.lower() or "pasos" in es.lower())
    assert answer._repr_latex_().startswith("$$\\begin{aligned}")
    assert "c_c" not in answer.show(steps=False).steps
    assert "5/6" in answer.text()


def test_figures():
    answer = cagd.solve(COONS)
    fig = answer.figure()
    svg = fig._repr_svg_()
    assert svg.lstrip().startswith("<svg") or svg.lstrip().startswith("<?xml")
    page = fig.interactive()
    assert page._repr_html_().startswith("<iframe srcdoc=")
    assert "<html" in page.html.lower()
    assert cagd.figure(COONS)._repr_svg_() == svg
    assert cagd.figure({"bezier": [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]]})._repr_svg_()


def test_figure_saves(tmp_path):
    fig = cagd.solve(OCTANT).figure()
    fig.save(str(tmp_path / "octant.svg"))
    fig.save(str(tmp_path / "octant.html"))
    assert (tmp_path / "octant.svg").read_text().count("<path") > 0
    assert (tmp_path / "octant.html").stat().st_size > 1000
    with pytest.raises(cagd.CagdError):
        fig.save(str(tmp_path / "octant.png"))


# ---------------------------------------------------------------- the same as `cagd solve`


@pytest.mark.parametrize("steps", [False, True])
def test_every_format_example_answers_as_the_command_line(steps):
    problems = format_examples()
    cli = cli_solve(problems, *(["--steps"] if steps else []))
    mine = [cagd.solve(p, steps=steps).to_json() for p in problems]
    assert len(cli) == len(mine)
    for problem, theirs, ours in zip(problems, cli, mine):
        assert ours == theirs, problem["op"]


def test_errors_are_the_command_lines():
    bad = json.loads(json.dumps(COONS))
    bad["c1"]["bezier"][1] = ["1/2", 0]
    problems = [
        bad,
        {"op": "coons", "blned": "cubic"},
        {"op": "circle", "radius": "1/0", "arcs": 4},
        dict(COONS, c1={"bezier": [[0, 0, 0], [0.5, 0, 2], [1, 0, 3], [2, 0, 0]]}),
        {"op": "nope"},
    ]
    cli = cli_solve(problems)
    answers = cagd.solve_batch(problems, errors="return")
    for theirs, ours in zip(cli, answers):
        assert not theirs["ok"]
        assert isinstance(ours, cagd.CagdError)
        assert str(ours) == theirs["error"]
