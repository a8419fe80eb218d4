"""tests/blender/test_addon.py: the scaf UV add-on in Blender, headless.

Run by run_blender_test.sh inside `blender -b --factory-startup
--python-exit-code 1 --python test_addon.py -- ZIP SCAF_PROGRAM WORK`:
installs the add-on from its zip (into the scratch BLENDER_USER_SCRIPTS),
enables it, and on a UV sphere with marked seams (a meridian and the
equator: two hemispheres; quads and pole triangles) runs Bijective
Unwrap (edit mode) and Bijective Pack (object mode, from bijective and
from mirrored UVs), each written map checked by the build's `scaf check
--json` on an OBJ written here (bijective, min_chart_gap >= the padding);
vertex count, positions, a second UV map and a custom attribute
unchanged; Ctrl-Z (ed.undo) restores the previous UVs; Check selects
a face made flipped (and the neighbours it touches only), and faces of both of two islands moved
onto each other; Esc's flag cancels a run. Any failed
assertion exits 1 (--python-exit-code).
"""

import json
import os
import subprocess
import sys
import traceback

import bpy
import numpy as np

ZIP, SCAF, WORK = sys.argv[sys.argv.index("--") + 1:][:3]


def fail(msg):
    raise AssertionError(msg)


def uvs(me, name=None):
    layer = me.uv_layers[name] if name else me.uv_layers.active
    a = np.empty(len(me.loops) * 2, np.float32)
    layer.data.foreach_get("uv", a)
    return a.reshape(-1, 2)


def write_obj(me, path):
    """Triangles with v and vt; one vt per (vertex, exact UV) as any OBJ
    export of a UV map; every number printed with repr (exact)."""
    me.calc_loop_triangles()
    tl = np.empty(len(me.loop_triangles) * 3, np.int32)
    me.loop_triangles.foreach_get("loops", tl)
    lv = np.empty(len(me.loops), np.int32)
    me.loops.foreach_get("vertex_index", lv)
    uv = uvs(me)
    key = np.column_stack([lv, uv.view(np.uint32)]).astype(np.int64)
    _, first, vt = np.unique(key, axis=0, return_index=True, return_inverse=True)
    vt = vt.reshape(-1)
    with open(path, "w") as out:
        for v in me.vertices:
            out.write("v %r %r %r\n" % tuple(float(x) for x in v.co))
        for u, v in uv[first].tolist():
            out.write("vt %r %r\n" % (u, v))
        for t in tl.reshape(-1, 3).tolist():
            out.write("f %s\n" % " ".join("%d/%d" % (lv[c] + 1, vt[c] + 1) for c in t))


def scaf_check(obj, tag):
    path = os.path.join(WORK, tag + ".obj")
    write_obj(obj.data, path)
    p = subprocess.run([SCAF, "check", "--json", path], capture_output=True, text=True)
    if p.returncode not in (0, 1):
        fail("%s: scaf check exit %d: %s" % (tag, p.returncode, p.stderr))
    return json.loads(p.stdout)


def snapshot(me):
    co = np.empty(len(me.vertices) * 3)
    me.vertices.foreach_get("co", co)
    w = np.empty(len(me.vertices), np.float32)
    me.attributes["scaf_test_weight"].data.foreach_get("value", w)
    return {"nv": len(me.vertices), "nl": len(me.loops), "co": co, "second": uvs(me, "second"),
            "weight": w}


def same_attributes(before, me, tag):
    now = snapshot(me)
    for k in before:
        if not np.array_equal(np.asarray(before[k]), np.asarray(now[k])):
            fail("%s changed %s" % (tag, k))


def make_sphere():
    bpy.ops.mesh.primitive_uv_sphere_add(segments=16, ring_count=8, radius=1.0)
    obj = bpy.context.active_object
    me = obj.data
    for e in me.edges:  # the meridian x = 0, y > 0 (pole to pole) and the equator
        a, b = (me.vertices[i].co for i in e.vertices)
        meridian = abs(a.x) < 1e-6 and abs(b.x) < 1e-6 and a.y >= -1e-6 and b.y >= -1e-6
        equator = abs(a.z) < 1e-6 and abs(b.z) < 1e-6
        e.use_seam = meridian or equator
    first = me.uv_layers.active.name
    second = me.uv_layers.new(name="second")
    vals = np.arange(len(me.loops) * 2, dtype=np.float32) / 7.0
    second.data.foreach_set("uv", vals)
    me.uv_layers.active = me.uv_layers[first]
    attr = me.attributes.new("scaf_test_weight", "FLOAT", "POINT")
    attr.data.foreach_set("value", np.arange(len(me.vertices), dtype=np.float32) * 0.5)
    return obj


