"""tests/blender/test_modal.py: the add-on as the UI runs it (a window).

Run by run_blender_test.sh under xvfb-run: `blender --factory-startup
--enable-event-simulate --python test_modal.py -- WORK`, with the add-on
installed by test_addon.py's run (the same scratch user folder). Invokes
Bijective Unwrap as a click does (INVOKE_DEFAULT: the modal operator, its
worker thread, timer, status text and progress), waits for the UVs to
change (observed in a timer, no fixed sleep), then checks the UI's own
undo step: ed.undo restores the UVs before the unwrap, ed.redo the
unwrapped ones (so the operator pushed a step of its own). A result file
WORK/modal.txt says "ok" or the failure; the runner checks it.
"""

import os
import sys
import traceback

import bmesh
import bpy

WORK = sys.argv[sys.argv.index("--") + 1]
RESULT = os.path.join(WORK, "modal.txt")
state = {"ticks": 0}


def finish(msg):
    with open(RESULT, "w") as f:
        f.write(msg + "\n")
    bpy.ops.wm.quit_blender()


def corner_uvs(obj):
    bm = bmesh.from_edit_mesh(obj.data)
    layer = bm.loops.layers.uv.active
    return [tuple(l[layer].uv) for f in bm.faces for l in f.loops]


def start():
    import addon_utils
    addon_utils.enable("scaf_uv", default_set=True)
    for o in list(bpy.data.objects):
        bpy.data.objects.remove(o)
    bpy.ops.mesh.primitive_uv_sphere_add(segments=16, ring_count=8)
    obj = bpy.context.active_object
    me = obj.data
    for e in me.edges:
        a, b = (me.vertices[i].co for i in e.vertices)
        e.use_seam = (abs(a.x) < 1e-6 and abs(b.x) < 1e-6 and a.y >= -1e-6 and b.y >= -1e-6) or \
            (abs(a.z) < 1e-6 and abs(b.z) < 1e-6)
    win = bpy.context.window_manager.windows[0]
    area = next(a for a in win.screen.areas if a.type == "VIEW_3D")
    with bpy.context.temp_override(window=win, area=area):
        bpy.ops.object.mode_set(mode="EDIT")
        bpy.ops.ed.undo_push(message="before unwrap")
        state["before"] = corner_uvs(obj)
        r = bpy.ops.uv.scaf_bijective_unwrap("INVOKE_DEFAULT", resolution=256, padding_texels=4)
    if r != {"RUNNING_MODAL"}:
        finish("invoke returned %s, expected RUNNING_MODAL" % r)
        return None
    state["obj"] = obj
    bpy.app.timers.register(wait, first_interval=0.2)
    return None


def wait():
    try:
        obj = state["obj"]
        state["ticks"] += 1
        if corner_uvs(obj) == state["before"]:
            if state["ticks"] > 600:  # two minutes: the run never ended
                finish("the modal unwrap did not change the UVs")
                return None
            return 0.2
        win = bpy.context.window_manager.windows[0]
        area = next(a for a in win.screen.areas if a.type == "VIEW_3D")
        after = corner_uvs(obj)
        with bpy.context.temp_override(window=win, area=area):
            bpy.ops.ed.undo()
        if corner_uvs(obj) != state["before"]:
            finish("undo after the modal unwrap did not restore the UVs")
            return None
        # redo reaches the unwrapped UVs only if the operator pushed its own step
        with bpy.context.temp_override(window=win, area=area):
            bpy.ops.ed.redo()
        if corner_uvs(obj) != after:
            finish("redo did not bring the unwrapped UVs back: the operator pushed no undo step")
            return None
        finish("ok")
    except Exception:
        finish("error: " + traceback.format_exc())
    return None


bpy.context.preferences.view.show_splash = False
bpy.app.timers.register(start, first_interval=1.0)
