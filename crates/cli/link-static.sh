#!/usr/bin/env bash
# The linker of x86_64 Linux (glibc) builds, set in .cargo/config.toml: it links the `cagd`
# executable statically and passes every other link (libraries, tests, build scripts, proc
# macros, the Python module) to `cc` unchanged.
#
# Why: a dynamically linked `cagd` spends most of an empty `cagd solve` in the dynamic loader
# (mapping libc, libm and libgcc_s, binding their symbols) and in the page faults that brings;
# linked statically, the empty run costs about what spawning `true` does (docs/performance.md,
# "Start-up"). Rust's own switch for this, `-C target-feature=+crt-static`, cannot be given to
# one binary only: set for the build, it also reaches the proc macros, which cannot be built so.
#
# How: rustc asks for a dynamic link of a position-dependent executable (crates/cli/build.rs
# passes -no-pie); this makes of it the static link rustc itself asks for under crt-static:
# no -Bdynamic, libgcc_eh and libgcc in place of libgcc_s, then -static. Where the static link
# fails (a system without glibc's static libraries, libc.a), `cagd` is linked dynamically, as
# rustc asked: it works the same, it starts more slowly; the static link's messages are then
# kept beside the binary, in deps/cagd-<hash>.static-link.log (.ci/static-check prints them).
set -u
out="" prev=""
for arg in "$@"; do
    [ "$prev" = "-o" ] && out="$arg"
    prev="$arg"
done
case "${out##*/}" in
    cagd-*) ;;
    *) exec cc "$@" ;;
esac
static=()
for arg in "$@"; do
    case "$arg" in
        -Wl,-Bdynamic | -pie | -no-pie) ;;
        -lgcc_s) static+=(-lgcc_eh -lgcc) ;;
        *) static+=("$arg") ;;
    esac
done
log="$out.static-link.log"
if cc "${static[@]}" -lc -static -no-pie 2>"$log"; then
    rm -f "$log"
    exit 0
fi
exec cc "$@"
