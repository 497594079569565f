#!/usr/bin/env bash
# The side-by-side comparison of cagd-exact with SymPy and python-flint, in one command
# (`just bench-peers`): installs both in a local virtual environment, has cagd-exact write the
# inputs of tasks T1-T6 with its exact answers and timings (cagd-bench's `peers-data`), runs the
# same tasks in SymPy and in FLINT and as whole `cagd solve` processes (the release binary, on
# each task's input written as a problem file, alternately with FLINT), checks that every exact
# answer is identical, and writes docs/performance.md.
#
# Environment: PEERS_VENV (default target/peers-venv), CARGO_TARGET_DIR (default target),
# PEERS_OUT (default docs/performance.md), PEERS_FILTER (only tasks whose name contains it),
# PEERS_SKIP_SYMPY=1 (FLINT only; the SymPy column stays empty), PEERS_PROBLEMS (a directory
# to keep the tasks' `cagd solve` problem files in, e.g. to profile one; by default a temporary
# one), PEERS_PYTHON=0 (without the Python module's in-process column; by default run.sh installs
# it in the virtual environment and times it beside FLINT).
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../../.." && pwd)"
venv="${PEERS_VENV:-$root/target/peers-venv}"
out="${PEERS_OUT:-$root/docs/performance.md}"
filter="${PEERS_FILTER:-}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

# Measure at a higher priority when allowed (root), else at the normal one.
if nice -n -5 true 2>/dev/null; then prio=(nice -n -5); else prio=(); fi

if [ ! -x "$venv/bin/python" ]; then
    python3 -m venv "$venv"
fi
"$venv/bin/python" -m pip install --quiet --disable-pip-version-check sympy python-flint
if [ "${PEERS_PYTHON:-1}" != "0" ]; then
    echo "== the Python module (pip install ./crates/python, release)" >&2
    CARGO_TARGET_DIR="${CARGO_TARGET_DIR:-$root/target}/python" "$venv/bin/python" -m pip install \
        --quiet --disable-pip-version-check --force-reinstall --no-deps "$root/crates/python"
fi

echo "== building cagd-bench and cagd (release)" >&2
(cd "$root" && cargo build --release --quiet -p cagd-bench --bin peers-data)
(cd "$root" && cargo build --release --quiet --bin cagd)
bin="${CARGO_TARGET_DIR:-$root/target}/release/peers-data"
cagd="${CARGO_TARGET_DIR:-$root/target}/release/cagd"
problems="${PEERS_PROBLEMS:-$work/problems}"

echo "== cagd-exact: inputs, exact answers and timings" >&2
cat /proc/loadavg > "$work/load-before" 2>/dev/null || true
ps -eo pcpu,comm --sort=-pcpu 2>/dev/null | head -8 > "$work/ps-before" || true
"${prio[@]}" "$bin" "$work/cagd.json" "$filter"

echo "== SymPy, python-flint and cagd solve processes" >&2
SYMPY_GROUND_TYPES=flint "${prio[@]}" "$venv/bin/python" "$here/peers.py" \
    --cagd "$work/cagd.json" --out "$out" --cagd-bin "$cagd" --problems "$problems" \
    --load-before "$work/load-before" --ps-before "$work/ps-before"
echo "wrote $out" >&2
