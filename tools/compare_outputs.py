#!/usr/bin/env python3
"""Two builds of `cagd` side by side on what a teacher meets: every fixture under fixtures/ and
every example problem of docs/format.md (code blocks tagged `json problem`), each solved in
every format (text, LaTeX, Markdown, JSON) and language (en, es), with and without --steps.
Prints each output that differs (a unified diff, cut), and a count.

    python3 tools/compare_outputs.py OLD_CAGD NEW_CAGD [--full]
"""
import difflib
import glob
import os
import subprocess
import sys
import tempfile


def doc_examples(path="docs/format.md"):
    out, cur = [], None
    for n, line in enumerate(open(path, encoding="utf-8"), 1):
        fence = line.strip()
        if cur is None:
            if fence == "```json problem":
                cur = (n, [])
        elif fence == "```":
            out.append((f"{path}:{cur[0]}", "".join(cur[1])))
            cur = None
        else:
            cur[1].append(line)
    return out


def run(cagd, path, args):
    p = subprocess.run([cagd, "solve", path, *args], capture_output=True, timeout=600)
    return p.returncode, p.stdout.decode("utf-8", "replace"), p.stderr.decode("utf-8", "replace")


def main(argv):
    old, new = argv[0], argv[1]
    full = "--full" in argv
    problems = [(f, None) for f in sorted(glob.glob("fixtures/**/*.json", recursive=True))]
    tmp = tempfile.mkdtemp()
    for i, (where, text) in enumerate(doc_examples()):
        f = os.path.join(tmp, f"format_{i:02}.json")
        open(f, "w", encoding="utf-8").write(text)
        problems.append((f, where))
    runs = differ = 0
    for f, where in problems:
        for fmt in ("text", "latex", "markdown", "json"):
            for lang in ("en", "es"):
                if fmt == "json" and lang == "es":
                    continue
                for steps in ([], ["--steps"]):
                    args = ["--format", fmt, "--lang", lang, *steps]
                    a, b = run(old, f, args), run(new, f, args)
                    runs += 1
                    if a == b:
                        continue
                    differ += 1
                    print(f"== {where or f} {' '.join(args)}: exit {a[0]} -> {b[0]}")
                    lines = list(difflib.unified_diff(
                        (a[1] + a[2]).splitlines(), (b[1] + b[2]).splitlines(), lineterm="", n=0))
                    print("\n".join(lines if full else lines[:12]))
    print(f"{runs} outputs compared, {differ} differ")
    return 1 if differ else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
