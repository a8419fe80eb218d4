"""scaf_uv.operators: Bijective unwrap, Bijective pack, Check.

Unwrap and pack compute in a worker thread (the ctypes calls release the
GIL) while a modal operator keeps Blender responsive: a timer shows the
scaf iteration in the status bar and the window manager's progress, Esc
sets a flag the progress callback returns (scaf cancels after the current
iteration, and no UV changes). Run from a script (EXEC_DEFAULT, also in
`blender -b`) the same job runs in the calling thread. The mesh is read
before and written after the run, both in Blender's main thread; the
operators are REGISTER + UNDO, so Ctrl-Z restores the previous UVs.
Every object is computed on its own (its own atlas in [0,1]^2).
"""

import threading

import bpy
import numpy as np

from . import charts, checker, library, mesh_data, orientation, overlaps

# Requested padding = texels / resolution + this margin, so that rounding
# the certified doubles to Blender's float32 UVs (each coordinate in [0,1]
# moves by at most 2^-25) keeps every gap >= the padding asked for.
FLOAT32_MARGIN = 1e-6


def _mesh_objects(context):
    objs = list(context.objects_in_mode_unique_data) if context.mode == "EDIT_MESH" else \
        [o for o in context.selected_objects if o.type == "MESH"]
    seen, out = set(), []
    for o in objs:
        if o.type == "MESH" and o.data not in seen:
            seen.add(o.data)
            out.append(o)
    return out


def _padding(op):
    return op.padding_texels / op.resolution + FLOAT32_MARGIN


class _Job:
    """The runs of one operator call: tasks done one after the other, each
    a function of a progress callback; the latest progress info and a
    cancel flag shared with the main thread."""

    def __init__(self, tasks):
        self.tasks = tasks  # [(name, fn(progress) -> result)]
        self.results = []   # [(name, result)]
        self.error = None
        self.cancel = False
        self.current = ""
        self.info = None
        self.thread = None

    def progress(self, info):
        self.info = info
        return self.cancel

    def run(self):
        try:
            for i, (name, fn) in enumerate(self.tasks):
                self.current = "%s (%d/%d)" % (name, i + 1, len(self.tasks))
                self.results.append((name, fn(self.progress)))
        except BaseException as e:  # noqa: B902 - handed to the main thread
            self.error = e

    def start(self):
        self.thread = threading.Thread(target=self.run, name="scaf_uv", daemon=True)
        self.thread.start()

    def status(self):
        i = self.info
        if i is None:
            return "scaf: %s starting - Esc cancels" % self.current
        return ("scaf: %s %s iteration %d, energy %.4g, efficiency %.3f - Esc cancels"
                % (self.current, i.phase, i.iteration, i.energy, i.efficiency))


