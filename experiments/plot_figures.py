#!/usr/bin/python3
"""Figures of a dtlab experiment report, drawn from DIR/data/results.json.

Usage: /usr/bin/python3 plot_figures.py DIR   (Debian's python3-matplotlib)
"""
import json
import os
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402

BACKEND_STYLE = {
    "naive": ("tab:red", "o"),
    "epsilon": ("tab:orange", "s"),
    "adaptive+sos": ("tab:green", "^"),
    "exact+sos": ("tab:blue", "v"),
}
TOOL_STYLE = {"dtlab": ("tab:green", "o"), "cgal": ("tab:blue", "s"), "tetgen": ("tab:purple", "^")}


def wilson(k, n, z=1.959963984540054):
    """95% Wilson score interval of k failures in n cases: (rate, low, high)."""
    if n == 0:
        return 0.0, 0.0, 1.0
    p = k / n
    centre = p + z * z / (2 * n)
    spread = z * ((p * (1 - p) / n + z * z / (4 * n * n)) ** 0.5)
    scale = 1 + z * z / n
    low = 0.0 if k == 0 else (centre - spread) / scale
    high = 1.0 if k == n else (centre + spread) / scale
    return p, low, high


def rate_errorbar(ax, xs, ks, ns, **style):
    """Failure rates k/n at xs with their 95% Wilson intervals as error bars."""
    r = [wilson(k, n) for k, n in zip(ks, ns)]
    # the axis ends at exactly 0 and 1: markers there are drawn whole, not clipped
    ax.errorbar(xs, [x[0] for x in r], yerr=[[x[0] - x[1] for x in r], [x[2] - x[0] for x in r]], capsize=2,
                clip_on=False, **style)


def rate_axis(ax, label):
    ax.set_ylim(0, 1)
    ax.set_ylabel(label)


def save(fig, d, name):
    fig.tight_layout()
    fig.savefig(os.path.join(d, name), dpi=110)
    plt.close(fig)
    print("wrote", name)


def grid_axes(k, ncols=4, size=3.2):
    nrows = (k + ncols - 1) // ncols
    ncols = min(ncols, k)
    fig, axes = plt.subplots(nrows, ncols, figsize=(size * ncols, size * 0.85 * nrows + 0.4), squeeze=False)
    flat = [a for row in axes for a in row]
    for a in flat[k:]:
        a.axis("off")
    return fig, flat[:k]


# ---------------------------------------------------------------- thesis-failures

def fig_rates(d, rates):
    fams = rates["families"]
    fig, axes = grid_axes(len(fams))
    cells = rates["cells"]
    # coinciding lines stay visible by size (drawn largest first), never by moving them
    for ax, fam in zip(axes, fams):
        for k, (b, (color, marker)) in enumerate(BACKEND_STYLE.items()):
            pts = sorted((c["n"], c["failed"], c["cases"]) for c in cells if c["family"] == fam and c["backend"] == b)
            if pts:
                rate_errorbar(ax, [p[0] for p in pts], [p[1] for p in pts], [p[2] for p in pts], color=color,
                              marker=marker, label=b, alpha=0.85, lw=3.0 - 0.6 * k, ms=9 - 1.5 * k)
        ax.set_xscale("log", base=2)
        rate_axis(ax, "failure rate")
        ax.set_title(fam, fontsize=10)
        ax.set_xlabel("n (points)")
        ax.grid(alpha=0.3)
    axes[0].legend(fontsize=8)
    fig.suptitle("Failure rate (build stopped or checker defect) per backend, %d cases per point, 95%% Wilson intervals"
                 % rates["cases"])
    save(fig, d, "fig_rates.png")

    # naive: what goes wrong, pooled over families
    kinds = [("failed", "any failure"), ("crash", "walk/flip loop (crash)"),
             ("overlap_inverted", "overlapping / inverted"), ("missing_point", "points missing (incl. stopped builds)"),
             ("non_delaunay", "non-Delaunay facets")]
    fig, ax = plt.subplots(figsize=(6.4, 4))
    for key, label in kinds:
        agg = defaultdict(lambda: [0, 0])
        for c in cells:
            if c["backend"] == "naive" and c["family"] != "uniform":
                agg[c["n"]][0] += c[key]
                agg[c["n"]][1] += c["cases"]
        ns = sorted(agg)
        dashed = key == "crash"  # equal to "missing" when no missing-point defect: keep it visible
        rate_errorbar(ax, ns, [agg[n][0] for n in ns], [agg[n][1] for n in ns], marker="x" if dashed else "o",
                      ls="--" if dashed else "-", lw=2.5 if dashed else 1.5, ms=9 if dashed else 6, label=label,
                      zorder=3 if dashed else 2)
    ax.set_xscale("log", base=2)
    rate_axis(ax, "share of naive cases")
    ax.set_xlabel("n (points)")
    ax.set_title("Naive floating point, every family but uniform pooled\n(95% Wilson intervals)")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    save(fig, d, "fig_naive_kinds.png")


