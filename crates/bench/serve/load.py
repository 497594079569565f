#!/usr/bin/env python3
"""A load benchmark of `cagd serve` (docs/performance.md, "A class on the page"): simulated
students on 127.0.0.1 checking answers, bounded in count and time. Not a test: it measures.

    python3 crates/bench/serve/load.py target/release/cagd [--students 100] [--seconds 30]

The set served is the 13 problems of the diagnosis reports (crates/diagnose/tests/reports/,
one per family of mistakes). Each simulated student checks, again and again, one of three
answers to one of them: the key's own (right), the report's (a known mistake) or one with a
malformed cell. First every answer is checked once and its verdict compared with what it must
be (right: correct; the mistake: wrong, diagnosed with the mistake's id; malformed: not
correct) - a wrong verdict fails the run. Then wrk (Debian's package) keeps `--students`
connections busy for `--seconds`, each a student sending the next answer as soon as the last
is answered; it reports requests per second and the latency percentiles. The server's
resident memory is read from /proc every half second. Failed requests (a socket error, a
status other than 200, a timeout) make the run fail.
"""
import argparse, json, os, re, shutil, socket, subprocess, sys, tempfile, threading, time
import urllib.request

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", "..", ".."))
REPORTS = os.path.join(ROOT, "crates", "diagnose", "tests", "reports")

LUA = r"""
-- each connection is a student: the answers are taken in turn, from a different start
local bodies = {}
local counter = 0
function init(args)
  for line in io.lines(args[1]) do bodies[#bodies + 1] = line end
  counter = math.random(#bodies)
end
function request()
  counter = counter % #bodies + 1
  return wrk.format("POST", "/api/check", {["Content-Type"] = "application/json"}, bodies[counter])
end
"""


def free_port():
    s = socket.socket()
    s.bind(("127.0.0.1", 0))
    port = s.getsockname()[1]
    s.close()
    return port


def post(url, body):
    req = urllib.request.Request(url, data=json.dumps(body).encode(), headers={"Content-Type": "application/json"})
    with urllib.request.urlopen(req, timeout=60) as r:
        return json.load(r)


def malformed(v):
    """The answer with its first number cell changed to text the grammar refuses."""
    done = [False]

    def walk(x):
        if done[0]:
            return x
        if isinstance(x, (int, float)) and not isinstance(x, bool) or isinstance(x, str) and any(c.isdigit() for c in x):
            done[0] = True
            return "5/*"
        if isinstance(x, list):
            return [walk(y) for y in x]
        if isinstance(x, dict):
            return {k: walk(y) for k, y in x.items()}
        return x

    return walk(v)


