"""scaf._drag: the Drag handle (scaf_drag_t, include/scaf/drag.h).

Interactive dragging of an atlas's charts and vertices: soft handles pull,
SCAF iterations (step) move the layout, which stays bijective with the
padding kept after every iteration; cancel / checkpoint + undo restore a
layout bit for bit; output() is the normalized layout, certified exactly
(what an editor saves). Positions in and out are in layout units (the
mesh's units divided by a power of two; fixed for a mesh), numpy arrays
with numpy, lists of rows without.
"""

import ctypes
import math
import numbers
from dataclasses import dataclass
from typing import Any, Tuple

from . import _arrays, _lib
from ._core import IterationInfo, _Handle, _call_with_progress, _status_name, lib
from ._errors import UsageError


@dataclass
class DragChartInfo:
    """One chart's numbers (scaf_drag_chart_info_t): faces, uvs (its layout
    vertices), centroid (area-weighted, layout units: the pivot of
    move_chart), uv_area, energy (its distortion E, 4 at an isometry),
    held (it has a chart handle)."""

    faces: int
    uvs: int
    centroid: Tuple[float, float]
    uv_area: float
    energy: float
    held: bool


@dataclass(repr=False)
class DragOutput:
    """The normalized, certified layout (scaf_drag_get_output): uv #UV x 2
    in [0,1]^2, ft #F x 3, chart #F, efficiency, gap (inf with one chart)."""

    uv: Any
    ft: Any
    chart: Any
    efficiency: float
    gap: float

    def __repr__(self):
        return "<scaf.DragOutput %d UVs, efficiency %.4f, min gap %.6g>" % (
            len(self.uv), self.efficiency, self.gap)


def _index(x, what):
    if isinstance(x, bool) or not isinstance(x, numbers.Integral):
        raise ValueError("%s: expected an int, got %r" % (what, x))
    x = int(x)
    if not _arrays.INT32_MIN <= x <= _arrays.INT32_MAX:
        raise ValueError("%s: %d is outside the C int range" % (what, x))
    return x


def _real(x, what):
    if isinstance(x, bool) or not isinstance(x, numbers.Real):
        raise ValueError("%s: expected a number, got %r" % (what, x))
    return float(x)


def _count(n):
    if isinstance(n, bool) or not isinstance(n, numbers.Integral):
        raise ValueError("iterations: expected an int, got %r" % (n,))
    return max(min(int(n), _arrays.INT32_MAX), _arrays.INT32_MIN)