def fig_epsilon(d, eps):
    fig, axes = plt.subplots(1, 2, figsize=(11, 4), sharey=True)
    fams = eps["families"]
    colors = plt.cm.tab10.colors
    for ax, mode in zip(axes, ["absolute", "relative"]):
        for i, fam in enumerate(fams):
            pts = sorted((c["eps"], c["failed"], c["cases"]) for c in eps["cells"]
                         if c["family"] == fam and c["mode"] == mode)
            base = [c["failed"] / c["cases"] for c in eps["cells"] if c["family"] == fam and c["mode"] == "naive"]
            # the true values, unshifted: coinciding lines stay visible by size (largest first)
            rate_errorbar(ax, [p[0] for p in pts], [p[1] for p in pts], [p[2] for p in pts], marker="o",
                          color=colors[i], label=fam, lw=3.2 - 0.5 * i, ms=9 - 1.2 * i, alpha=0.8)
            if base:
                ax.axhline(base[0], color=colors[i], ls=":", lw=1)
        ax.set_xscale("log")
        ax.set_ylim(0, 1)
        ax.set_xlabel("eps (%s band)" % mode)
        ax.set_title("epsilon predicates, %s: |det| <= eps%s" % (mode, "" if mode == "absolute" else " * M^k"))
        ax.grid(alpha=0.3)
    axes[0].set_ylabel("failure rate (dotted: naive)")
    axes[0].legend(fontsize=8)
    fig.suptitle("A tolerance does not fix it (n = %d, %d cases per point, 95%% Wilson intervals)"
                 % (eps["n"], eps["cases"]))
    save(fig, d, "fig_epsilon.png")


def fig_bigtet(d, big):
    fig, axes = plt.subplots(1, 2, figsize=(11, 4))
    colors = plt.cm.tab10.colors
    i = 0
    for fam in big["families"]:
        for n in big["sizes"]:
            cells = [c for c in big["cells"] if c["family"] == fam and c["n"] == n]
            fs = sorted(set(c["factor"] for c in cells))
            miss, wrong, count = [], [], []
            for f in fs:
                cs = [c for c in cells if c["factor"] == f]
                miss.append(sum(1.0 if c["failure"] else c["missing"] / max(1, c["reference_tets"]) for c in cs) / len(cs))
                wrong.append(sum(1 for c in cs if c["failure"] or c["missing"] or c["extra"]))
                count.append(len(cs))
            style = "-" if n == big["sizes"][0] else "--"
            axes[0].plot(fs, miss, style, marker="o", ms=3, color=colors[i % 10], label="%s n=%d" % (fam, n))
            rate_errorbar(axes[1], fs, wrong, count, ls=style, marker="o", ms=3, color=colors[i % 10],
                          label="%s n=%d" % (fam, n))
        i += 1
    for ax in axes:
        ax.set_xscale("log")
        ax.set_xlabel("bigtet factor (1 = smallest holding the bounding box)")
        ax.grid(alpha=0.3)
    axes[0].set_yscale("symlog", linthresh=1e-3)
    axes[0].set_ylim(0, 1)
    axes[0].set_ylabel("share of true DT tets missing (mean)")
    rate_axis(axes[1], "share of inputs whose result is not the DT")
    axes[1].legend(fontsize=7)
    fig.suptitle("The big enclosing tetrahedron vs the infinite vertex (adaptive+sos; right: 95% Wilson intervals)")
    save(fig, d, "fig_bigtet.png")


def fig_cost(d, cost):
    cells = cost["cells"]
    groups = sorted(set((c["source"], c["n"]) for c in cells), key=lambda g: (g[0], g[1]))
    backends = list(BACKEND_STYLE)
    fig, ax = plt.subplots(figsize=(max(6, 1.3 * len(groups)), 4))
    w = 0.8 / len(backends)
    for j, b in enumerate(backends):
        xs, ys, lo, hi = [], [], [], []
        for i, g in enumerate(groups):
            for c in cells:
                if (c["source"], c["n"]) == g and c["backend"] == b:
                    xs.append(i + (j - 1.5) * w)
                    ys.append(c["median_s"])
                    lo.append(c["median_s"] - c["min_s"])
                    hi.append(c["max_s"] - c["median_s"])
        ax.bar(xs, ys, width=w, color=BACKEND_STYLE[b][0], label=b, yerr=[lo, hi], capsize=2)
    for i, g in enumerate(groups):
        for j, b in enumerate(backends):
            for c in cells:
                if (c["source"], c["n"]) == g and c["backend"] == b and (c["defects"] or c["failure"]):
                    ax.text(i + (j - 1.5) * w, c["median_s"], "x", ha="center", va="bottom", color="red",
                            fontsize=11, fontweight="bold")
    ax.set_xticks(range(len(groups)))
    ax.set_xticklabels(["%s\nn=%d" % g for g in groups], fontsize=8)
    ax.set_yscale("log")
    ax.set_ylabel("build time, s (median; bars: min to max)")
    ax.set_title("Cost of robustness, %d runs per bar (exact at 10^5: 1) (red x: wrong result)" % cost["runs"])
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3, axis="y")
    save(fig, d, "fig_cost.png")


