#!/usr/bin/env bash
# Runs every fuzz target of cagd-exact for SECONDS seconds each (default 600), one at a time,
# at the lowest priority. New inputs go to a scratch corpus (fuzz/artifacts/work/<target>),
# so the seeds in fuzz/corpus/<target> stay the few dozen that are committed; crashes go to
# fuzz/artifacts/<target>/. Needs cargo-fuzz (cargo install cargo-fuzz); on stable Rust,
# RUSTC_BOOTSTRAP=1 lets it use the sanitizer flags. The timeout is 30 s a unit: the
# instrumented build runs exact arithmetic about 50 times slower than a release build.
#
#   bash fuzz/run.sh            # every target, 10 minutes each
#   bash fuzz/run.sh 60 parse_expr
set -euo pipefail
cd "$(dirname "$0")"
seconds="${1:-600}"
shift || true
targets=("$@")
if [ ${#targets[@]} -eq 0 ]; then
    targets=(parse_number read_number parse_expr solve_json solve_structured)
fi
export RUSTC_BOOTSTRAP=1
failed=()
for t in "${targets[@]}"; do
    mkdir -p "artifacts/work/$t"
    echo "== fuzz $t for ${seconds}s"
    extra=()
    if [ "$t" = solve_json ] || [ "$t" = solve_structured ]; then
        # A whole problem in the instrumented build runs 100-200 times slower than `cagd
        # solve` (a rational patch's normal in Q(√2) with 50-digit weights: 0.13 s in release,
        # over 30 s here, nearly all of it num-bigint's gcd in BigRational). Fork mode records
        # such slow units in artifacts/ (to be timed with a release build) and goes on; a
        # panic still stops the run.
        extra=(-fork=1 -ignore_timeouts=1 -ignore_ooms=0 -ignore_crashes=0)
    fi
    if ! nice -n 19 cargo fuzz run "$t" "artifacts/work/$t" "corpus/$t" -- \
        -max_total_time="$seconds" -timeout=30 -rss_limit_mb=2048 -print_final_stats=1 \
        "${extra[@]}"; then
        failed+=("$t")
    fi
done
if [ ${#failed[@]} -gt 0 ]; then
    echo "== crashes in: ${failed[*]} (inputs in fuzz/artifacts/<target>/)"
    exit 1
fi
echo "== no crash"
