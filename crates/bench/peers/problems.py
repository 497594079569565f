"""The tasks T1-T6 of docs/performance.md as `cagd solve` problems (docs/format.md), shared by
peers.py and tools/peers_problems.py."""


def problem_json(task):
    """The task's input as a `cagd solve` problem (docs/format.md), numbers as written by peers-data."""
    label, n, raw = task["label"], task["n"], task["input"]
    surface = {"bezier": raw["mesh"]}
    if label == "T1":
        return {"op": "evaluate", "surface": surface, "params": raw["params"]}
    if label == "T2":
        return {"op": "elevate", "surface": surface, "by": [task["extra"], task["extra"]]}
    if label == "T3":
        return {"op": "restrict", "surface": surface, "u": ["1/3", "3/4"], "v": ["1/5", "1/2"]}
    if label == "T4":
        uniform = [f"{i}/{n}" for i in range(n + 1)]
        return {"op": "interpolate", "basis": "bezier", "u": uniform, "v": uniform, "points": raw["mesh"]}
    if label == "T5":
        return {"op": "closed_form", "surface": surface}
    if label == "T6":
        return {"op": "approximate", "degree": [n, n], "points": raw["points"], "params": raw["params"]}
    raise ValueError(label)