def fig_sampling(d, s):
    fig, ax = plt.subplots(figsize=(6.4, 4))
    colors = {"rays": "tab:red", "sdf": "tab:orange", "winding": "tab:green"}
    for m in ["rays", "sdf", "winding"]:
        pts = sorted((c["removed_fraction"], c["outside"], c["points"]) for c in s["cells"] if c["method"] == m)
        rate_errorbar(ax, [100 * p[0] for p in pts], [p[1] for p in pts], [p[2] for p in pts], marker="o",
                      color=colors[m], label=m)
    ax.set_xlabel("faces removed from the bumpy torus (%)")
    rate_axis(ax, "share of samples outside the solid")
    ax.set_title("Volume samplers on a mesh with holes\n(%d points each, 95%% Wilson intervals)" % s["count"])
    ax.grid(alpha=0.3)
    ax.legend()
    save(fig, d, "fig_sampling.png")

    fig, axes = plt.subplots(1, 3, figsize=(13, 3.4), sharey=True)
    for ax, m in zip(axes, ["rays", "sdf", "winding"]):
        path = os.path.join(d, "data", "slice_%s.json" % m)
        if not os.path.exists(path):
            continue
        pts = json.load(open(path))
        inside = [p for p in pts if p[2]]
        outside = [p for p in pts if not p[2]]
        ax.scatter([p[0] for p in inside], [p[1] for p in inside], s=2, color="0.5", label="inside")
        ax.scatter([p[0] for p in outside], [p[1] for p in outside], s=6, color="red",
                   label="outside (%d)" % len(outside))
        ax.set_aspect("equal")
        ax.set_ylim(-0.6, 0.9)
        ax.set_title("%s: slab |y| < 0.05" % m)
        ax.set_xlabel("x")
        ax.legend(fontsize=8, loc="upper center")
    axes[0].set_ylabel("z")
    fig.suptitle("Bumpy torus with every 20th face removed: where the samples land")
    save(fig, d, "fig_sampling_slice.png")


def fig_overlap(d, case):
    if not case:
        return
    import numpy as np

    P = np.array(case["points"], dtype=float)
    # principal axes of the points, each stretched to unit extent: a failing configuration
    # is nearly flat or collinear, and a positive scaling per axis keeps every orientation
    c = P.mean(axis=0)
    _, _, vt = np.linalg.svd(P - c)
    if np.linalg.det(vt) < 0:
        vt[2] = -vt[2]
    Q = (P - c) @ vt.T
    stretch = np.abs(Q).max(axis=0)
    Q = Q / np.where(stretch > 0, stretch, 1)
    tets = case["naive_tets"]
    named = defaultdict(set)
    for df in case["defects"]:
        if df["kind"] in ("overlap", "inverted", "flat"):
            for t in df["tets"]:
                named[t].add(df["kind"])
    faces = lambda t: [[Q[t[0]], Q[t[1]], Q[t[2]]], [Q[t[0]], Q[t[1]], Q[t[3]]],
                       [Q[t[0]], Q[t[2]], Q[t[3]]], [Q[t[1]], Q[t[2]], Q[t[3]]]]
    fig = plt.figure(figsize=(12, 5))
    views = [(20, 30), (20, 120), (70, 60)]
    colors = ["tab:red", "tab:orange", "tab:purple", "tab:brown"]
    for k, (elev, azim) in enumerate(views):
        ax = fig.add_subplot(1, 3, k + 1, projection="3d")
        for ti, t in enumerate(tets):
            if ti in named:
                continue
            ax.add_collection3d(Poly3DCollection(faces(t), facecolor=(0.6, 0.6, 0.6, 0.05),
                                                 edgecolor=(0.4, 0.4, 0.4, 0.5), lw=0.5))
        for j, ti in enumerate(sorted(named)):
            col = colors[j % len(colors)]
            ax.add_collection3d(Poly3DCollection(faces(tets[ti]), facecolor=matplotlib.colors.to_rgba(col, 0.25),
                                                 edgecolor=col, lw=1.5))
        ax.scatter(Q[:, 0], Q[:, 1], Q[:, 2], color="k", s=12)
        for i, q in enumerate(Q):
            ax.text(q[0], q[1], q[2], " %d" % i, fontsize=7)
        ax.set_xlim(-1, 1)
        ax.set_ylim(-1, 1)
        ax.set_zlim(-1, 1)
        ax.view_init(elev=elev, azim=azim)
        ax.set_xticks([])
        ax.set_yticks([])
        ax.set_zticks([])
    label = ", ".join("tet %d: %s" % (t, "/".join(sorted(k))) for t, k in sorted(named.items()))
    if any("inverted" in k for k in named.values()):
        label += " (an inverted tet overlaps its neighbours)"
    fig.suptitle("Naive build of %d points (%s, shrunk): %d tets, %s\n(exact result: %d tets; "
                 "principal axes stretched to unit extent: thickness %.1e of the length)"
                 % (len(P), case["family"], len(tets), label, len(case["exact_tets"]), stretch[2] / stretch[0]), fontsize=10)
    save(fig, d, "fig_overlap.png")


