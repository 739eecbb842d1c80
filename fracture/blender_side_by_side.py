#!/usr/bin/env python3
"""dtlab fracture next to Blender's Cell Fracture add-on, on the same mesh and sites.

    python3 fracture/blender_side_by_side.py DTLAB MESH_DIR [--meshes cube,elephant,bunny00,knot1]
                                             [--pieces 20,100] [--seed 3] [--rounds 1]
                                             [--dtlab-args "--threads 1"] [--out table.md]

Per mesh and piece count: `dtlab fracture MESH.off --pieces N --seed S --out TMP --json`
(its whole run timed), its sites (one per site_index of the manifest) written to an
.xyz, then `blender -b --factory-startup -P fracture/blender_cell_fracture.py` on the
same mesh and sites (child vertices, islands split, margin 0; its whole run timed, and
the add-on's operator alone). Pieces are checked here for dtlab (pieces.obj: closed and
edge-manifold, volumes in Python floats) and inside Blender for Blender (bmesh: edges
in two faces, manifold edges and vertices, as they come and after merging vertices
within 1e-6 of the mesh size). Volume error: |sum of piece volumes - mesh volume| /
mesh volume. Without blender on PATH the Blender rows say so and the dtlab rows remain.
With --rounds R each pair runs R times alternated (dtlab, Blender, dtlab, Blender, ...):
the times are the median with [min - max], the ratio the median of the per-round ratios
with its spread, and the load average (1 min) is read before every run.
"""
import argparse
import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from demo_meshes import closed_manifold, read_off, read_pieces, volume, write_table  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))


def run_dtlab(dtlab, mesh, n, seed, tmp, extra=()):
    t0 = time.time()
    p = subprocess.run([dtlab, 'fracture', mesh, '--pieces', str(n), '--seed', str(seed), '--out', tmp, '--json',
                        '--quiet', *extra], capture_output=True, text=True)
    seconds = time.time() - t0
    if p.returncode != 0:
        raise RuntimeError(f'dtlab fracture {mesh}: {p.stderr.strip()}')
    manifest = json.loads(p.stdout)
    verts, pieces = read_pieces(os.path.join(tmp, 'pieces.obj'))
    mv, mt = read_off(mesh)
    solid = volume(mv, mt)
    ok = sum(closed_manifold(t) for t in pieces)
    err = abs(sum(volume(verts, t) for t in pieces) - solid) / solid
    sites = {}
    for q in manifest['pieces']:
        sites[q['site_index']] = q['site']
    return {'pieces': len(pieces), 'ok': ok, 'ok_welded': ok, 'error': err, 'error_welded': err,
            'seconds': seconds, 'op_seconds': sum(manifest['seconds'].values())}, list(sites.values())


def run_blender(mesh, sites, tmp):
    xyz, out = os.path.join(tmp, 'sites.xyz'), os.path.join(tmp, 'blender.json')
    with open(xyz, 'w') as f:
        f.writelines('%r %r %r\n' % tuple(s) for s in sites)
    t0 = time.time()
    p = subprocess.run(['blender', '-b', '--factory-startup', '--python-exit-code', '1', '-P',
                        os.path.join(HERE, 'blender_cell_fracture.py'), '--', mesh, xyz, out, '0'],
                       capture_output=True, text=True)
    seconds = time.time() - t0
    if p.returncode != 0 or not os.path.exists(out):
        raise RuntimeError(f'blender on {mesh}: exit {p.returncode}: {p.stdout[-400:]}')
    b = json.load(open(out))
    P, v = b['pieces'], b['mesh_volume']
    return {'pieces': len(P), 'ok': sum(q['closed'] and q['manifold'] for q in P),
            'ok_welded': sum(q['welded_closed'] and q['welded_manifold'] for q in P),
            'error': abs(sum(q['volume'] for q in P) - v) / v,
            'error_welded': abs(sum(q['welded_volume'] for q in P) - v) / v,
            'seconds': seconds, 'op_seconds': b['seconds']}


def spread(values, fmt):
    """median [min - max] of the rounds (the value alone for one round)."""
    if len(values) == 1:
        return fmt % values[0]
    return f"{fmt % statistics.median(values)} [{fmt % min(values)} - {fmt % max(values)}]"


def measure_pair(args, mesh, n, have_blender):
    """R alternated rounds of dtlab and Blender on the same sites: per tool the first
    round's checks and every round's times, with the load average before each run."""
    runs = {'dtlab': [], 'Blender Cell Fracture': []}
    loads = []
    for _ in range(args.rounds):
        with tempfile.TemporaryDirectory() as tmp:
            loads.append(os.getloadavg()[0])
            d, sites = run_dtlab(args.dtlab, mesh, n, args.seed, tmp, args.dtlab_args.split())
            runs['dtlab'].append(d)
            if have_blender:
                loads.append(os.getloadavg()[0])
                runs['Blender Cell Fracture'].append(run_blender(mesh, sites, tmp))
    return runs, sites, loads


def table_rows(name, sites, runs, loads):
    d, b = runs['dtlab'], runs['Blender Cell Fracture']
    ratios = [x['seconds'] / y['seconds'] for x, y in zip(d, b)]
    load = spread(loads, '%.1f')
    rows = []
    for tool, rs in runs.items():
        if not rs:
            rows.append(f'| {name} | {len(sites)} | {tool} | not run: blender is not installed | | | | | | |')
            continue
        r = rs[0]
        ratio = spread(ratios, '%.2f') if ratios and tool == 'dtlab' else ''
        rows.append(f"| {name} | {len(sites)} | {tool} | {r['pieces']} | {r['ok']} ({r['ok_welded']}) | "
                    f"{r['error']:.1e} ({r['error_welded']:.1e}) | {spread([x['seconds'] for x in rs], '%.2f')} | "
                    f"{spread([x['op_seconds'] for x in rs], '%.2f')} | {ratio} | {load if tool == 'dtlab' else ''} |")
    return rows


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('dtlab')
    ap.add_argument('mesh_dir')
    ap.add_argument('--meshes', default='cube,elephant,bunny00,knot1')
    ap.add_argument('--pieces', default='20,100')
    ap.add_argument('--seed', type=int, default=3)
    ap.add_argument('--rounds', type=int, default=1)
    ap.add_argument('--dtlab-args', default='', help='more options for dtlab fracture, e.g. "--threads 1"')
    ap.add_argument('--out', default='')
    args = ap.parse_args()
    have_blender = shutil.which('blender') is not None
    lines = ['| mesh | sites | tool | pieces | closed & manifold (welded) | volume error (welded) | whole run s | '
             'fracture s | dtlab / Blender whole run | load average |',
             '| --- | ---: | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |']
    for name in args.meshes.split(','):
        mesh = os.path.join(args.mesh_dir, name + '.off')
        for n in (int(x) for x in args.pieces.split(',')):
            runs, sites, loads = measure_pair(args, mesh, n, have_blender)
            rows = table_rows(name, sites, runs, loads)
            lines += rows
            print('\n'.join(rows), file=sys.stderr, flush=True)
    write_table(lines, args.out)


if __name__ == '__main__':
    main()
