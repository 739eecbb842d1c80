#!/usr/bin/env bash
# Issue 26's "Must show" ratios in one command, for a quiet machine (kernel/README.md,
# "The parallel build"): dtlab serial, dtlab on 2 threads, CGAL Parallel_tag and HXT (gmsh)
# on 2 threads, on 10^6 uniform and 10^6 mesh-sampled points held in memory, rounds
# alternated between the tools (dtlab bench's own machinery), then the medians, the spread
# and the ratios:
#   speed-up = dtlab serial / dtlab 2 threads   (goal >= 1.7)
#   dtlab 2 threads / cgal-parallel 2 threads   (goal <= 0.6)
#   dtlab 2 threads / gmsh-hxt 2 threads        (goal <= 0.6)
# Usage: bench/parallel_speed.sh [SIZES [RUNS [THREADS]]]   (defaults 1e6, 5, 2)
# About 4-5 minutes at the defaults on an idle 2-core machine. Set DTLAB to the binary
# (default build/release/cli/dtlab); OUT to keep the JSON (default a temporary file).
set -euo pipefail
sizes=${1:-1e6}
runs=${2:-5}
threads=${3:-2}
dtlab=${DTLAB:-build/release/cli/dtlab}
out=${OUT:-$(mktemp --suffix=.json)}
echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
"$dtlab" bench --sizes "$sizes" --family uniform,mesh --tools dtlab-serial,dtlab,cgal-parallel,gmsh-hxt \
  --threads "$threads" --runs "$runs" --out "$out"
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
/usr/bin/python3 - "$out" <<'PY'
import json, sys
rows = json.load(open(sys.argv[1]))
by = {}
for r in rows:
    by.setdefault((r["distribution"], r["n"]), {})[r["tool"]] = r
print("\n| points | distribution | serial / dtlab (>= 1.7) | dtlab / cgal-parallel (<= 0.6) | dtlab / gmsh-hxt (<= 0.6) |")
print("| ---: | --- | ---: | ---: | ---: |")
def ratio(a, b):
    # median ratio, and the range from the runs' extremes (min/max and max/min)
    if not a or not b or a["median_s"] <= 0 or b["median_s"] <= 0:
        return "n/a"
    return "%.2f [%.2f, %.2f]" % (a["median_s"] / b["median_s"], a["min_s"] / b["max_s"], a["max_s"] / b["min_s"])
for (dist, n), t in sorted(by.items()):
    d = t.get("dtlab")
    print("| %d | %s | %s | %s | %s |" % (n, dist, ratio(t.get("dtlab-serial"), d), ratio(d, t.get("cgal-parallel")),
                                         ratio(d, t.get("gmsh-hxt"))))
PY
