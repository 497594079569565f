#!/usr/bin/env python3
"""Module import cycles inside Rust crates.

For each crate directory given (default: every crate under crates/), maps each source file to
its module path, collects the modules it names (`crate::a::b`, `super::x`, `self::x`, and `use`
groups `crate::{a, b::c}`), follows a name through the `use` items of the module it is
named from (so `crate::Foo`, re-exported by lib.rs from `foo`, is an edge to `foo`), and prints every strongly connected component of more than one
module: a set of modules that import each other, directly or through others. Exit code 1 when
a crate listed with --deny has a cycle.

    python3 tools/module_cycles.py                 # report every crate
    python3 tools/module_cycles.py --deny crates/problem crates/keys
"""
import os
import re
import sys


def module_of(src, path):
    rel = os.path.relpath(path, src)[:-3].split(os.sep)
    if rel[-1] in ("lib", "main", "mod"):
        rel = rel[:-1]
    return tuple(rel)


def modules(src):
    mods = {}
    for root, _, files in os.walk(src):
        for f in files:
            if f.endswith(".rs"):
                p = os.path.join(root, f)
                mods[module_of(src, p)] = p
    return mods


def strip_comments(text):
    text = re.sub(r"/\*.*?\*/", "", text, flags=re.S)
    return re.sub(r"//[^\n]*", "", text)


def expand_group(prefix, body):
    """`a::{b, c::{d, e}}` -> [a::b, a::c::d, a::c::e] (segments only)."""
    out, depth, cur = [], 0, ""
    for ch in body:
        if ch == "{":
            depth += 1
        elif ch == "}":
            depth -= 1
        if ch == "," and depth == 0:
            out.append(cur)
            cur = ""
        else:
            cur += ch
    out.append(cur)
    paths = []
    for item in out:
        item = item.strip()
        if not item:
            continue
        m = re.match(r"^([\w:]*?)::\{(.*)\}$", item, flags=re.S)
        if m:
            paths += expand_group(prefix + m.group(1).split("::"), m.group(2))
        else:
            paths.append(prefix + [s for s in item.split(" as ")[0].split("::") if s])
    return paths


def references(text, here, is_mod_file):
    text = strip_comments(text)
    refs = []
    # use groups: crate::{...}, super::{...}
    for m in re.finditer(r"\b(crate|super|self)::((?:\w+::)*)\{", text):
        start = m.end()
        depth, i = 1, start
        while i < len(text) and depth:
            depth += {"{": 1, "}": -1}.get(text[i], 0)
            i += 1
        base = [m.group(1)] + [s for s in m.group(2).split("::") if s]
        refs += expand_group(base, text[start : i - 1])
    for m in re.finditer(r"\b(crate|super|self)((?:::\w+)+)", text):
        refs.append([m.group(1)] + m.group(2).strip(":").split("::"))
    # in a module file, a bare path through a child module (`curve::evaluate(..)`,
    # `use curve::Foo`), but not the child's declaration (`mod curve;`)
    if is_mod_file:
        body = re.sub(r"\b(?:pub(?:\([^)]*\))?\s+)?mod\s+\w+\s*;", "", text)
        for m in re.finditer(r"(?<![\w:])(\w+)::", body):
            if m.group(1) not in ("crate", "super", "self", "std", "core", "alloc"):
                refs.append(["self", m.group(1)])
    out = []
    # the module a `super` or `self` is relative to: a mod.rs/lib.rs file is its own module
    parent = here if is_mod_file else here[:-1]
    for r in refs:
        if r[0] == "crate":
            out.append(tuple(r[1:]))
        elif r[0] == "self":
            out.append(parent + tuple(r[1:]) if not is_mod_file else here + tuple(r[1:]))
        else:
            base = list(parent)
            rest = r[1:]
            while rest and rest[0] == "super":
                base = base[:-1]
                rest = rest[1:]
            out.append(tuple(base[:-1] if False else base) + tuple(rest))
    return out


