"""scaf._volume: the 3D functions of scaf/volume.h on arrays.

inflate, untangle, flow and tet_mesh each run on one C scaf_volume_t, freed before
they return; check_surface and check_tets fill a C report. Arrays in as
scaf.param takes them (numpy array-likes or nested lists), positions out
as #V x 3 float64. Progress callbacks and cancellation as scaf.param: a
callback gets a VolumeStepInfo after every step, a true return raises
Cancelled (inflate and flow attach .result, the positions of the last
finished step), an exception inside it is re-raised, Ctrl-C stops the run.
Options are checked by C (struct_size set by its _default() function):
a value out of range raises UsageError naming it, never a silent default.
"""

import ctypes
from dataclasses import dataclass
from typing import Any, Optional, Tuple

from . import _arrays, _lib
from ._core import _call_with_progress, _enum_value, _fill, _raise, lib
from ._errors import Cancelled


@dataclass
class VolumeStepInfo:
    """One step of a 3D run (scaf_volume_step_info_t): phase "flow_step"
    (scaf.flow, untangle's first phase; flow also reports step 0, the
    normalized start) or "iteration" (the 3D SCAF loop of inflate and
    untangle's flow back). defects: intersecting face pairs + zero-area
    faces after the step, -1 when not checked; energy, step_length, tets,
    quality_min (iterations); rms, max (untangle: distance to the input
    relative to its bounding-box diagonal)."""

    phase: str
    step: int
    seconds: float
    check_seconds: float
    defects: int
    pairs: int
    degenerate_faces: int
    energy: float
    arap: float
    step_length: float
    rms: float
    max: float
    tets: int
    scaffold_vertices: int
    quality_min: float
    quality_p5: float

    @classmethod
    def _from_c(cls, c):
        phase = _lib.VOLUME_PHASES[c.phase] if 0 <= c.phase < len(_lib.VOLUME_PHASES) else c.phase
        return cls(phase, c.step, c.seconds, c.check_seconds, c.defects, c.pairs,
                   c.degenerate_faces, c.energy, c.arap, c.step_length, c.rms, c.max, c.tets,
                   c.scaffold_vertices, c.quality_min, c.quality_p5)


@dataclass(repr=False)
class InflateResult:
    """What scaf.inflate returns. positions: #V x 3 (the input's faces at
    the grown positions); iterations done; box_lo, box_hi: the fixed box
    of tets; diagonal_before / diagonal_after: the bounding-box diagonal
    of the input and of the result; tets: with tets=True, (P #P x 3, T #T x
    4 positively oriented, label #T: 1 inside the surface, 2 outside), the
    surface's vertices first in P; else None."""

    positions: Any
    iterations: int
    box_lo: Tuple[float, float, float]
    box_hi: Tuple[float, float, float]
    diagonal_before: float
    diagonal_after: float
    tets: Optional[Tuple[Any, Any, Any]] = None

    def __repr__(self):
        return "<scaf.InflateResult %d vertices, diagonal x%.4g after %d iteration(s)>" % (
            len(self.positions), self.diagonal_after / self.diagonal_before
            if self.diagonal_before else 0.0, self.iterations)


@dataclass(repr=False)
class UntangleResult:
    """What scaf.untangle returns. positions: #V x 3, free of
    self-intersections (the iterate of lowest energy); flowed: the surface
    the flow freed (the input when already free); stop_reason:
    "already_free", "converged", "zero_step" or "iteration_limit";
    input_pairs; flow_steps; iterations; best_iteration; rms, max (result)
    and flowed_rms, flowed_max: distances to the input relative to its
    bounding-box diagonal `diagonal`."""

    positions: Any
    flowed: Any
    stop_reason: str
    input_pairs: int
    flow_steps: int
    iterations: int
    best_iteration: int
    diagonal: float
    rms: float
    max: float
    flowed_rms: float
    flowed_max: float

    def __repr__(self):
        return "<scaf.UntangleResult %d vertices, %s, %d flow step(s), %d iteration(s), rms %.4g>" % (
            len(self.positions), self.stop_reason, self.flow_steps, self.iterations, self.rms)


@dataclass(repr=False)
class FlowResult:
    """What scaf.flow returns. positions: #V x 3 in the normalized frame
    (area-weighted centroid at the origin, unit area); steps done;
    input_defects and defects (with until_free: intersecting face pairs +
    zero-area faces of the normalized input and of the result; else -1)."""

    positions: Any
    steps: int
    input_defects: int
    defects: int

    def __repr__(self):
        return "<scaf.FlowResult %d vertices after %d step(s)>" % (len(self.positions), self.steps)