# ---------------------------------------------------------------- benchmark

def fig_benchmark(d, res):
    rows = [r for r in res["summary"] if r["ok"]]
    dists = sorted(set(r["distribution"] for r in res["summary"]), key=lambda x: (x != "uniform", x))
    for name, key, ylabel, logy in [("fig_time.png", "median_s", "seconds (median)", True),
                                    ("fig_rate.png", "mpoints_per_s", "million points / s", False),
                                    ("fig_memory.png", "own_mb", "peak MB above the fork baseline", True)]:
        fig, axes = grid_axes(len(dists), ncols=4, size=3.6)
        for ax, dist in zip(axes, dists):
            for tool, (color, marker) in TOOL_STYLE.items():
                pts = sorted((r["n"], r[key], r["min_s"], r["max_s"]) for r in rows
                             if r["distribution"] == dist and r["tool"] == tool)
                if not pts:
                    continue
                xs = [p[0] for p in pts]
                ys = [p[1] for p in pts]
                if key == "median_s":
                    ax.errorbar(xs, ys, yerr=[[p[1] - p[2] for p in pts], [p[3] - p[1] for p in pts]],
                                color=color, marker=marker, label=tool, capsize=2)
                elif key == "mpoints_per_s":  # from the slowest and the fastest run
                    ax.errorbar(xs, ys, yerr=[[y - p[0] / p[3] / 1e6 for y, p in zip(ys, pts)],
                                              [p[0] / p[2] / 1e6 - y for y, p in zip(ys, pts)]],
                                color=color, marker=marker, label=tool, capsize=2)
                else:
                    ax.plot(xs, ys, color=color, marker=marker, label=tool)
            ax.set_xscale("log")
            if logy:
                ax.set_yscale("log")
            ax.set_title(dist, fontsize=10)
            ax.set_xlabel("n (points)")
            ax.set_ylabel(ylabel)
            ax.grid(alpha=0.3, which="both")
        axes[0].legend(fontsize=8)
        save(fig, d, name)

    pred = res["predicates"]
    fig, axes = plt.subplots(1, 2, figsize=(10, 3.8), sharey=True)
    backends = ["naive", "epsilon", "adaptive", "exact"]
    for ax, source in zip(axes, ["uniform", "near_degenerate"]):
        for j, p in enumerate(["orient3d", "insphere"]):
            ys = [next((r["ns_per_call"] for r in pred if r["points"] == source and r["backend"] == b
                        and r["predicate"] == p), 0) for b in backends]
            bars = ax.bar([i + (j - 0.5) * 0.4 for i in range(len(backends))], ys, width=0.4, label=p)
            for bar, y in zip(bars, ys):
                ax.text(bar.get_x() + bar.get_width() / 2, y, "%.0f" % y, ha="center", va="bottom", fontsize=7)
        ax.set_xticks(range(len(backends)))
        ax.set_xticklabels(backends)
        ax.set_yscale("log")
        ax.set_title("tuples from %s points" % source)
        ax.grid(alpha=0.3, axis="y")
    axes[0].set_ylabel("ns per call")
    axes[0].legend(fontsize=8)
    save(fig, d, "fig_predicates.png")


def main():
    d = sys.argv[1] if len(sys.argv) > 1 else "."
    res = json.load(open(os.path.join(d, "data", "results.json")))
    if res["experiment"] == "thesis-failures":
        fig_rates(d, res["rates"])
        fig_epsilon(d, res["epsilon"])
        fig_bigtet(d, res["bigtet"])
        fig_cost(d, res["cost"])
        fig_sampling(d, res["sampling"])
        fig_overlap(d, res["overlap_case"])
    elif res["experiment"] == "benchmark":
        fig_benchmark(d, res)
    else:
        sys.exit("unknown experiment " + str(res.get("experiment")))


if __name__ == "__main__":
    main()
