#!/usr/bin/env python3
"""Checks a `dtlab fracture --gltf` output against the glTF 2.0 rules it relies on.

    python3 fracture/tests/gltf_structure.py OUT_DIR

asset 2.0; one scene whose nodes are the pieces, one node and mesh per piece (named
piece_i); materials outer and cut; every primitive in triangles (mode 4) with material
0 (mesh surface) or 1 (cut faces), the cut primitive holding the manifest's
cut_triangles; accessors inside their buffer views, views inside the buffer (4-byte
aligned), POSITION min/max right, indices below the vertex count; each piece's
volume from the float32 positions within 1e-5 of the manifest's (plus 1e-7 of the
mesh volume: float32 on slivers), and each piece
closed (every directed edge's reverse present). Exit 0 ok, 1 with the failures.
"""
import base64
import json
import os
import struct
import sys


def main():
    out = sys.argv[1]
    g = json.load(open(os.path.join(out, "pieces.gltf")))
    manifest = json.load(open(os.path.join(out, "manifest.json")))
    pieces = manifest["pieces"]
    fails = []

    def need(cond, what):
        if not cond:
            fails.append(what)

    need(g["asset"]["version"] == "2.0", "asset.version")
    need(g["scenes"][g["scene"]]["nodes"] == list(range(len(pieces))), "scene nodes")
    need(len(g["nodes"]) == len(pieces) and len(g["meshes"]) == len(pieces), "a node and a mesh per piece")
    need([m["name"] for m in g["materials"]] == ["outer", "cut"], "materials")
    uri = g["buffers"][0]["uri"]
    prefix = "data:application/octet-stream;base64,"
    need(uri.startswith(prefix), "embedded buffer")
    data = base64.b64decode(uri[len(prefix):])
    need(len(data) == g["buffers"][0]["byteLength"], "buffer byteLength")

    def values(acc_id):
        acc = g["accessors"][acc_id]
        view = g["bufferViews"][acc["bufferView"]]
        need(view["byteOffset"] % 4 == 0 and view["byteOffset"] + view["byteLength"] <= len(data), "view bounds")
        width = {"VEC3": 3, "SCALAR": 1}[acc["type"]]
        fmt = {5126: "f", 5125: "I"}[acc["componentType"]]
        need(acc["count"] * width * 4 <= view["byteLength"], "accessor bounds")
        flat = struct.unpack_from("<%d%s" % (acc["count"] * width, fmt), data, view["byteOffset"])
        return [flat[i:i + width] for i in range(0, len(flat), width)] if width > 1 else list(flat)

    for i, (node, mesh) in enumerate(zip(g["nodes"], g["meshes"])):
        need(node["name"] == f"piece_{i}" and node["mesh"] == i, f"node {i}")
        tris, cut = [], 0
        pos_id = mesh["primitives"][0]["attributes"]["POSITION"]
        pos = values(pos_id)
        acc = g["accessors"][pos_id]
        for k in range(3):
            need(abs(acc["min"][k] - min(p[k] for p in pos)) == 0, f"piece {i} POSITION min")
            need(abs(acc["max"][k] - max(p[k] for p in pos)) == 0, f"piece {i} POSITION max")
        for prim in mesh["primitives"]:
            need(prim["mode"] == 4 and prim["material"] in (0, 1), f"piece {i} primitive")
            need(prim["attributes"]["POSITION"] == pos_id, f"piece {i} shared positions")
            idx = values(prim["indices"])
            need(len(idx) % 3 == 0 and max(idx) < len(pos), f"piece {i} indices")
            t = [tuple(idx[k:k + 3]) for k in range(0, len(idx), 3)]
            cut += len(t) if prim["material"] == 1 else 0
            tris += t
        need(cut == pieces[i]["cut_triangles"], f"piece {i}: {cut} cut triangles, manifest {pieces[i]['cut_triangles']}")
        edges = {(t[k], t[(k + 1) % 3]) for t in tris for k in range(3)}
        need(all((b, a) in edges for a, b in edges), f"piece {i} not closed")
        vol = 0.0
        for a, b, c in tris:
            pa, pb, pc = pos[a], pos[b], pos[c]
            vol += (pa[0] * (pb[1] * pc[2] - pb[2] * pc[1]) - pa[1] * (pb[0] * pc[2] - pb[2] * pc[0]) +
                    pa[2] * (pb[0] * pc[1] - pb[1] * pc[0])) / 6
        need(abs(vol - pieces[i]["volume"]) <= 1e-5 * abs(pieces[i]["volume"]) + 1e-7 * manifest["mesh_volume"],
             f"piece {i}: volume {vol} vs manifest {pieces[i]['volume']}")
    print(f"gltf: {len(g['nodes'])} nodes, {len(g['accessors'])} accessors, {len(data)} bytes, "
          f"{len(fails)} failures")
    for f in fails[:20]:
        print("FAIL:", f)
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