class _AtlasOperator:
    """Shared by unwrap and pack: read, run scaf.atlas per object, write."""

    bl_options = {"REGISTER", "UNDO"}

    resolution: bpy.props.IntProperty(name="Texture size", description="Texels per side of the texture",
                                      default=1024, min=1, max=65536)
    padding_texels: bpy.props.FloatProperty(name="Padding (texels)",
                                            description="Smallest distance between two islands, in texels",
                                            default=4.0, min=0.0, max=1024.0)

    @classmethod
    def poll(cls, context):
        return bool(_mesh_objects(context))

    def tasks(self, context, scaf):  # -> [(name, fn)], self.meshes filled
        raise NotImplementedError

    def _prepare(self, context):
        try:
            scaf = library.load(context)
        except library.NotFound as e:
            self.report({"ERROR"}, str(e))
            return None
        self.meshes = {}
        try:
            tasks = self.tasks(context, scaf)
        except ValueError as e:
            self.report({"ERROR"}, str(e))
            return None
        self.scaf = scaf
        return _Job(tasks)

    def _finish(self, context, job):
        scaf = self.scaf
        if job.error is not None:
            if isinstance(job.error, scaf.Cancelled):
                self.report({"WARNING"}, "scaf: cancelled, UVs unchanged")
            elif isinstance(job.error, scaf.Error):
                hint = ""
                if "closed surface" in str(job.error) or "cut it open" in str(job.error):
                    hint = " (mark seams in edit mode: Edge > Mark Seam)"
                self.report({"ERROR"}, "scaf: %s%s" % (job.error, hint))
            else:
                self.report({"ERROR"}, "scaf: %s: %s" % (type(job.error).__name__, job.error))
            return {"CANCELLED"}
        lines = []
        for name, r in job.results:
            obj, m = self.meshes[name]
            loop_uv, disagree = m.corner_uvs(r.uv, r.ft)
            mesh_data.write_uvs(obj, loop_uv)
            # the float32 UVs as Blender stores them: still no flipped triangle?
            ids, uv = charts.ids_from_uvs(m.loop_vert, loop_uv)
            signs = orientation.orient(uv, ids[m.tri_loops])
            bad = int(np.count_nonzero(signs <= 0))
            lines.append("%s: %d island(s), efficiency %.3f, min gap %.4g texels%s%s" % (
                name, r.chart_count, r.efficiency, r.min_gap * self.resolution,
                "" if not bad else ", %d triangle(s) flipped by rounding to 32-bit UVs: run Check" % bad,
                "" if not disagree else ", %d corner(s) cut inside a face" % disagree))
            if getattr(r, "note", None):
                lines.append("%s: %s" % (name, r.note))
        for line in lines:
            self.report({"INFO"}, line)
        return {"FINISHED"}

    def execute(self, context):
        job = self._prepare(context)
        if job is None:
            return {"CANCELLED"}
        wm = context.window_manager
        wm.progress_begin(0, 1000)
        try:
            job.run()
        finally:
            wm.progress_end()
        return self._finish(context, job)

    def invoke(self, context, event):
        job = self._prepare(context)
        if job is None:
            return {"CANCELLED"}
        self.job = job
        wm = context.window_manager
        self.timer = wm.event_timer_add(0.1, window=context.window)
        wm.modal_handler_add(self)
        wm.progress_begin(0, self.total_iterations)
        job.start()
        return {"RUNNING_MODAL"}

    def _end_modal(self, context):
        wm = context.window_manager
        wm.event_timer_remove(self.timer)
        wm.progress_end()
        context.workspace.status_text_set(None)

    def modal(self, context, event):
        job = self.job
        if event.type == "ESC":
            job.cancel = True  # the next progress call returns True
        if event.type == "TIMER":
            if job.thread.is_alive():
                context.workspace.status_text_set(job.status())
                if job.info is not None:
                    context.window_manager.progress_update(min(job.info.iteration, self.total_iterations))
            else:
                job.thread.join()
                self._end_modal(context)
                return self._finish(context, job)
        return {"RUNNING_MODAL"}  # the mesh stays untouched until the run ends

    def _atlas_options(self, scaf):
        d = scaf.default_atlas_options()
        self.total_iterations = max(1, d["settle_iterations"] + d["compact_iterations"])
        return {}


class SCAF_OT_bijective_unwrap(_AtlasOperator, bpy.types.Operator):
    """Unwrap with scaf: islands cut along the marked seams, mapped without any flipped or \
overlapping triangle and packed into the UV square with the padding (certified)"""

    bl_idname = "uv.scaf_bijective_unwrap"
    bl_label = "Bijective Unwrap"

    def tasks(self, context, scaf):
        options = self._atlas_options(scaf)
        if "seams" in scaf.default_atlas_options():
            # automatic seams: the marked ones plus the cuts every island needs to open into a disk
            options["seams"] = "extend"
        tasks = []
        for obj in _mesh_objects(context):
            m = mesh_data.MeshArrays(obj)
            self.meshes[obj.name] = (obj, m)
            ids = charts.ids_from_seams(m.loop_vert, m.loop_edge, m.loop_next, m.edge_seam)
            used, ft = np.unique(ids[m.tri_loops], return_inverse=True)
            ft = ft.reshape(-1, 3).astype(np.int32)
            uv = np.zeros((len(used), 2))  # only the indices say where the seams are
            pad = _padding(self)

            def run(progress, m=m, ft=ft, uv=uv, pad=pad):
                return scaf.atlas(m.Vt, m.Ft, uv, ft, padding=pad, progress=progress, **options)
            tasks.append((obj.name, run))
        return tasks


