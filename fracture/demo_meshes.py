#!/usr/bin/env python3
"""Fracture every mesh of a folder with --repair and tabulate the results.

    python3 fracture/demo_meshes.py DTLAB MESH_DIR [--pieces 20] [--seed 3] [--timeout 60]
                                    [--jobs 1] [--out table.md] [--only a.off,b.off]
                                    [--tolerance 1e-9] [--extra "--no-island-split"]

For each mesh: `dtlab mesh check --json` (the problems found), then
`dtlab fracture MESH --repair --pieces N --seed S --out TMP --json` under a wall-clock
timeout. The pieces are then checked here, independently of dtlab: pieces.obj is read,
every piece must be closed and edge-manifold (each directed edge once, its reverse
once), of positive volume, and the signed volumes of the pieces (divergence theorem, in
Python floats) must sum to the volume of repaired.off to --tolerance (relative). The
`islands` column counts pieces with more than one connected component of positive
volume (through shared edges; a shell of negative volume is a cavity inside its piece):
0 unless --extra --no-island-split. Prints a Markdown table and a tally.
"""
import argparse
import concurrent.futures
import json
import os
import subprocess
import sys
import tempfile
import time


def read_off(path):
    with open(path) as f:
        words = [w for line in f for w in line.split('#')[0].split()]
    assert words[0] == 'OFF'
    nv, nf = int(words[1]), int(words[2])
    pos = 4
    verts = [tuple(float(words[pos + 3 * i + k]) for k in range(3)) for i in range(nv)]
    pos += 3 * nv
    tris = []
    for _ in range(nf):
        n = int(words[pos])
        idx = [int(w) for w in words[pos + 1:pos + 1 + n]]
        pos += 1 + n
        tris += [(idx[0], idx[k], idx[k + 1]) for k in range(1, n - 1)]
    return verts, tris


def read_pieces(path):
    """pieces.obj -> list of (vertices, triangles), one per `o` object."""
    pieces, verts, base = [], [], 0
    for line in open(path):
        if line.startswith('o '):
            pieces.append((len(verts), []))
        elif line.startswith('v '):
            verts.append(tuple(float(w) for w in line.split()[1:4]))
        elif line.startswith('f '):
            pieces[-1][1].append(tuple(int(w.split('/')[0]) - 1 for w in line.split()[1:4]))
    return verts, [tris for _, tris in pieces]


def volume(verts, tris):
    o = verts[tris[0][0]] if tris else (0, 0, 0)
    v = 0.0
    for a, b, c in tris:
        ax, ay, az = (verts[a][k] - o[k] for k in range(3))
        bx, by, bz = (verts[b][k] - o[k] for k in range(3))
        cx, cy, cz = (verts[c][k] - o[k] for k in range(3))
        v += ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx)
    return v / 6


def closed_manifold(tris):
    edges = {}
    for t in tris:
        for k in range(3):
            e = (t[k], t[(k + 1) % 3])
            if e[0] == e[1] or e in edges:
                return False
            edges[e] = 1
    return bool(tris) and all((b, a) in edges for a, b in edges)


def components(verts, tris):
    """(shells, cavities): connected components of a triangle list through shared
    (undirected) edges, of positive and of negative signed volume."""
    parent = list(range(len(tris)))

    def find(x):
        while parent[x] != x:
            parent[x] = parent[parent[x]]
            x = parent[x]
        return x
    first = {}
    for i, t in enumerate(tris):
        for k in range(3):
            e = (min(t[k], t[(k + 1) % 3]), max(t[k], t[(k + 1) % 3]))
            if e in first:
                parent[find(i)] = find(first[e])
            else:
                first[e] = i
    comps = {}
    for i in range(len(tris)):
        comps.setdefault(find(i), []).append(tris[i])
    vols = [volume(verts, c) for c in comps.values()]
    return sum(v > 0 for v in vols), sum(v <= 0 for v in vols)


def short_problems(report):
    if 'triangles' not in report:  # an error object ({"error": ...}): the file was refused
        return 'unreadable'
    words = []
    if report['triangles'] == 0:
        words.append('no triangles')
    if report['boundary_edges']:
        words.append(f"{report['boundary_loops']} holes")
    if not report['manifold']:
        words.append(f"non-manifold ({report['nonmanifold_edges']} e, {report['nonmanifold_vertices']} v)")
    if report['misoriented_edges']:
        words.append(f"{report['misoriented_edges']} misoriented")
    if report['self_intersecting_pairs']:
        words.append(f"{report['self_intersecting_pairs']} self-int.")
    if report['degenerate_triangles']:
        words.append(f"{report['degenerate_triangles']} degenerate")
    if report['duplicate_vertices']:
        words.append(f"{report['duplicate_vertices']} dup. v")
    return ', '.join(words) or '-'


SHORT_STEP = {
    'merged duplicate vertices': 'merged',
    'dropped degenerate triangles': 'degen.',
    'dropped repeated triangles': 'repeated',
    'split non-manifold vertices and edges': 'split nm',
    'reversed triangles to orient consistently': 'oriented',
    'stitched border edges': 'stitched',
    'filled holes': 'holes',
    'collapsed degenerate triangles': 'collapsed',
    'resolved self-intersecting triangle pairs': 'self-int.',
    'separated pinched vertices': 'pinched',
    'dropped shells that enclose no volume': 'flat shells',
    'reversed triangles to bound a volume': 'outward',
}


def short_step(step):
    name = SHORT_STEP.get(step['step'], step['step'])
    if step['detail'].startswith('winding-number solid'):
        name = 'winding solid'  # self-intersections resolved by the winding-number solid
    return f"{name} {step['count']}"


