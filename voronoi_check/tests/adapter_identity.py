# The scipy-voronoi / qvoronoi adapter (voronoi_check/voronoi_peer.py) against a frozen
# copy of the adapter before its array rewrite (voronoi_peer_reference.py, main c6e3e29):
# the cells files must be the same bytes, the tool's seconds (bytes 4..11) left out.
#   adapter_identity.py [--sizes 1000,10000] [--families uniform,...] [--peers scipy,qvoronoi]
# Each family at each size in three boxes: the sites' box grown by 0.1 of its extent (the
# peers' default), the sites' box itself (many cells cut by the walls) and its middle 60%
# (sites outside the box, cells left out). Exit 0 when every pair is the same, 1 otherwise.
# ctest `voronoi_peer_adapter_identity` runs it at 500 sites; voronoi_check/README.md has
# the runs at 10^3-10^5.
import argparse, os, shutil, struct, subprocess, sys, tempfile, time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
NEW = os.path.join(HERE, "..", "voronoi_peer.py")
OLD = os.path.join(HERE, "voronoi_peer_reference.py")


def sites(family, n, seed):
    rng = np.random.default_rng(seed)
    k = max(2, round(n ** (1 / 3)))
    grid = np.stack(np.meshgrid(*[np.arange(k, dtype=float)] * 3, indexing="ij"), axis=-1).reshape(-1, 3) / k
    if family == "uniform":
        return rng.random((n, 3))
    if family == "lattice":
        return grid
    if family == "jittered_lattice":
        return grid + rng.uniform(-1e-4, 1e-4, grid.shape) / k
    if family == "sphere":
        g = rng.normal(size=(n, 3))
        return g / np.linalg.norm(g, axis=1)[:, None]
    if family == "cospherical":  # a sphere of sites with a uniform cloud inside
        g = rng.normal(size=(n // 2, 3))
        return np.concatenate([g / np.linalg.norm(g, axis=1)[:, None], rng.uniform(-0.5, 0.5, (n - n // 2, 3))])
    if family == "duplicates":
        p = rng.random((n - n // 10, 3))
        return np.concatenate([p, p[rng.integers(0, len(p), n // 10)]])[rng.permutation(n)]
    if family == "clustered":
        centres = rng.random((20, 3))
        return centres[rng.integers(0, 20, n)] + rng.normal(scale=0.01, size=(n, 3))
    raise ValueError(family)


def boxes(p):
    lo, hi = p.min(axis=0), p.max(axis=0)
    ext = hi - lo
    return {"margin0.1": (lo - 0.1 * ext, hi + 0.1 * ext), "tight": (lo, hi), "middle": (lo + 0.2 * ext, hi - 0.2 * ext)}


def run(script, peer, node, out, box):
    t = time.perf_counter()
    r = subprocess.run([sys.executable, script, peer, node, out] + ["%r" % float(x) for x in box],
                       capture_output=True, text=True)
    return r.returncode, r.stderr.strip().splitlines()[-1:] if r.returncode else [], time.perf_counter() - t


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--sizes", default="1000")
    ap.add_argument("--families", default="uniform,lattice,jittered_lattice,sphere,cospherical,duplicates,clustered")
    ap.add_argument("--peers", default="scipy,qvoronoi")
    ap.add_argument("--boxes", default="margin0.1,tight,middle")
    ap.add_argument("--seed", type=int, default=1)
    a = ap.parse_args()
    peers = [x for x in a.peers.split(",") if (x == "qvoronoi" and shutil.which("qvoronoi"))
             or (x == "scipy" and subprocess.run([sys.executable, "-c", "import scipy.spatial"]).returncode == 0)]
    if not peers:
        print("neither scipy nor qvoronoi is installed"); return 77
    bad = 0
    with tempfile.TemporaryDirectory() as d:
        for n in [int(x) for x in a.sizes.split(",")]:
            for fam in a.families.split(","):
                p = np.ascontiguousarray(sites(fam, n, a.seed), dtype="<f8")
                node = os.path.join(d, "in.bin")
                with open(node, "wb") as f:
                    f.write(b"DTLP" + struct.pack("<Q", len(p)) + p.tobytes())
                for bname, (lo, hi) in boxes(p).items():
                    if bname not in a.boxes.split(","):
                        continue
                    for peer in peers:
                        res = []
                        for script, tag in ((OLD, "old"), (NEW, "new")):
                            out = os.path.join(d, tag + ".cells")
                            if os.path.exists(out):
                                os.remove(out)
                            rc, err, sec = run(script, peer, node, out, list(lo) + list(hi))
                            data = open(out, "rb").read() if rc == 0 and os.path.exists(out) else b""
                            res.append((rc, err, data[:4] + data[12:], sec))
                        same = res[0][0] == res[1][0] and res[0][2] == res[1][2]
                        cells = struct.unpack("<Q", res[1][2][4:12])[0] if len(res[1][2]) >= 12 else 0
                        print("%-6s n=%-7d %-16s %-9s %-8s cells %-7d %s  old %.2f s (rc %d) new %.2f s (rc %d)%s"
                              % ("same" if same else "DIFFER", len(p), fam, bname, peer, cells,
                                 "%d bytes" % len(res[1][2]), res[0][3], res[0][0], res[1][3], res[1][0],
                                 "" if same else " " + repr(res[0][1] + res[1][1])), flush=True)
                        bad += not same
    print("%d differ" % bad)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