class SCAF_OT_bijective_pack(_AtlasOperator, bpy.types.Operator):
    """Pack the UV islands with scaf: certified padding, no overlap, no mirrored island; starts \
from the current layout when it is bijective, else lays the islands out afresh"""

    bl_idname = "uv.scaf_bijective_pack"
    bl_label = "Bijective Pack"

    def tasks(self, context, scaf):
        options = self._atlas_options(scaf)
        tasks = []
        for obj in _mesh_objects(context):
            m = mesh_data.MeshArrays(obj)
            self.meshes[obj.name] = (obj, m)
            ids, uv = charts.ids_from_uvs(m.loop_vert, m.loop_uv)
            used, ft = np.unique(ids[m.tri_loops], return_inverse=True)
            ft = ft.reshape(-1, 3).astype(np.int32)
            uv = uv[used]
            pad = _padding(self)

            def run(progress, m=m, ft=ft, uv=uv, pad=pad):
                try:  # the current UVs as the start: accepted only when exactly bijective and padded
                    return scaf.atlas(m.Vt, m.Ft, uv, ft, padding=pad, init_input=True, progress=progress,
                                      **options)
                except (scaf.MeshError, scaf.UsageError) as e:  # not bijective / padding not met
                    r = scaf.atlas(m.Vt, m.Ft, uv, ft, padding=pad, progress=progress, **options)
                    r.note = "the current UVs cannot be the start (%s): islands laid out afresh" % e
                    return r
            tasks.append((obj.name, run))
        return tasks


class SCAF_OT_check(bpy.types.Operator):
    """Check the active UV map with scaf's exact checker: select the faces with a flipped or \
zero-area triangle or an overlapping boundary, and report every defect"""

    bl_idname = "uv.scaf_check"
    bl_label = "Check Bijectivity"
    bl_options = {"REGISTER", "UNDO"}  # the selection changes

    @classmethod
    def poll(cls, context):
        return bool(_mesh_objects(context))

    def execute(self, context):
        try:
            scaf = library.load(context)
        except library.NotFound as e:
            self.report({"ERROR"}, str(e))
            return {"CANCELLED"}
        program = checker.find_program(library.program(context), scaf.library_path)
        total = 0
        for obj in _mesh_objects(context):
            try:
                m = mesh_data.MeshArrays(obj)
            except ValueError as e:
                self.report({"ERROR"}, str(e))
                return {"CANCELLED"}
            ids, uv = charts.ids_from_uvs(m.loop_vert, m.loop_uv)
            ft = ids[m.tri_loops]
            signs = orientation.orient(uv, ft)
            crossing, _ = overlaps.overlapping_triangles(uv, ft)
            bad_poly = np.zeros(len(m.poly_start), bool)
            bad_poly[m.tri_poly[signs <= 0]] = True
            bad_poly[m.tri_poly[crossing]] = True
            mesh_data.select_polygons(obj, bad_poly, context.tool_settings)
            nbad = int(np.count_nonzero(bad_poly))
            total += nbad
            if program:
                try:
                    rep = checker.check(program, m.Vt, m.Ft, uv, ft)
                except (checker.CheckError, OSError) as e:
                    self.report({"ERROR"}, str(e))
                    return {"CANCELLED"}
                verdict = checker.summary(rep)
            else:
                verdict = ("%d flipped or zero-area triangle(s), %d with crossing or touching boundaries; "
                           "folds and nesting not checked: the scaf program was not found (set it in the "
                           "add-on preferences)" % (int(np.count_nonzero(signs <= 0)), len(crossing)))
            self.report({"INFO"} if verdict == "bijective" else {"WARNING"},
                        "%s: %s; %d face(s) selected" % (obj.name, verdict, nbad))
        return {"FINISHED"}


classes = (SCAF_OT_bijective_unwrap, SCAF_OT_bijective_pack, SCAF_OT_check)
