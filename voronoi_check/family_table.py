# The README's Voronoi table: every Voronoi peer on N sites of each fuzz family, judged by
# `dtlab voronoi F --against all --json`; prints one line per family, then the table.
#   PYTHONPATH=build/release/python /usr/bin/python3 voronoi_check/family_table.py DTLAB OUTDIR [N] [SEED]
import collections, json, os, subprocess, sys

import numpy as np

import dtlab

dtlab_bin, outdir = sys.argv[1], sys.argv[2]
n = int(sys.argv[3]) if len(sys.argv) > 3 else 200
seed = int(sys.argv[4]) if len(sys.argv) > 4 else 1
os.makedirs(outdir, exist_ok=True)
verdicts = collections.defaultdict(dict)
for fam in dtlab.fuzz.families():
    name = fam if isinstance(fam, str) else fam[0]
    f = os.path.join(outdir, name + ".xyz")
    np.savetxt(f, dtlab.fuzz.generate(name, n, seed=seed), fmt="%.17g")
    r = subprocess.run([dtlab_bin, "voronoi", f, "--against", "all", "--json", "--quiet", "--no-obj",
                        "--timeout", "30"], capture_output=True, text=True)
    j = json.loads(r.stdout) if r.stdout.strip() else {}
    with open(os.path.join(outdir, name + ".json"), "w") as out:
        json.dump({k: j[k] for k in ("exact_check", "peers") if k in j}, out, indent=1)
    if "peers" not in j:
        print(name, "exit", r.returncode, j.get("error", {}).get("reason", r.stderr.strip()[:100]))
        continue
    for p, v in j["peers"].items():
        verdicts[p][name] = v["verdict"]
    print(name, "exit", r.returncode, "ours", j["exact_check"]["verdict"], "|",
          " ; ".join("%s=%s %s" % (p, v["verdict"], v.get("counts", "")) for p, v in j["peers"].items()), flush=True)
kinds = ["exact-topology", "rounded-topology", "bad-geometry", "volume-mismatch", "wrong-topology", "refused"]
print("| peer | " + " | ".join(kinds) + " | families not exact |")
print("| --- | " + " | ".join("---:" for _ in kinds) + " | --- |")
for p, per in verdicts.items():
    c = collections.Counter(per.values())
    bad = ", ".join("%s (%s)" % (f, v) for f, v in per.items() if v != "exact-topology")
    print("| `%s` | %s | %s |" % (p, " | ".join(str(c[k]) for k in kinds), bad))
