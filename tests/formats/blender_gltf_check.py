"""Run inside Blender (tests/formats/test_gltf_blender.py): import a .glb
scaf wrote and compare its UV layers with the UVs the file holds.

argv after "--": the .glb, then a JSON file {"loops": total triangle
corners, "uvs": {mesh name: sorted [u, v] of TEXCOORD_0 per corner, v
already flipped as Blender flips it}}. Exits 1 (via --python-exit-code)
on the first difference."""
import json
import sys

import bpy

args = sys.argv[sys.argv.index("--") + 1:]
path, expected = args[0], json.load(open(args[1]))
before = set(bpy.data.meshes)  # the startup scene's cube
# import_shading SMOOTH: Debian's Blender 3.4 guesses flat faces (the
# default, NORMALS) with numpy's np.bool, which Debian's numpy 1.24 removed
bpy.ops.import_scene.gltf(filepath=path, import_shading="SMOOTH")
total = 0
for me in [m for m in bpy.data.meshes if m not in before]:
    loops = len(me.loops)
    total += loops
    if not me.uv_layers:
        raise SystemExit("mesh %s has no UV layer" % me.name)
    uv = me.uv_layers[0]
    if len(uv.data) != loops:
        raise SystemExit("mesh %s: %d UVs for %d loops" % (me.name, len(uv.data), loops))
    got = sorted([round(d.uv[0], 5), round(d.uv[1], 5)] for d in uv.data)
    want = sorted([round(u, 5), round(v, 5)] for u, v in expected["uvs"][me.name])
    if got != want:
        raise SystemExit("mesh %s: the UV layer differs from the file's TEXCOORD_0" % me.name)
if total != expected["loops"]:
    raise SystemExit("%d loops imported, the file has %d triangle corners" % (total, expected["loops"]))
print("blender_gltf_check: ok, %d loops" % total)
