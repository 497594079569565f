# A class of 300 students x 10 problems as files, for timing the whole `cagd check` process
# (docs/performance.md, "Checking a class"). Run in an empty folder: python3 make.py PATH/TO/cagd
import json, random, subprocess, sys, os
cagd = sys.argv[1]
topics = ["evaluate","restrict","elevate","derivative","normal","interpolate","translational","ruled","coons","revolution"]
problems = []
for i, t in enumerate(topics):
    subprocess.run([cagd, "generate", "--topic", t, "--count", "1", "--seed", str(7 + i), "--out", f"g{i}"], check=True, capture_output=True)
    problems.append(json.load(open(f"g{i}/problems.json"))[0])
json.dump(problems, open("problems.json", "w"))
out = subprocess.run([cagd, "solve", "problems.json", "--format", "json"], check=True, capture_output=True, text=True).stdout
answers = json.loads(out)
def perturb(v, rng):
    # change one number string somewhere
    paths = []
    def walk(x, path):
        if isinstance(x, str) and any(c.isdigit() for c in x):
            paths.append(path)
        elif isinstance(x, list):
            for k, y in enumerate(x): walk(y, path + [k])
        elif isinstance(x, dict):
            for k, y in x.items(): walk(y, path + [k])
    walk(v, [])
    if not paths: return v
    p = rng.choice(paths)
    x = v
    for k in p[:-1]: x = x[k]
    x[p[-1]] = "7/3"
    return v
rng = random.Random(1)
os.makedirs("students", exist_ok=True)
for s in range(300):
    mine = []
    for p, a in zip(problems, answers):
        q = dict(p)
        r = {k: v for k, v in a["result"].items() if k not in ("remarks", "steps", "derivation")}
        r = json.loads(json.dumps(r))
        if rng.random() < 0.5:
            r = perturb(r, rng)
        q["expected"] = r
        mine.append(q)
    json.dump(mine, open(f"students/s{s:03d}.json", "w"))
print("ok")
