"""integrations/blender/screenshot.py: the README's picture of the add-on.

    xvfb-run -s "-screen 0 1400x820x24" blender --factory-startup \
      --enable-event-simulate --window-geometry 0 0 1400 820 \
      --python integrations/blender/screenshot.py -- OUT.png

(Blender draws its UI only in a window: Xvfb gives it one without a
display.) Enables the add-on (on the Python path: BLENDER_USER_SCRIPTS
or PYTHONPATH as tests/blender/run_blender_test.sh sets), makes a UV
sphere with two seamed islands, unwraps it with Bijective Unwrap, shows
the UV editor with the sidebar tab "scaf", saves a screenshot of the
window and quits.
"""

import sys

import bpy

OUT = sys.argv[sys.argv.index("--") + 1]


def setup():
    import addon_utils
    addon_utils.enable("scaf_uv", default_set=True)
    for o in list(bpy.data.objects):
        bpy.data.objects.remove(o)
    bpy.ops.mesh.primitive_uv_sphere_add(segments=24, ring_count=12)
    me = bpy.context.active_object.data
    for e in me.edges:
        a, b = (me.vertices[i].co for i in e.vertices)
        e.use_seam = (abs(a.x) < 1e-6 and abs(b.x) < 1e-6 and a.y >= -1e-6 and b.y >= -1e-6) or \
            (abs(a.z) < 1e-6 and abs(b.z) < 1e-6)
    win = bpy.context.window_manager.windows[0]
    screen = win.screen
    areas = sorted(screen.areas, key=lambda a: a.width * a.height, reverse=True)
    view3d = next(a for a in areas if a.type == "VIEW_3D")
    with bpy.context.temp_override(window=win, area=view3d):
        bpy.ops.object.mode_set(mode="EDIT")
        bpy.ops.mesh.select_all(action="SELECT")
        bpy.context.scene.scaf_uv.padding_texels = 8  # shown in the panel
        bpy.ops.uv.scaf_bijective_unwrap(resolution=1024, padding_texels=8)
    # the 3D view becomes the UV editor with the add-on's sidebar
    view3d.type = "IMAGE_EDITOR"
    space = view3d.spaces.active
    space.mode = "UV"
    space.show_region_ui = True
    return view3d


def _ui_region(area):
    return next(r for r in area.regions if r.type == "UI")


def click_tab():
    """Open the sidebar tab "scaf": Blender 3.4 has no Python setting for
    the active tab, so a click is simulated where the tab is drawn (the
    fourth tab, after Image, Tool and View, at the sidebar's right edge)."""
    win = bpy.context.window_manager.windows[0]
    area = next(a for a in win.screen.areas if a.type == "IMAGE_EDITOR")
    with bpy.context.temp_override(window=win, area=area,
                                   region=next(r for r in area.regions if r.type == "WINDOW")):
        bpy.ops.image.view_all(fit_view=True)
    ui = _ui_region(area)
    x, y = ui.x + ui.width - 9, ui.y + ui.height - 165
    win.event_simulate(type="MOUSEMOVE", value="NOTHING", x=x, y=y)
    win.event_simulate(type="LEFTMOUSE", value="PRESS", x=x, y=y)
    win.event_simulate(type="LEFTMOUSE", value="RELEASE", x=x, y=y)
    win.event_simulate(type="MOUSEMOVE", value="NOTHING", x=ui.x - 200, y=ui.y + 200)
    bpy.app.timers.register(shoot, first_interval=2.0)
    return None


def shoot():
    win = bpy.context.window_manager.windows[0]
    area = next(a for a in win.screen.areas if a.type == "IMAGE_EDITOR")
    with bpy.context.temp_override(window=win, area=area):
        bpy.ops.screen.screenshot(filepath=OUT)
    print("screenshot:", OUT)
    bpy.ops.wm.quit_blender()
    return None


bpy.context.preferences.view.show_splash = False
setup()
bpy.app.timers.register(click_tab, first_interval=2.0)