def rss_kib(pid):
    with open(f"/proc/{pid}/status") as f:
        for line in f:
            if line.startswith("VmRSS:"):
                return int(line.split()[1])
    return 0


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("cagd")
    ap.add_argument("--students", type=int, default=100)
    ap.add_argument("--seconds", type=int, default=30)
    ap.add_argument("--threads", type=int, default=2, help="wrk's threads")
    args = ap.parse_args()
    if not shutil.which("wrk"):
        sys.exit("wrk is needed: apt-get install -y wrk")
    cagd = os.path.abspath(args.cagd)
    tmp = tempfile.mkdtemp(prefix="cagd-load-")
    names = sorted(f for f in os.listdir(REPORTS) if f.endswith(".json"))
    reports = [json.load(open(os.path.join(REPORTS, f))) for f in names]
    problems = [{k: v for k, v in r.items() if k not in ("expected", "student")} for r in reports]
    set_path = os.path.join(tmp, "set.json")
    json.dump(problems, open(set_path, "w"))
    solved = json.loads(subprocess.run([cagd, "solve", set_path, "--format", "json"], check=True,
                                       capture_output=True, text=True).stdout)
    port = free_port()
    server = subprocess.Popen([cagd, "serve", set_path, "--port", str(port)],
                              stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    base = f"http://127.0.0.1:{port}"
    try:
        for _ in range(200):
            try:
                urllib.request.urlopen(base + "/api/set", timeout=2).read()
                break
            except OSError:
                time.sleep(0.1)
        else:
            sys.exit("cagd serve did not answer")
        # the answers, each checked once and its verdict compared
        bodies, failures = [], []
        for i, (r, a) in enumerate(zip(reports, solved)):
            right = {k: v for k, v in a["result"].items() if k not in ("remarks", "steps", "derivation")}
            cases = [("right", right), ("mistake", r["expected"]), ("malformed", malformed(r["expected"]))]
            for kind, answer in cases:
                body = {"problem": i, "answer": answer, "lang": "es" if len(bodies) % 2 else "en"}
                got = post(base + "/api/check", body)
                v = got.get("verdict")
                ok = {"right": v == "correct",
                      "mistake": v == "wrong" and len(got.get("diagnoses", [])) > 0,
                      "malformed": v != "correct"}[kind]
                if not ok:
                    failures.append(f"{names[i]} {kind}: verdict {v}, diagnoses {got.get('diagnoses')}")
                bodies.append(json.dumps(body, ensure_ascii=False))
        if failures:
            print("wrong verdicts:\n  " + "\n  ".join(failures))
            sys.exit(1)
        print(f"{len(bodies)} answers ({len(reports)} problems x right, a known mistake, malformed): every verdict as it must be")
        lines = os.path.join(tmp, "bodies.txt")
        open(lines, "w").write("\n".join(bodies) + "\n")
        lua = os.path.join(tmp, "check.lua")
        open(lua, "w").write(LUA)
        samples = []
        stop = threading.Event()

        def sample():
            while not stop.is_set():
                samples.append((time.time(), rss_kib(server.pid)))
                time.sleep(0.5)

        before = rss_kib(server.pid)
        t = threading.Thread(target=sample)
        t.start()
        run = subprocess.run(["wrk", "-t", str(args.threads), "-c", str(args.students), "-d", f"{args.seconds}s",
                              "--timeout", "30s", "--latency", "-s", lua, base + "/api/check", "--", lines],
                             capture_output=True, text=True)
        stop.set()
        t.join()
        out = run.stdout
        print(out)
        rps = re.search(r"Requests/sec:\s+([\d.]+)", out)
        total = re.search(r"(\d+) requests in", out)
        p50 = re.search(r"^\s+50%\s+(\S+)", out, re.M)
        p99 = re.search(r"^\s+99%\s+(\S+)", out, re.M)
        errors = re.search(r"Socket errors: (.*)", out)
        non2xx = re.search(r"Non-2xx or 3xx responses: (\d+)", out)
        rss = [k for _, k in samples]
        third = max(1, len(rss) // 3)
        first, last = rss[:third], rss[-third:]
        print(f"students (connections): {args.students}, seconds: {args.seconds}, server workers: default")
        print(f"requests: {total.group(1) if total else '?'}, per second: {rps.group(1) if rps else '?'}")
        print(f"latency p50: {p50.group(1) if p50 else '?'}, p99: {p99.group(1) if p99 else '?'}")
        print(f"failed: non-2xx {non2xx.group(1) if non2xx else 0}; socket errors: {errors.group(1) if errors else 'none'}")
        print(f"server memory (RSS): before {before // 1024} MiB; first third of the run max {max(first) // 1024} MiB, "
              f"last third max {max(last) // 1024} MiB, peak {max(rss) // 1024} MiB")
        tenth = max(1, len(rss) // 10)
        print("RSS over the run (MiB, each tenth's max): " + " ".join(str(max(rss[k:k + tenth]) // 1024) for k in range(0, len(rss), tenth)))
        failed = (non2xx is not None) or (errors is not None) or run.returncode != 0
        if failed:
            sys.exit("failed requests")
    finally:
        server.terminate()
        server.wait(timeout=10)
        shutil.rmtree(tmp, ignore_errors=True)


if __name__ == "__main__":
    main()
