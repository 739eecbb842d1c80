# Runs inside Blender (blender_side_by_side.py starts it):
#   blender -b --factory-startup --python-exit-code 1 -P fracture/blender_cell_fracture.py -- \
#       MESH.off SITES.xyz OUT.json [MARGIN]
# Builds the OFF mesh as an object, the sites as a child object's vertices, runs the Cell
# Fracture add-on (object_fracture_cell, source = child vertices, islands split) and
# writes per piece: closed (every edge in two faces), manifold (edges and vertices),
# signed volume, as the piece comes and after merging vertices within 1e-6 of the
# mesh's size; the operator's seconds and the mesh's volume.
import json
import sys
import time

import bmesh
import bpy


def read_off(path):
    words = [w for line in open(path) for w in line.split('#')[0].split()]
    nv, nf = int(words[1]), int(words[2])
    pos = 4
    verts = [tuple(float(words[pos + 3 * i + k]) for k in range(3)) for i in range(nv)]
    pos += 3 * nv
    faces = []
    for _ in range(nf):
        n = int(words[pos])
        faces.append([int(w) for w in words[pos + 1:pos + 1 + n]])
        pos += 1 + n
    return verts, faces


def measure(obj, weld=0.0):
    """Closed / manifold / volume as the piece comes, and after welding vertices
    closer than `weld` (Blender's Merge by Distance)."""
    bm = bmesh.new()
    bm.from_mesh(obj.data)
    bm.transform(obj.matrix_world)
    out = {}
    for key, dist in (("", 0.0), ("welded_", weld)):
        if dist > 0:
            bmesh.ops.remove_doubles(bm, verts=bm.verts[:], dist=dist)
        closed = all(len(e.link_faces) == 2 for e in bm.edges)
        out[key + "closed"] = closed
        out[key + "manifold"] = closed and all(e.is_manifold for e in bm.edges) and all(v.is_manifold for v in bm.verts)
        out[key + "volume"] = bm.calc_volume(signed=True)
    bm.free()
    return out


def main():
    mesh_path, sites_path, out_path = sys.argv[sys.argv.index("--") + 1:][:3]
    rest = sys.argv[sys.argv.index("--") + 4:]
    margin = float(rest[0]) if rest else 0.0
    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.ops.preferences.addon_enable(module="object_fracture_cell")
    verts, faces = read_off(mesh_path)
    me = bpy.data.meshes.new("input")
    me.from_pydata(verts, [], faces)
    obj = bpy.data.objects.new("input", me)
    bpy.context.scene.collection.objects.link(obj)
    sites = [tuple(float(w) for w in line.split()[:3]) for line in open(sites_path) if line.strip()]
    sm = bpy.data.meshes.new("sites")
    sm.from_pydata(sites, [], [])
    so = bpy.data.objects.new("sites", sm)
    bpy.context.scene.collection.objects.link(so)
    so.parent = obj
    mesh_volume = measure(obj)["volume"]
    bpy.context.view_layer.objects.active = obj
    obj.select_set(True)
    before = set(bpy.data.objects)
    t0 = time.perf_counter()
    bpy.ops.object.add_fracture_cell_objects(source={'VERT_CHILD'}, source_limit=0, source_noise=0.0,
                                             margin=margin, use_island_split=True, recursion=0,
                                             use_remove_original=False, use_debug_redraw=False)
    seconds = time.perf_counter() - t0
    diag = max((max(v[k] for v in verts) - min(v[k] for v in verts)) for k in range(3))
    pieces = [measure(o, 1e-6 * diag) for o in bpy.data.objects if o not in before and o.type == 'MESH']
    json.dump({"seconds": seconds, "mesh_volume": mesh_volume, "sites": len(sites), "pieces": pieces},
              open(out_path, "w"))


main()
