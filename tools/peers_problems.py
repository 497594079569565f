#!/usr/bin/env python3
"""Writes the peers' benchmark inputs (tasks T1-T6 of docs/performance.md) as `cagd solve`
problem files, one problem and a batch of 100 copies per task, from the JSON that cagd-bench's
`peers-data` writes. The problems are those of crates/bench/peers/peers.py (`problem_json`).

    cargo build --release -p cagd-bench --bin peers-data
    target/release/peers-data /tmp/cagd.json ""
    python3 tools/peers_problems.py /tmp/cagd.json /tmp/problems
"""
import json
import os
import sys


def problem_json(task):
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


def main(source, out):
    with open(source) as f:
        cagd = json.load(f)
    os.makedirs(out, exist_ok=True)
    for task in cagd["tasks"]:
        name = task["name"].replace(" ", "_")
        p = problem_json(task)
        with open(os.path.join(out, name + ".json"), "w") as f:
            json.dump(p, f)
        with open(os.path.join(out, name + "-x100.json"), "w") as f:
            json.dump([p] * 100, f)
    print(len(cagd["tasks"]), "tasks")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