def main():
    bpy.ops.preferences.addon_install(filepath=ZIP)
    bpy.ops.preferences.addon_enable(module="scaf_uv")
    import scaf_uv
    from scaf_uv import library, operators
    user = os.environ["BLENDER_USER_SCRIPTS"]
    if not os.path.realpath(scaf_uv.__file__).startswith(os.path.realpath(user)):
        fail("scaf_uv imported from %s, not from the installed zip in %s" % (scaf_uv.__file__, user))
    scaf = library.load(bpy.context)
    print("scaf", scaf.__version__, "from", scaf.library_path)

    bpy.ops.object.select_all(action="DESELECT")
    for o in list(bpy.data.objects):
        bpy.data.objects.remove(o)
    obj = make_sphere()
    me = obj.data
    before = snapshot(me)
    uv_before = uvs(me).copy()

    # -- unwrap in edit mode (where the UV editor is), then undo
    # Operators called from a script push no undo step of their own (the
    # UI pushes one after each REGISTER + UNDO operator): the test pushes
    # them around the call as the UI would.
    for op in (operators.SCAF_OT_bijective_unwrap, operators.SCAF_OT_bijective_pack,
               operators.SCAF_OT_check):
        if op.bl_options != {"REGISTER", "UNDO"}:
            fail("%s: bl_options %s" % (op.bl_idname, op.bl_options))
    bpy.ops.object.mode_set(mode="EDIT")
    bpy.ops.ed.undo_push(message="before unwrap")
    r = bpy.ops.uv.scaf_bijective_unwrap(resolution=256, padding_texels=4)
    if r != {"FINISHED"}:
        fail("unwrap: %s" % r)
    bpy.ops.ed.undo_push(message="Bijective Unwrap")
    bpy.ops.object.mode_set(mode="OBJECT")
    rep = scaf_check(obj, "unwrap")
    print("unwrap:", rep)
    if not rep["bijective"] or rep["charts"] != 2 or not rep["min_chart_gap"] >= 4 / 256:
        fail("unwrap: not bijective with 2 charts and gap >= 4/256: %s" % rep)
    same_attributes(before, me, "unwrap")
    uv_unwrapped = uvs(me).copy()
    if np.array_equal(uv_unwrapped, uv_before):
        fail("unwrap left the UVs as they were")

    bpy.ops.object.mode_set(mode="EDIT")
    bpy.ops.ed.undo()
    bpy.ops.object.mode_set(mode="OBJECT")
    me = obj.data
    if not np.array_equal(uvs(me), uv_before):
        fail("undo did not restore the UVs before the unwrap")
    print("undo: UVs restored")
    me = obj.data

    # -- pack in object mode from the (bijective) unwrapped layout
    me.uv_layers.active.data.foreach_set("uv", uv_unwrapped.reshape(-1))
    r = bpy.ops.uv.scaf_bijective_pack(resolution=256, padding_texels=8)
    rep = scaf_check(obj, "pack")
    print("pack:", rep)
    if r != {"FINISHED"} or not rep["bijective"] or not rep["min_chart_gap"] >= 8 / 256:
        fail("pack: %s %s" % (r, rep))
    same_attributes(before, me, "pack")

    # -- pack from a mirrored island (not bijective): a fresh layout, no mirrored island
    uv = uvs(me).copy()
    lv_poly = np.repeat(np.arange(len(me.polygons)), [p.loop_total for p in me.polygons])
    north = np.array([me.polygons[p].center.z > 0 for p in lv_poly])
    uv[north, 0] = -uv[north, 0]
    me.uv_layers.active.data.foreach_set("uv", uv.reshape(-1))
    if scaf_check(obj, "mirrored")["mirrored_charts"] != 1:
        fail("the test's mirrored island is not one mirrored chart")
    r = bpy.ops.uv.scaf_bijective_pack(resolution=256, padding_texels=8)
    rep = scaf_check(obj, "pack_mirrored")
    print("pack from mirrored:", rep)
    if r != {"FINISHED"} or not rep["bijective"] or rep["mirrored_charts"] != 0 \
            or not rep["min_chart_gap"] >= 8 / 256:
        fail("pack from a mirrored island: %s %s" % (r, rep))
    same_attributes(before, me, "pack from mirrored")

    # -- check: a bijective map selects nothing; one flipped face is selected alone
    bpy.ops.object.mode_set(mode="EDIT")
    r = bpy.ops.uv.scaf_check()
    bpy.ops.object.mode_set(mode="OBJECT")
    if any(p.select for p in me.polygons):
        fail("check selected faces of a bijective map")
    # a pole triangle: swap two corners' UVs (plain values: polygon
    # references dangle once the mode changes)
    tri = next(p for p in me.polygons if p.loop_total == 3)
    tri_index, tri_verts, a = tri.index, set(tri.vertices), tri.loop_start
    b = a + 1
    del tri
    uv = uvs(me).copy()
    uv[[a, b]] = uv[[b, a]]
    me.uv_layers.active.data.foreach_set("uv", uv.reshape(-1))
    bpy.ops.object.mode_set(mode="EDIT")
    bpy.ops.uv.scaf_check()
    bpy.ops.object.mode_set(mode="OBJECT")
    selected = [p.index for p in me.polygons if p.select]
    # the swapped corners also make the face's UV edges boundaries touching
    # its neighbours' (scaf check counts boundary_touchings): those are selected too
    near = [p.index for p in me.polygons if set(p.vertices) & tri_verts]
    if tri_index not in selected or not set(selected) <= set(near):
        fail("check selected %s, expected the flipped face %d and some of its neighbours %s"
             % (selected, tri_index, near))
    if scaf_check(obj, "flipped")["flipped"] < 1:
        fail("the test's flipped face is not flipped")
    print("check: selected", selected)
    # two islands moved onto each other (no flipped triangle): faces of both are selected
    uv[[a, b]] = uv[[b, a]]
    uv[north] += uv[~north].mean(axis=0) - uv[north].mean(axis=0)
    me.uv_layers.active.data.foreach_set("uv", uv.reshape(-1))
    rep = scaf_check(obj, "overlap")
    if rep["flipped"] != 0 or rep["boundary_crossings"] < 1:
        fail("the test's overlapping islands: %s" % rep)
    bpy.ops.object.mode_set(mode="EDIT")
    bpy.ops.uv.scaf_check()
    bpy.ops.object.mode_set(mode="OBJECT")
    sel = np.array([p.select for p in me.polygons])
    pole_north = np.array([p.center.z > 0 for p in me.polygons])
    if not (sel & pole_north).any() or not (sel & ~pole_north).any():
        fail("check on overlapping islands selected %d faces, not faces of both islands" % sel.sum())
    seam_edges = {tuple(sorted(e.vertices)) for e in me.edges if e.use_seam}
    off_boundary = [p.index for p in me.polygons if p.select and not (set(p.edge_keys) & seam_edges)]
    if off_boundary:
        fail("check selected faces with no island boundary edge: %s" % off_boundary)
    print("check on overlapping islands: %d faces selected, all on the islands' boundaries" % sel.sum())

    # -- Esc: the job's cancel flag is returned by the progress callback
    m = operators.mesh_data.MeshArrays(obj)
    ids = operators.charts.ids_from_seams(m.loop_vert, m.loop_edge, m.loop_next, m.edge_seam)
    used, ft = np.unique(ids[m.tri_loops], return_inverse=True)
    uv0 = np.zeros((len(used), 2))
    calls = []

    def run(progress):
        return scaf.atlas(m.Vt, m.Ft, uv0, ft.reshape(-1, 3), progress=lambda i: calls.append(i) or progress(i))
    job = operators._Job([("sphere", run)])
    job.cancel = True
    job.start()
    job.thread.join()
    if not isinstance(job.error, scaf.Cancelled):
        fail("a cancelled job ended with %r" % (job.error,))
    if len(calls) != 1:
        fail("a cancelled job ran %d iterations, expected 1 (cancelled at the first callback)" % len(calls))
    print("cancel: scaf.Cancelled")

    # -- a closed mesh without any seam: automatic seams, or the library's clear error
    bpy.ops.object.select_all(action="DESELECT")
    bpy.ops.mesh.primitive_cube_add()
    cube = bpy.context.active_object
    uv_cube = uvs(cube.data).copy()
    try:
        r = bpy.ops.uv.scaf_bijective_unwrap(resolution=256, padding_texels=4)
    except RuntimeError as e:
        r = str(e)
    if "seams" in scaf.default_atlas_options():
        if r != {"FINISHED"} or not scaf_check(cube, "cube")["bijective"]:
            fail("closed cube with automatic seams: %s" % (r,))
    else:
        if r == {"FINISHED"} or "Mark Seam" not in r or not np.array_equal(uvs(cube.data), uv_cube):
            fail("closed cube without seams: expected an error and the UVs untouched, got %s" % (r,))
        print("closed cube without seams:", r.strip())
    print("blender add-on test: OK")


try:
    main()
except Exception:
    traceback.print_exc()
    sys.exit(1)