def imports(text, here, is_mod_file, mods):
    """The names a module's `use` items bring in (`use a::b::X;`, `pub use c::{Y, Z as W};`):
    name -> the full path it stands for, relative to the crate root. A path through another
    crate (`use cagd_poly::Poly;`) is left out."""
    text = strip_comments(text)
    parent = here if is_mod_file else here[:-1]
    out = {}
    for m in re.finditer(r"\b(?:pub(?:\([^)]*\))?\s+)?use\s+([^;]+);", text):
        body = m.group(1).strip()
        for path, name in use_paths(body):
            if not path or path[-1] == "*":
                continue
            head = path[0]
            if head == "crate":
                full = tuple(path[1:])
            elif head in ("self", "super"):
                base, rest = list(parent), path
                if rest[0] == "self":
                    rest = rest[1:]
                while rest and rest[0] == "super":
                    base, rest = base[:-1], rest[1:]
                full = tuple(base) + tuple(rest)
            elif parent + (head,) in mods:
                full = parent + tuple(path)
            else:
                continue
            out[name] = full
    return out


def use_paths(body):
    """`a::{b, c::d as e}` -> [(["a", "b"], "b"), (["a", "c", "d"], "e")]."""
    m = re.match(r"^([\w:]*?)::\{(.*)\}$", body, flags=re.S)
    if not m:
        parts = body.split(" as ")
        path = [s for s in parts[0].strip().split("::") if s]
        name = parts[1].strip() if len(parts) > 1 else (path[-1] if path else "")
        return [(path, name)]
    prefix = [s for s in m.group(1).split("::") if s]
    out, depth, cur = [], 0, ""
    for ch in m.group(2) + ",":
        if ch == "{":
            depth += 1
        elif ch == "}":
            depth -= 1
        if ch == "," and depth == 0:
            if cur.strip():
                out += [(prefix + p, n) for p, n in use_paths(cur.strip())]
            cur = ""
        else:
            cur += ch
    return out


def resolve(r, mods, uses, depth=0):
    """The module a path names: its longest prefix that is a module, followed through that
    module's `use` items when the next segment is a name it imports (`crate::escape_latex`
    re-exported by lib.rs from `escape` names the module `escape`)."""
    for k in range(len(r), -1, -1):
        if r[:k] in mods:
            nxt = r[k] if k < len(r) else None
            target = uses.get(r[:k], {}).get(nxt) if nxt else None
            if target is not None and depth < 16 and target != r[: k + 1]:
                return resolve(target + r[k + 1 :], mods, uses, depth + 1)
            return r[:k]
    return None


def graph(src):
    mods = modules(src)
    edges = {m: set() for m in mods}
    texts, uses = {}, {}
    for m, p in mods.items():
        is_mod_file = os.path.basename(p) in ("mod.rs", "lib.rs", "main.rs") or os.path.isdir(p[:-3])
        with open(p, encoding="utf-8") as f:
            texts[m] = (f.read(), is_mod_file)
        uses[m] = imports(texts[m][0], m, is_mod_file, mods)
    for m, (text, is_mod_file) in texts.items():
        for r in references(text, m, is_mod_file):
            # the module the path names, through re-exports
            target = resolve(r, mods, uses)
            if target is not None and target != m and target != ():
                edges[m].add(target)
    return mods, edges


def sccs(edges):
    index, low, stack, on, out, counter = {}, {}, [], set(), [], [0]

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in edges[v]:
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            out.append(comp)

    sys.setrecursionlimit(10000)
    for v in edges:
        if v not in index:
            visit(v)
    return [c for c in out if len(c) > 1]


def main(argv):
    deny = "--deny" in argv
    dirs = [a for a in argv if not a.startswith("--")]
    if not dirs:
        dirs = sorted(os.path.join("crates", d) for d in os.listdir("crates"))
    failed = False
    for d in dirs:
        src = os.path.join(d, "src")
        if not os.path.isdir(src):
            continue
        _, edges = graph(src)
        cycles = sccs(edges)
        name = os.path.basename(d.rstrip("/"))
        if not cycles:
            print(f"{name}: no module imports one that imports it back")
            continue
        failed = True
        for c in cycles:
            names = sorted("::".join(m) or "crate" for m in c)
            print(f"{name}: a cycle of {len(c)} modules: {', '.join(names)}")
    return 1 if failed and deny else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