def run_one(dtlab, mesh, args):
    name = os.path.basename(mesh)
    row = {'mesh': name, 'problems': '?', 'repairs': '', 'pieces': 0, 'error': None, 'seconds': 0.0,
           'ok': False, 'reason': '', 'multi': 0, 'sites': 0, 'cavities': 0, 'exact': False}
    try:
        check = subprocess.run([dtlab, 'mesh', 'check', mesh, '--json'], capture_output=True, text=True,
                               timeout=args.timeout)
        row['problems'] = short_problems(json.loads(check.stdout)) if check.stdout.strip() else 'unreadable'
    except (subprocess.TimeoutExpired, json.JSONDecodeError):
        row['problems'] = 'check failed'
    with tempfile.TemporaryDirectory() as tmp:
        t0 = time.time()
        try:
            p = subprocess.run([dtlab, 'fracture', mesh, '--repair', '--pieces', str(args.pieces), '--seed',
                                str(args.seed), '--out', tmp, '--json', '--threads', '1'] + args.extra.split(),
                               capture_output=True, text=True, timeout=args.timeout)
        except subprocess.TimeoutExpired:
            row['seconds'] = time.time() - t0
            row['reason'] = f'timeout ({args.timeout} s)'
            return row
        row['seconds'] = time.time() - t0
        if p.returncode != 0 or not os.path.exists(os.path.join(tmp, 'pieces.obj')):
            msg = (p.stderr.strip().splitlines() or ['exit %d' % p.returncode])[-1]
            row['reason'] = msg.split(': ', 2)[-1][:160]
            return row
        manifest = json.loads(p.stdout)
        row['repairs'] = ', '.join(short_step(s) for s in manifest['repairs']) or '-'
        # The exact tiling (exact piece volumes before rounding sum to the solid's exactly).
        row['exact'] = manifest.get('volume_identity', {}).get('exact_tiling', {}).get('holds', False)
        verts, pieces = read_pieces(os.path.join(tmp, 'pieces.obj'))
        rv, rt = read_off(os.path.join(tmp, 'repaired.off'))
        solid = volume(rv, rt)
        total = sum(volume(verts, t) for t in pieces)
        row['pieces'] = len(pieces)
        row['sites'] = len({p.get('site_index', i) for i, p in enumerate(manifest['pieces'])})
        shells = [components(verts, t) for t in pieces]
        row['multi'] = sum(s > 1 for s, _ in shells)
        row['cavities'] = sum(c for _, c in shells)
        row['error'] = abs(total - solid) / abs(solid) if solid else float('inf')
        bad = sum(not closed_manifold(t) for t in pieces)
        inside_out = sum(volume(verts, t) <= 0 for t in pieces)
        if bad:
            row['reason'] = f'{bad} pieces not closed/manifold'
        elif inside_out:
            row['reason'] = f'{inside_out} pieces of volume <= 0'
        elif row['error'] > args.tolerance:
            row['reason'] = f"volume error {row['error']:.1e}"
        else:
            row['ok'] = True
    return row


def write_table(lines, out):
    """The table's lines to stdout, and to the file `out` too when given."""
    text = '\n'.join(lines) + '\n'
    if out:
        open(out, 'w').write(text)
    sys.stdout.write(text)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('dtlab')
    ap.add_argument('mesh_dir')
    ap.add_argument('--pieces', type=int, default=20)
    ap.add_argument('--seed', type=int, default=3)
    ap.add_argument('--timeout', type=float, default=60)
    ap.add_argument('--jobs', type=int, default=1)
    ap.add_argument('--only', default='')
    ap.add_argument('--out', default='')
    ap.add_argument('--tolerance', type=float, default=1e-9)
    ap.add_argument('--extra', default='', help='more fracture options, e.g. "--no-island-split"')
    args = ap.parse_args()
    meshes = sorted(os.path.join(args.mesh_dir, f) for f in os.listdir(args.mesh_dir) if f.endswith('.off'))
    if args.only:
        keep = set(args.only.split(','))
        meshes = [m for m in meshes if os.path.basename(m) in keep]
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        rows = list(pool.map(lambda m: run_one(args.dtlab, m, args), meshes))
    lines = ['| mesh | problems found | repairs | sites | pieces | islands | volume error | exact | seconds | result |',
             '| --- | --- | --- | ---: | ---: | ---: | ---: | --- | ---: | --- |']
    for r in rows:
        err = '' if r['error'] is None else f"{r['error']:.1e}"
        lines.append(f"| {r['mesh']} | {r['problems']} | {r['repairs']} | {r['sites'] or ''} | {r['pieces'] or ''} | "
                     f"{r['multi'] if r['pieces'] else ''} | {err} | {('yes' if r['exact'] else 'no') if r['pieces'] else ''} | "
                     f"{r['seconds']:.1f} | {'fractured' if r['ok'] else r['reason']} |")
    ok = sum(r['ok'] for r in rows)
    slowest = max((r['seconds'] for r in rows), default=0)
    lines.append('')
    multi = sum(r['multi'] for r in rows)
    split = sum(r['pieces'] - r['sites'] for r in rows if r['ok'])
    cavities = sum(r['cavities'] for r in rows)
    exact = sum(r['exact'] for r in rows if r['ok'])
    lines.append(f"**{ok} of {len(rows)} fractured** into closed, manifold pieces of positive volume whose volumes "
                 f"sum to the repaired solid's ({args.tolerance:g}); {multi} pieces with more than one connected "
                 f"component; {split} pieces more than sites (islands); {cavities} cavity shells inside pieces; "
                 f"exact tiling proven on {exact} of the {ok}; slowest {slowest:.1f} s.")
    write_table(lines, args.out)


if __name__ == '__main__':
    main()