@dataclass
class SurfaceReport:
    """scaf.check_surface's verdict (exact): intersection_free (no
    intersecting pair and no zero-area face); pairs and their kinds;
    first_pairs: up to 16 intersecting (i, j) face pairs; closed, manifold,
    boundary_edges, vertices (referenced), faces, degenerate_faces."""

    intersection_free: bool
    faces: int
    vertices: int
    boundary_edges: int
    closed: bool
    manifold: bool
    degenerate_faces: int
    first_degenerate: int
    pairs: int
    crossing_pairs: int
    vertex_pairs: int
    edge_pairs: int
    duplicate_pairs: int
    first_pairs: list


@dataclass
class TetsReport:
    """scaf.check_tets's verdict (exact orient3d): valid when every tet is
    positively oriented; counts; first_bad: the lowest inverted or flat
    tet, -1 when none."""

    valid: bool
    tets: int
    positive: int
    inverted: int
    degenerate: int
    first_bad: int


class _Volume:
    """One scaf_volume_t for one call."""

    def __enter__(self):
        self.h = lib.scaf_volume_new()
        if not self.h:
            raise MemoryError("scaf: out of memory creating a 3D handle")
        return self

    def __exit__(self, *exc):
        lib.scaf_volume_destroy(self.h)
        self.h = None

    def check(self, status):
        if status != _lib.SCAF_OK:
            msg = lib.scaf_volume_error(self.h)
            _raise(status, msg.decode("utf-8", "replace") if msg else "")

    def positions(self, getter=None):
        out = _arrays.Output(lib.scaf_volume_vertex_count(self.h), 3, False)
        self.check((getter or lib.scaf_volume_get_positions)(self.h, out.ptr))
        return out.value()

    def summary(self):
        s = _lib.VolumeSummary()
        s.struct_size = ctypes.sizeof(s)
        self.check(lib.scaf_volume_get_summary(self.h, ctypes.byref(s)))
        return s


def _options(defaults, options):
    o = defaults()
    if "struct_size" in options:
        raise TypeError("struct_size is set by the binding")
    if "solver" in options:
        options["solver"] = _enum_value(options["solver"], _lib.SOLVER_NEWTON_OR_SLIM, "solver")
    if "verify" in options or "until_free" in options:
        for k in ("verify", "until_free"):
            if k in options:
                options[k] = 1 if options[k] else 0
    return _fill(o, options)


def _surface(V, F):
    return _arrays.matrix(V, "V", 3, False), _arrays.matrix(F, "F", 3, True)


def _run(fn, opts, v, f, progress, vol):
    return _call_with_progress(
        _lib.VOLUME_PROGRESS, VolumeStepInfo, progress,
        lambda cb: fn(vol.h, v.ptr, v.rows, f.ptr, f.rows, ctypes.byref(opts), cb, None))


def inflate(V, F, *, scale=2.0, iterations=None, tets=False, progress=None, **options):
    """Grow (scale > 1) or shrink the closed surface (V #V x 3, F #F x 3)
    toward `scale` times its size about its centroid, inside a fixed box of
    tets that it presses against but never passes through, nor through
    itself (scaf_inflate). iterations: default 50; more options: box_scale
    (> 1, default 3.76), solver ("newton" or "slim"). tets=True also
    returns the final tet mesh. progress(VolumeStepInfo) after every
    iteration, true to cancel (Cancelled with .result). Raises ValueError
    (bad arrays), UsageError (an option out of range), MeshError (not a
    closed manifold surface free of self-intersections), NumericError."""
    options["scale"] = scale
    if iterations is not None:
        options["iterations"] = iterations
    opts = _options(lib.scaf_inflate_options_default, options)
    v, f = _surface(V, F)
    with _Volume() as vol:
        status = _run(lib.scaf_inflate, opts, v, f, progress, vol)

        def result():
            s = vol.summary()
            t = None
            if tets:
                P = _arrays.Output(lib.scaf_volume_tet_vertex_count(vol.h), 3, False)
                T = _arrays.Output(lib.scaf_volume_tet_count(vol.h), 4, True)
                label = _arrays.Output(lib.scaf_volume_tet_count(vol.h), None, True)
                vol.check(lib.scaf_volume_get_tets(vol.h, P.ptr, T.ptr, label.ptr))
                t = (P.value(), T.value(), label.value())
            return InflateResult(vol.positions(), s.iterations, tuple(s.box_lo), tuple(s.box_hi),
                                 s.diagonal_before, s.diagonal_after, t)

        try:
            vol.check(status)
        except Cancelled as e:
            e.result = result()
            raise
        return result()


