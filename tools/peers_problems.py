#!/usr/bin/env python3
"""Writes the peers' benchmark inputs (tasks T1-T6 of docs/performance.md) as `cagd solve`
problem files, one problem and a batch of 100 copies per task, from the JSON that cagd-bench's
`peers-data` writes. The problems are crates/bench/peers/problems.py's, as peers.py runs them.

    cargo build --release -p cagd-bench --bin peers-data
    target/release/peers-data /tmp/cagd.json ""
    python3 tools/peers_problems.py /tmp/cagd.json /tmp/problems
"""
import json
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "crates", "bench", "peers"))
from problems import problem_json  # noqa: E402


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
