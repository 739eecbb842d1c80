#!/usr/bin/env python3
"""The README's leaderboard table from a `dtlab experiment leaderboard` folder.

    python3 experiments/leaderboard_table.py DIR > table.md
    python3 experiments/leaderboard_table.py --shrinks DIR   # how each pair's shrink ended

One row per peer: cases, non-delaunay verdicts (share, Wilson 95% interval, which),
and for each (source, n) of the speed table the peer's seconds with the ratio to CGAL
in the same run; bytes per tet (peak RSS / tets) at the largest uniform size. Reads
only DIR's leaderboard.csv, data/speed.csv and environment.json, of a finished run
(data/facts.json there: run_folder.py; else it exits 1 naming what is missing). --shrinks: instead,
the failing (peer, source) pairs' shrinks counted by how they ended, and each pair
that is not 1-minimal (leaderboard.csv's shrink columns)."""
import csv
import json
import os
import sys
from collections import Counter, defaultdict

from run_folder import require_whole_run
from wilson import wilson


def failed(row):
    v = row["verdict"]
    if v in ("delaunay", "not-installed"):
        return False
    return not (row["lower_dimensional"] == "1" and v == "refused")


def main(folder):
    env = json.load(open(os.path.join(folder, "environment.json")))
    versions = env.get("peers", {})
    cases, failing, verdicts, order = Counter(), Counter(), defaultdict(Counter), []
    for row in csv.DictReader(open(os.path.join(folder, "leaderboard.csv"))):
        p = row["peer"]
        if p not in order:
            order.append(p)
        if row["verdict"] == "not-installed":
            continue
        cases[p] += 1
        if failed(row):
            failing[p] += 1
            verdicts[p][row["verdict"]] += 1
    speed = list(csv.DictReader(open(os.path.join(folder, "data", "speed.csv"))))
    answered = [r for r in speed if r["verdict"] not in ("crashed", "hung", "out-of-memory", "refused", "not-installed")]
    columns = []
    for r in speed:
        key = (r["source"], int(r["n"]))
        if key not in columns:
            columns.append(key)
    cgal = {(r["source"], int(r["n"])): float(r["seconds"]) for r in answered if r["peer"] == "cgal"}
    timing = {(r["peer"], r["source"], int(r["n"])): r for r in speed}
    uniform_n = max((n for s, n in columns if s == "uniform"), default=None)

    head = ["peer (version)", "cases", "not delaunay", "share [Wilson 95%]", "verdicts (not delaunay)"]
    head += ["s at %s %s (x CGAL)" % (f"{n:.0e}".replace("e+0", "e"), s) for s, n in columns]
    head += ["bytes/tet at %s uniform" % f"{uniform_n:.0e}".replace("e+0", "e")] if uniform_n else []
    print("| " + " | ".join(head) + " |")
    print("| --- | " + " | ".join("---:" for _ in head[1:4]) + " | --- | " + " | ".join("---:" for _ in head[5:]) + " |")
    for p in order:
        row = ["`%s` (%s)" % (p, versions.get(p, "?"))]
        if not cases[p]:
            print("| " + " | ".join(row + ["0", "-", "-", "not-installed"] + ["-"] * (len(head) - 5)) + " |")
            continue
        lo, hi = wilson(failing[p], cases[p])
        row += [str(cases[p]), str(failing[p]),
                "%.0f%% [%.0f%%, %.0f%%]" % (100 * failing[p] / cases[p], 100 * lo, 100 * hi),
                ", ".join("%s %d" % kv for kv in sorted(verdicts[p].items())) or "-"]
        for s, n in columns:
            t = timing.get((p, s, n))
            if not t or t["verdict"] in ("crashed", "hung", "out-of-memory", "refused", "not-installed"):
                row.append(t["verdict"] if t else "-")
                continue
            sec = float(t["seconds"])
            ratio = " (%.2f)" % (sec / cgal[(s, n)]) if cgal.get((s, n)) else ""
            mark = "" if t["verdict"] == "delaunay" else " " + t["verdict"]
            row.append("%.3g%s%s" % (sec, ratio, mark))
        if uniform_n:
            t = timing.get((p, "uniform", uniform_n))
            tets = int(t["tets"]) if t else 0
            row.append("%.0f" % (int(t["peak_rss_bytes"]) / tets) if tets else "-")
        print("| " + " | ".join(row) + " |")


def shrinks(folder):
    rows = [r for r in csv.DictReader(open(os.path.join(folder, "leaderboard.csv"))) if r.get("corpus_file")]
    ended = Counter(r["shrink_ended"] for r in rows)
    print("%d pairs with an input saved: %s" % (len(rows), ", ".join("%s %d" % kv for kv in sorted(ended.items()))))
    for r in rows:
        if r["shrink_ended"] == "1-minimal":
            continue
        print("- %s on %s (%s, n = %s): %s, %s -> %s points, %s passes, %s runs, %.1f s%s, fresh %s" % (
            r["peer"], r["source"], r["verdict"], r["n"], r["shrink_ended"], r["n"], r["shrunk_points"],
            r["shrink_passes"], r["shrink_runs"], float(r["shrink_seconds"]),
            ", tries under %s s" % r["hung_try_seconds"] if float(r["hung_try_seconds"] or 0) > 0 else "",
            r["shrunk_verdict_fresh"]))


if __name__ == "__main__":
    if len(sys.argv) == 3 and sys.argv[1] == "--shrinks":
        require_whole_run(sys.argv[2], "leaderboard.csv")
        shrinks(sys.argv[2])
    elif len(sys.argv) == 2:
        require_whole_run(sys.argv[1], "environment.json", "leaderboard.csv", os.path.join("data", "speed.csv"))
        main(sys.argv[1])
    else:
        sys.exit(__doc__)