def untangle(V, F, *, iterations=None, progress=None, **options):
    """Remove the self-intersections of the closed genus-0 surface (V, F)
    (scaf_untangle): curvature flow until the exact checker proves it free,
    then the 3D SCAF loop pulls it back toward the input without ever
    letting it pass through itself. iterations: of the flow back (default
    300); more options: delta, flow_steps, tolerance, anchor, verify.
    progress(VolumeStepInfo) after every flow step and iteration, true to
    cancel (Cancelled, no result). Returns an UntangleResult; an input
    already free comes back unchanged (stop_reason "already_free")."""
    if iterations is not None:
        options["iterations"] = iterations
    opts = _options(lib.scaf_untangle_options_default, options)
    v, f = _surface(V, F)
    with _Volume() as vol:
        vol.check(_run(lib.scaf_untangle, opts, v, f, progress, vol))
        s = vol.summary()
        stop = lib.scaf_untangle_stop_name(s.stop).decode()
        return UntangleResult(vol.positions(), vol.positions(lib.scaf_volume_get_flowed), stop,
                              s.input_defects, s.steps, s.iterations, s.best_iteration,
                              s.diagonal_before, s.rms, s.max, s.flowed_rms, s.flowed_max)


def flow(V, F, *, steps=10, delta=1e-3, until_free=False, progress=None):
    """Conformalized mean curvature flow of the closed surface (V, F)
    (scaf_flow): `steps` steps of time `delta` on the surface normalized to
    unit area; with until_free, stop at the first step the exact checker
    proves free of self-intersections (NumericError when none is).
    progress(VolumeStepInfo) at the start (step 0) and after every step,
    true to cancel (Cancelled with .result). Returns a FlowResult."""
    opts = _options(lib.scaf_flow_options_default,
                    {"steps": steps, "delta": delta, "until_free": until_free})
    v, f = _surface(V, F)
    with _Volume() as vol:
        status = _run(lib.scaf_flow, opts, v, f, progress, vol)

        def result():
            s = vol.summary()
            return FlowResult(vol.positions(), s.steps, s.input_defects, s.defects)

        try:
            vol.check(status)
        except Cancelled as e:
            e.result = result()
            raise
        return result()


def tet_mesh(V, F, *, box_scale=3.0, box_cells=8):
    """The tets of the box around the closed surface (V, F), every surface
    triangle kept (scaf_tet_mesh: TetGen, checked exactly): (P #P x 3 with
    the surface's vertices first, T #T x 4 positively oriented, label #T:
    1 inside the surface, 2 outside). box_scale > 1, box_cells 1..64.
    MeshError when the surface cannot be meshed (the message says why)."""
    opts = _options(lib.scaf_tet_options_default, {"box_scale": box_scale, "box_cells": box_cells})
    v, f = _surface(V, F)
    with _Volume() as vol:
        vol.check(lib.scaf_tet_mesh(vol.h, v.ptr, v.rows, f.ptr, f.rows, ctypes.byref(opts)))
        P = _arrays.Output(lib.scaf_volume_tet_vertex_count(vol.h), 3, False)
        T = _arrays.Output(lib.scaf_volume_tet_count(vol.h), 4, True)
        label = _arrays.Output(lib.scaf_volume_tet_count(vol.h), None, True)
        vol.check(lib.scaf_volume_get_tets(vol.h, P.ptr, T.ptr, label.ptr))
        return P.value(), T.value(), label.value()


def _report_check(status, report):
    if status != _lib.SCAF_OK:
        _raise(status, report.message.decode("utf-8", "replace"))


def check_surface(V, F):
    """Exact self-intersection check of the triangle surface (V #V x 3,
    F #F x 3; open or closed) (scaf_check_surface). Returns a
    SurfaceReport; MeshError for an index out of range or a non-finite
    coordinate."""
    v, f = _surface(V, F)
    r = _lib.SurfaceReport()
    r.struct_size = ctypes.sizeof(r)
    _report_check(lib.scaf_check_surface(v.ptr, v.rows, f.ptr, f.rows, ctypes.byref(r)), r)
    return SurfaceReport(bool(r.intersection_free), r.faces, r.vertices, r.boundary_edges,
                         bool(r.closed), bool(r.manifold), r.degenerate_faces, r.first_degenerate,
                         r.pairs, r.crossing_pairs, r.vertex_pairs, r.edge_pairs, r.duplicate_pairs,
                         [tuple(r.first[i]) for i in range(r.nfirst)])


def check_tets(V, T):
    """Exact orientation check of the tets (V #V x 3, T #T x 4)
    (scaf_check_tets): positive when d sees (a, b, c) counter-clockwise.
    Returns a TetsReport; MeshError for an index out of range or a
    non-finite coordinate."""
    v = _arrays.matrix(V, "V", 3, False)
    t = _arrays.matrix(T, "T", 4, True)
    r = _lib.TetsReport()
    r.struct_size = ctypes.sizeof(r)
    _report_check(lib.scaf_check_tets(v.ptr, v.rows, t.ptr, t.rows, ctypes.byref(r)), r)
    return TetsReport(bool(r.valid), r.tets, r.positive, r.inverted, r.degenerate, r.first_bad)
