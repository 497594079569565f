# cagd-exact recipes. `just` alone lists them. Every recipe is a shortcut for a plain cargo
# command shown in README.md; nothing here is the only way to do something.

# list the recipes
default:
    @just --list

# run every test (the README's test command)
test:
    cargo test --workspace

# run every worked example of the notes (the README's main job)
examples:
    cargo run --release --bin cagd -- examples

# review changed insta snapshots (needs cargo-insta: cargo install cargo-insta)
review:
    cargo insta review --workspace

# accept all changed snapshots without cargo-insta, then inspect with git diff snapshots/
accept:
    INSTA_UPDATE=always cargo test --workspace
    git diff --stat snapshots/

# what CI runs: fmt, clippy, tests, main job
ci:
    bash .ci/run

# expand a polynomial expression, e.g. just expand "(1-v)*(u,0,u^3) + v*(u,1,u^2)"
expand EXPR:
    cargo run --release --bin cagd -- expand "{{EXPR}}"

# compile the LaTeX keys of every example (en, es) and a problem set with pdflatex, failing on an overfull box (installs texlive if missing)
latex:
    bash .ci/latex-check

# run the benchmarks (criterion) of the exact engine
bench:
    cargo bench -p cagd-bench

# compare with SymPy and python-flint on the same inputs, as library calls and as whole
# `cagd solve` processes; writes docs/performance.md
bench-peers:
    bash crates/bench/peers/run.sh

# fuzz each target for SECONDS (default 60) with cargo fuzz (stable toolchain via
# RUSTC_BOOTSTRAP); `just fuzz 600` is the 10-minute run of fuzz/README.md
fuzz SECONDS="60":
    bash fuzz/run.sh {{SECONDS}}

# render the figure of a problem or answer: just render problem.json out.svg
render FILE OUT:
    cargo run --release --bin cagd -- render {{FILE}} --svg {{OUT}}

# the page where students check their answers (the notes' examples, or: just serve set.json --lang es)
serve *ARGS:
    cargo run --release --bin cagd -- serve {{ARGS}}

# cagd serve under load: 100 simulated students for 90 s (needs wrk: apt-get install -y wrk)
bench-serve:
    cargo build --release --bin cagd
    python3 crates/bench/serve/load.py target/release/cagd --students 100 --seconds 90
