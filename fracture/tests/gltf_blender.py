# Loads a dtlab fracture glTF in Blender and checks what arrived:
#   blender -b --factory-startup -P fracture/tests/gltf_blender.py -- OUT_DIR
# One mesh object per piece (named piece_i), both materials, every piece's volume
# (bmesh, float32 positions) within 1e-5 of (its volume + 1e-2 of the mesh's). Exit 0 ok, 1 otherwise.
import json
import os
import sys

import bmesh
import bpy
import numpy

# Debian's Blender 3.4 glTF importer uses numpy.bool, which numpy 1.24 removed; the
# alias it meant is the builtin (Blender's bug, not the file's).
if not hasattr(numpy, "bool"):
    numpy.bool = bool

out = sys.argv[sys.argv.index("--") + 1]
manifest = json.load(open(os.path.join(out, "manifest.json")))
bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.ops.import_scene.gltf(filepath=os.path.join(out, "pieces.gltf"))
objs = {o.name: o for o in bpy.context.scene.objects if o.type == "MESH"}
fails = []
if len(objs) != len(manifest["pieces"]):
    fails.append(f"{len(objs)} mesh objects for {len(manifest['pieces'])} pieces")
materials = {m.name for o in objs.values() for m in o.data.materials}
if not {"outer", "cut"} <= materials:
    fails.append(f"materials {sorted(materials)}")
worst = 0.0
for i, p in enumerate(manifest["pieces"]):
    o = objs.get(f"piece_{i}")
    if o is None:
        fails.append(f"no object piece_{i}")
        continue
    bm = bmesh.new()
    bm.from_mesh(o.data)
    bm.transform(o.matrix_world)  # the importer turns glTF's +Y up into Blender's +Z up
    v = bm.calc_volume(signed=True)
    bm.free()
    # float32 positions: relative to the piece, plus 1e-7 of the mesh for slivers
    worst = max(worst, abs(v - p["volume"]) / (abs(p["volume"]) + 1e-2 * manifest["mesh_volume"]))
if worst > 1e-5:
    fails.append(f"worst relative volume error {worst:.2e}")
print(f"blender: {len(objs)} pieces imported, materials {sorted(materials)}, worst relative volume error {worst:.2e}")
for f in fails:
    print("FAIL:", f)
sys.exit(1 if fails else 0)