class Drag(_Handle):
    """A drag context (scaf_drag_t): options as keyword arguments named like
    the C fields (start: "layout" | "input" | "atlas", padding,
    weight_ratio, solver, box_scale, lambda_ratio, undo_depth). Options
    take effect at the next set_mesh.

        with scaf.Drag(start="input") as d:
            d.set_mesh(V, F, UV, FT)          # e.g. an atlas made by scaf.atlas
            d.checkpoint()
            d.move_chart(0, dx=0.3, angle=0.5)  # total motion since the grab
            d.step(3)                          # bijective after every iteration
            uv = d.uv                          # layout units
            d.undo()                           # back to the checkpoint
            out = d.output()                   # [0,1]^2, certified
    """

    _prefix = "scaf_drag_"
    _defaults = "scaf_drag_options_default"
    _Options = _lib.DragOptions

    def _need_mesh(self):
        if self._nf <= 0:
            raise UsageError("set_mesh first: there is no layout yet", 1, _status_name(1))

    # --- sizes and layout -------------------------------------------------------

    def _get(self, fn):
        with self._use() as h:
            return fn(h)

    chart_count = property(lambda self: self._get(lib.scaf_drag_chart_count))
    uv_count = property(lambda self: self._get(lib.scaf_drag_uv_count))
    face_count = property(lambda self: self._get(lib.scaf_drag_face_count))
    iterations = property(lambda self: self._get(lib.scaf_drag_iterations),
                          doc="Iterations since set_mesh (lowered by cancel and undo).")
    handle_count = property(lambda self: self._get(lib.scaf_drag_handle_count))
    undo_count = property(lambda self: self._get(lib.scaf_drag_undo_count))

    def get_uv(self):
        """(UV #UV x 2 in layout units, FT #F x 3, chart #F) of the current layout."""
        self._need_mesh()
        with self._use() as h:
            uv = _arrays.Output(lib.scaf_drag_uv_count(h), 2, False)
            ft = _arrays.Output(self._nf, 3, True)
            chart = _arrays.Output(self._nf, None, True)
            self._check(lib.scaf_drag_get_uv(h, uv.ptr, ft.ptr, chart.ptr))
            return uv.value(), ft.value(), chart.value()

    @property
    def uv(self):
        """The current positions, #UV x 2 layout units."""
        self._need_mesh()
        with self._use() as h:
            uv = _arrays.Output(lib.scaf_drag_uv_count(h), 2, False)
            self._check(lib.scaf_drag_get_uv(h, uv.ptr, None, None))
            return uv.value()

    def uv_charts(self):
        """The chart of every layout vertex (#UV ints)."""
        self._need_mesh()
        with self._use() as h:
            c = _arrays.Output(lib.scaf_drag_uv_count(h), None, True)
            self._check(lib.scaf_drag_uv_charts(h, c.ptr))
            return c.value()

    # --- handles ------------------------------------------------------------------

    def move_vertex(self, uv, x, y):
        """Pull layout vertex uv to (x, y), layout units (replaces its target)."""
        i, x, y = _index(uv, "uv"), _real(x, "x"), _real(y, "y")
        with self._use() as h:
            self._check(lib.scaf_drag_move_vertex(h, i, x, y))

    def move_vertices(self, idx, targets):
        """move_vertex for each idx[i] with targets[i] (n x 2)."""
        t = _arrays.matrix(targets, "targets", 2, False)
        idx = list(idx)
        if t.rows != len(idx):
            raise ValueError("targets has %d rows, idx has %d: one target per vertex" % (t.rows, len(idx)))
        for k, v in enumerate(idx):
            self.move_vertex(v, t.ptr[2 * k], t.ptr[2 * k + 1])

    def move_chart(self, chart, dx=0.0, dy=0.0, angle=0.0):
        """Pull a chart rigidly: its pose when the handle was created (the
        grab pose) turned by angle radians (counter-clockwise, about the
        grab pose's centroid) and moved by (dx, dy) layout units. Repeated
        calls give the total motion from that same grab pose."""
        c = _index(chart, "chart")
        dx, dy, angle = _real(dx, "dx"), _real(dy, "dy"), _real(angle, "angle")
        with self._use() as h:
            self._check(lib.scaf_drag_move_chart(h, c, dx, dy, angle))

    def clear_vertex(self, uv):
        with self._use() as h:
            self._check(lib.scaf_drag_clear_vertex(h, _index(uv, "uv")))

    def clear_chart(self, chart):
        with self._use() as h:
            self._check(lib.scaf_drag_clear_chart(h, _index(chart, "chart")))

    def clear_handles(self):
        with self._use() as h:
            self._check(lib.scaf_drag_clear_handles(h))

    # --- pins ---------------------------------------------------------------------

    def pin_vertex(self, uv, pinned=True):
        """Pin layout vertex uv (it keeps its exact coordinates through every
        step and compaction) or unpin it (pinned=False)."""
        i = _index(uv, "uv")
        with self._use() as h:
            self._check(lib.scaf_drag_pin_vertex(h, i, 1 if pinned else 0))

    def is_pinned(self, uv):
        with self._use() as h:
            return bool(lib.scaf_drag_is_pinned(h, _index(uv, "uv")))

    pinned_count = property(lambda self: self._get(lib.scaf_drag_pinned_count))

    @property
    def max_handle_error(self):
        """Largest handle-to-target distance (layout units); 0 without handles."""
        self._need_mesh()
        return self._get(lib.scaf_drag_max_handle_error)

    # --- iterations -------------------------------------------------------------

    def step(self, iterations=1, progress=None):
        """Run up to `iterations` SCAF iterations with the current handles
        (fewer when no step lowers the energy any more). progress(info:
        IterationInfo) after each; a true return raises Cancelled (the last
        finished iteration stays). The layout before is kept for cancel()."""
        n = _count(iterations)
        with self._use() as h:
            status = _call_with_progress(_lib.PARAM_PROGRESS, IterationInfo, progress,
                                         lambda cb: lib.scaf_drag_step(h, n, cb, None))
            self._check(status)

    def compact(self, iterations=1, progress=None):
        """The atlas's compaction from the current layout (handles ignored,
        kept for later steps); like step otherwise."""
        n = _count(iterations)
        with self._use() as h:
            status = _call_with_progress(_lib.PARAM_PROGRESS, IterationInfo, progress,
                                         lambda cb: lib.scaf_drag_compact(h, n, cb, None))
            self._check(status)

    def cancel(self):
        """Restore the layout before the last step (bit for bit)."""
        with self._use() as h:
            self._check(lib.scaf_drag_cancel(h))

    def checkpoint(self):
        """Save the current layout for undo (at most undo_depth kept)."""
        with self._use() as h:
            self._check(lib.scaf_drag_checkpoint(h))

    def undo(self):
        """Restore the last checkpoint (bit for bit) and drop it."""
        with self._use() as h:
            self._check(lib.scaf_drag_undo(h))

    def redo(self):
        """Restore the layout the last undo left (bit for bit); undo goes
        back again. A checkpoint, step or compaction drops what can be
        redone."""
        with self._use() as h:
            self._check(lib.scaf_drag_redo(h))

    redo_count = property(lambda self: self._get(lib.scaf_drag_redo_count))

    # --- rigid motions ------------------------------------------------------------

    @staticmethod
    def _motion(dx, dy, angle, factor, flip, remirror, pivot):
        m = lib.scaf_drag_motion_identity()
        m.dx, m.dy, m.angle = _real(dx, "dx"), _real(dy, "dy"), _real(angle, "angle")
        m.factor = _real(factor, "factor")
        if flip not in _lib.DRAG_FLIPS:
            raise ValueError("flip %r: give None, 'u' or 'v'" % (flip,))
        m.flip = _lib.DRAG_FLIPS[flip]
        m.remirror = 1 if remirror else 0
        if pivot is not None:
            p = list(pivot)
            if len(p) != 2:
                raise ValueError("pivot: give (u, v)")
            m.has_pivot = 1
            m.pivot[0], m.pivot[1] = _real(p[0], "pivot u"), _real(p[1], "pivot v")
        return m

    @staticmethod
    def _charts(charts):
        ids = [_index(c, "chart") for c in ([charts] if isinstance(charts, numbers.Integral) else list(charts))]
        return (ctypes.c_int * max(len(ids), 1))(*ids), len(ids)

    def rigid_begin(self, charts):
        """Grab a selection (a chart id or a list of them) for rigid moves:
        the current layout becomes the grab pose (scaf_drag_rigid_begin)."""
        arr, n = self._charts(charts)
        with self._use() as h:
            self._check(lib.scaf_drag_rigid_begin(h, arr, n))

    def rigid_move(self, dx=0.0, dy=0.0, angle=0.0, factor=1.0, flip=None, remirror=False,
                   pivot=None):
        """Move the grabbed selection rigidly by the total motion since the
        grab (translation, rotation about the pivot, uniform scale; flip
        'u' or 'v' only with remirror=True, as a half turn); the other
        charts are pushed by translations only, the padding kept, the
        layout certified exactly. Returns the fraction of the motion kept
        (1: all of it)."""
        m = self._motion(dx, dy, angle, factor, flip, remirror, pivot)
        reached = ctypes.c_double(0.0)
        with self._use() as h:
            self._check(lib.scaf_drag_rigid_move(h, ctypes.byref(m), ctypes.byref(reached)))
        return reached.value

    def rigid_end(self):
        with self._use() as h:
            self._check(lib.scaf_drag_rigid_end(h))

    def transform(self, charts, dx=0.0, dy=0.0, angle=0.0, factor=1.0, flip=None,
                  remirror=False, pivot=None):
        """One rigid operation on a selection (rigid_begin, rigid_move,
        rigid_end); checkpoint() before it for undo. Returns the fraction
        kept."""
        arr, n = self._charts(charts)
        m = self._motion(dx, dy, angle, factor, flip, remirror, pivot)
        reached = ctypes.c_double(0.0)
        with self._use() as h:
            self._check(lib.scaf_drag_transform(h, arr, n, ctypes.byref(m), ctypes.byref(reached)))
        return reached.value

    @property
    def energy_cap(self):
        """Deform mode: a chart without a handle may not rise above this
        times its E at the drag's start (0: no cap; default 1.25)."""
        return self._get(lib.scaf_drag_energy_cap)

    @energy_cap.setter
    def energy_cap(self, ratio):
        r = _real(ratio, "energy_cap")
        with self._use() as h:
            self._check(lib.scaf_drag_set_energy_cap(h, r))

    capped_count = property(lambda self: self._get(lib.scaf_drag_capped_count),
                            doc="Iterations the energy cap refused since set_mesh.")

    # --- measures and output ------------------------------------------------------

    @property
    def energy(self):
        self._need_mesh()
        return self._get(lib.scaf_drag_energy)

    @property
    def packing_efficiency(self):
        """Chart UV area / (longest side of the layout's bounding box)^2."""
        self._need_mesh()
        return self._get(lib.scaf_drag_packing_efficiency)

    def face_energy(self):
        """Distortion of every face (#F values, 4 at an isometry)."""
        self._need_mesh()
        with self._use() as h:
            e = _arrays.Output(self._nf, None, False)
            self._check(lib.scaf_drag_face_energy(h, e.ptr))
            return e.value()

    def chart_info(self, chart):
        """A DragChartInfo for one chart."""
        c = _index(chart, "chart")
        info = _lib.DragChartInfo()
        with self._use() as h:
            self._check(lib.scaf_drag_chart_info(h, c, ctypes.byref(info)))
        return DragChartInfo(info.faces, info.uvs, (info.centroid[0], info.centroid[1]), info.uv_area,
                             info.energy, bool(info.held))

    def output(self):
        """The current layout normalized into [0,1]^2 and certified exactly
        (bijective, every two charts at least the padding apart): a DragOutput."""
        self._need_mesh()
        with self._use() as h:
            uv = _arrays.Output(lib.scaf_drag_uv_count(h), 2, False)
            ft = _arrays.Output(self._nf, 3, True)
            chart = _arrays.Output(self._nf, None, True)
            eff, gap = ctypes.c_double(math.nan), ctypes.c_double(math.nan)
            self._check(lib.scaf_drag_get_output(h, uv.ptr, ft.ptr, chart.ptr, ctypes.byref(eff),
                                                 ctypes.byref(gap)))
            return DragOutput(uv.value(), ft.value(), chart.value(), eff.value, gap.value)


def default_drag_options():
    """The C defaults of scaf_drag_options_default() as a dict (Drag options)."""
    from ._core import _as_dict
    return _as_dict(lib.scaf_drag_options_default())
