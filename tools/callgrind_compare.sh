#!/usr/bin/env bash
# Two builds of `cagd` side by side on the same problem files: the instructions of the whole
# process (`cagd solve FILE --format json`, from exec to exit) under callgrind, which do not
# move with the load of the machine, and whether the two answers are byte for byte the same.
#
#   tools/callgrind_compare.sh OLD_CAGD NEW_CAGD DIR     # DIR: tools/peers_problems.py's output
set -euo pipefail
old="$1"; new="$2"; dir="$3"
count() {
    valgrind --tool=callgrind --callgrind-out-file=/dev/null "$1" solve "$2" --format json 2>&1 >/dev/null |
        sed -n 's/.*Collected : \([0-9]*\).*/\1/p'
}
printf '%-28s %14s %14s %8s %s\n' problem old new new/old answers
for f in "$dir"/*.json; do
    a=$(count "$old" "$f"); b=$(count "$new" "$f")
    same=same
    cmp -s <("$old" solve "$f" --format json 2>&1) <("$new" solve "$f" --format json 2>&1) || same=DIFFER
    printf '%-28s %14s %14s %8s %s\n' "$(basename "$f")" "$a" "$b" "$(python3 -c "print(f'{$b/$a:.3f}')")" "$same"
done
