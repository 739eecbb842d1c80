#!/usr/bin/python3
"""Render a fracture OBJ (exploded.obj or pieces.obj) to a PNG, headless.

usage: /usr/bin/python3 fracture/render_pieces.py OUT/exploded.obj OUT/exploded.png [--elev 30] [--azim -60]

Each piece ("o piece_N") gets its own colour; cut faces (material "cut") are drawn
in a darker shade of it, lit by a fixed directional light. Needs matplotlib only.
"""
import argparse
import colorsys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402


def read_obj(path):
    verts, tris, piece, cut = [], [], [], []
    cur_piece, cur_cut = -1, False
    with open(path) as f:
        for line in f:
            if line.startswith("v "):
                verts.append([float(x) for x in line.split()[1:4]])
            elif line.startswith("o "):
                cur_piece += 1
            elif line.startswith("usemtl"):
                cur_cut = line.split()[1] == "cut"
            elif line.startswith("f "):
                idx = [int(t.split("/")[0]) - 1 for t in line.split()[1:]]
                for k in range(1, len(idx) - 1):
                    tris.append([idx[0], idx[k], idx[k + 1]])
                    piece.append(max(cur_piece, 0))
                    cut.append(cur_cut)
    return np.array(verts), np.array(tris, dtype=int), np.array(piece), np.array(cut)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("obj")
    ap.add_argument("png")
    ap.add_argument("--elev", type=float, default=30)
    ap.add_argument("--azim", type=float, default=-60)
    ap.add_argument("--size", type=float, default=8, help="figure size in inches")
    a = ap.parse_args()
    v, t, piece, cut = read_obj(a.obj)
    if len(t) == 0:
        raise SystemExit(f"{a.obj}: no faces")
    tri = v[t]
    n = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    n /= np.maximum(np.linalg.norm(n, axis=1, keepdims=True), 1e-300)
    light = np.array([0.4, -0.5, 0.77])
    light /= np.linalg.norm(light)
    shade = 0.35 + 0.65 * np.clip(n @ light, 0, 1)
    npieces = piece.max() + 1
    golden = 0.61803398875
    base = np.array([colorsys.hsv_to_rgb((i * golden) % 1, 0.45, 0.95) for i in range(npieces)])
    col = base[piece]
    col[cut] = col[cut] * 0.55 + np.array([0.45, 0.12, 0.05])
    col = np.clip(col * shade[:, None], 0, 1)
    fig = plt.figure(figsize=(a.size, a.size))
    ax = fig.add_subplot(111, projection="3d")
    ax.add_collection3d(Poly3DCollection(tri, facecolors=col, edgecolors="none"))
    lo, hi = v.min(axis=0), v.max(axis=0)
    c, r = (lo + hi) / 2, (hi - lo).max() / 2
    ax.set_xlim(c[0] - r, c[0] + r)
    ax.set_ylim(c[1] - r, c[1] + r)
    ax.set_zlim(c[2] - r, c[2] + r)
    ax.set_box_aspect((1, 1, 1))
    ax.view_init(elev=a.elev, azim=a.azim)
    ax.set_axis_off()
    ax.set_title(f"{npieces} pieces", fontsize=10)
    fig.savefig(a.png, dpi=120, bbox_inches="tight")


if __name__ == "__main__":
    main()
