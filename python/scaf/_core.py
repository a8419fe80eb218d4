"""scaf._core: the Param and Atlas handles and the one-call functions.

Param and Atlas each own one C context (scaf_param_t / scaf_atlas_t) and
free it in close(), at the end of a `with` block, or at the latest when
they are garbage collected. Every C status other than SCAF_OK becomes a
scaf.Error subclass carrying the context's message. A progress callback
is called after every iteration with a copy of the C iteration info; a
true return value cancels the run (scaf.Cancelled); an exception raised
inside it cancels the run in C and is re-raised once the C call has
returned, so nothing is lost or crashes. Ctrl-C during a run (main thread)
cancels it after the current iteration and raises KeyboardInterrupt. A
handle takes one call at a time (a call from inside its own callback is
refused with UsageError); ctypes releases the GIL during each C call, so
two handles can run in two threads.
"""

import contextlib
import ctypes
import math
import numbers
import signal
import threading
from dataclasses import dataclass, field
from typing import Any, Dict

from . import _arrays, _lib
from ._errors import BY_STATUS, Cancelled, Error, UsageError

lib, library_path = _lib.load()
__version__ = lib.scaf_version().decode()


# scaf_param_set_handles' default weight ratio (SCAF_HANDLE_WEIGHT_DEFAULT)
HANDLE_WEIGHT_DEFAULT = 1e4


def _status_name(status):
    s = lib.scaf_status_name(status)
    return s.decode() if s else "status %d" % status


def _stop_reason_name(reason):
    """"iteration_limit", "tolerance", "zero_step", "cancelled", ... (C's
    scaf_stop_reason_name, so a reason added in C is named at once)."""
    return lib.scaf_stop_reason_name(reason).decode()


def _raise(status, message):
    cls = BY_STATUS.get(status, Error)
    raise cls(message or _status_name(status), status, _status_name(status))


# --- options ---------------------------------------------------------------

_BOOL_FIELDS = {"box_square", "init_input", "repack"}


def _enum_value(value, names, what):
    if isinstance(value, str):
        key = value.lower().replace("-", "_")
        if key not in names:
            raise ValueError("%s: unknown name %r; known: %s (or the C enum's int value)"
                             % (what, value, ", ".join(sorted(names))))
        return names[key]
    if isinstance(value, bool) or not isinstance(value, numbers.Integral):
        raise ValueError("%s: expected a name or an int, got %r" % (what, value))
    return int(value)


def _enum_name(value, names):
    for k, v in names.items():
        if v == value:
            return k
    return value  # a value this package has no name for yet


def _fill(struct, options):
    """Set fields of a ctypes options struct from a dict of Python values."""
    names = [f[0] for f in struct._fields_ if f[0] != "struct_size"]
    for key, value in options.items():
        if key == "struct_size":
            raise TypeError("struct_size is set by the binding")
        if key not in names:
            raise TypeError("unknown option %r; options: %s" % (key, ", ".join(names)))
        if key == "energy":
            value = _enum_value(value, _lib.ENERGIES, "energy")
        elif key == "init":
            value = _enum_value(value, _lib.INITS, "init")
        elif key == "solver":
            value = _enum_value(value, _lib.SOLVERS, "solver")
        elif key == "start":
            value = _enum_value(value, _lib.DRAG_STARTS, "start")
        elif key == "seams":
            value = _enum_value(value, _lib.SEAMS, "seams")
        elif key in _BOOL_FIELDS:
            value = 1 if value else 0
        ctype = dict(struct._fields_)[key]
        if ctype is ctypes.c_double:
            if isinstance(value, bool) or not isinstance(value, numbers.Real):
                raise ValueError("option %s: expected a number, got %r" % (key, value))
            value = float(value)
        else:
            if isinstance(value, bool) or not isinstance(value, numbers.Integral):
                raise ValueError("option %s: expected an int, got %r" % (key, value))
            value = int(value)
            if not _arrays.INT32_MIN <= value <= _arrays.INT32_MAX:
                raise ValueError("option %s: %d is outside the C int range" % (key, value))
        setattr(struct, key, value)
    return struct


def _as_dict(struct):
    out = {}
    for key, _ in struct._fields_:
        if key == "struct_size":  # the C version's, set by the binding
            continue
        v = getattr(struct, key)
        if key == "energy":
            v = _enum_name(v, _lib.ENERGIES)
        elif key == "init":
            v = _enum_name(v, _lib.INITS)
        elif key == "solver":
            v = _enum_name(v, _lib.SOLVERS)
        elif key == "start":
            v = _enum_name(v, _lib.DRAG_STARTS)
        elif key == "seams":
            v = _enum_name(v, _lib.SEAMS)
        elif key in _BOOL_FIELDS:
            v = bool(v)
        out[key] = v
    return out


def default_options():
    """The C defaults of scaf_options_default() as a dict (Param options)."""
    return _as_dict(lib.scaf_options_default())


def default_atlas_options():
    """The C defaults of scaf_atlas_options_default() as a dict (Atlas options)."""
    return _as_dict(lib.scaf_atlas_options_default())


def set_threads(n=0):
    """Threads of the per-triangle work (assembly, energies, line search)
    and of the sparse solver's dense kernels for the whole process
    (scaf_set_threads): n >= 1 threads, 0 = every core this process may run
    on. The same count gives the same numbers run after run; different
    counts the same bits only after set_deterministic(True). Returns the
    count in effect (0: the BLAS has no such setting)."""
    if isinstance(n, bool) or not isinstance(n, int) or n < 0:
        raise UsageError("set_threads: n must be an int >= 0 (0 = all cores), not %r" % (n,))
    return lib.scaf_set_threads(n)


def set_deterministic(on=True):
    """The same bits for every thread count (scaf_set_deterministic): the
    factorization's tree is cut into a fixed number of bins instead of one
    per thread; slower, most with one thread. Process-wide."""
    lib.scaf_set_deterministic(1 if on else 0)


# --- progress ----------------------------------------------------------------

@dataclass
class IterationInfo:
    """One finished SCAF iteration (scaf_iteration_info_t). `lambda_` is the
    C field `lambda` (the scaffold weight); phase_seconds maps each phase
    name ("assembly", "factorization", ...) to its share of `seconds`;
    solver is "slim" or "newton" (the step this iteration took) and
    decrement the relative Newton decrement (0 for SLIM steps); criterion
    the estimated relative distance to the minimum (inf until judged)."""

    iteration: int
    energy: float
    energy_before: float
    total_before: float
    total_after: float
    lambda_: float
    step: float
    scaffold_triangles: int
    scaffold_vertices: int
    seconds: float
    phase_seconds: Dict[str, float]
    solver: str
    decrement: float
    criterion: float

    @classmethod
    def _from_c(cls, c):
        return cls(c.iteration, c.energy, c.energy_before, c.total_before, c.total_after, c.lambda_,
                   c.step, c.scaffold_triangles, c.scaffold_vertices, c.seconds,
                   dict(zip(_lib.PHASES, list(c.phase_seconds))), _enum_name(c.solver, _lib.SOLVERS),
                   c.decrement, c.criterion)


@dataclass
class AtlasIterationInfo:
    """One finished atlas iteration (scaf_atlas_iteration_info_t): phase is
    "settle" or "compact"; efficiency and gap are those of the current
    layout (gap is inf with one chart); loop is the SCAF iteration's own
    IterationInfo."""

    phase: Any
    iteration: int
    phase_iteration: int
    energy: float
    efficiency: float
    gap: float
    seconds: float
    loop: IterationInfo

    @classmethod
    def _from_c(cls, c):
        phase = _lib.ATLAS_PHASES[c.phase] if 0 <= c.phase < len(_lib.ATLAS_PHASES) else c.phase
        return cls(phase, c.iteration, c.phase_iteration, c.energy, c.efficiency, c.gap, c.seconds,
                   IterationInfo._from_c(c.loop))


@contextlib.contextmanager
def _deferred_sigint(flag):
    """While a C run is in progress in the main thread with Python's default
    SIGINT handling, Ctrl-C only sets `flag` (the callback then cancels the
    run and KeyboardInterrupt is raised once C has returned): raised inside
    a ctypes callback, before its first line, it would be lost and leave
    the callback's return value undefined."""
    if (threading.current_thread() is not threading.main_thread()
            or signal.getsignal(signal.SIGINT) is not signal.default_int_handler):
        yield
        return
    old = signal.signal(signal.SIGINT, lambda signum, frame: flag.append(signum))
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, old)


def _call_with_progress(cfunc_type, info_type, progress, call):
    """Run call(c_callback) where the callback forwards to `progress`;
    returns the C status, re-raises what the callback raised. Without a
    progress function a callback is installed all the same, so that Ctrl-C
    stops a long run after the current iteration (KeyboardInterrupt)."""
    if progress is not None and not callable(progress):
        raise TypeError("progress must be callable (or None), got %r" % (progress,))
    raised, interrupted = [], []

    def trampoline(info_ptr, _user):
        if raised or interrupted:
            return 1
        try:
            if progress is None:
                return 0
            stop = progress(info_type._from_c(info_ptr.contents))
            # a Ctrl-C during the callback stops the run now, not one iteration later
            return 1 if stop or interrupted else 0
        except BaseException as e:  # noqa: B902 - must not unwind through C
            raised.append(e)
            return 1

    cb = cfunc_type(trampoline)  # kept alive by this frame during the call
    with _deferred_sigint(interrupted):
        status = call(cb)
    if raised:
        raise raised[0]
    if interrupted:
        raise KeyboardInterrupt
    return status


# --- results -----------------------------------------------------------------

def _shape(a):
    return "%d x %d" % (len(a), len(a[0]) if len(a) else 0)


@dataclass(repr=False)
class ParamResult:
    """What scaf.param returns. uv: #UV x 2 float64; ft: #F x 3 int32 (UV
    index of each corner of each input face); energy: the reported E (4 at
    an isometry with the symmetric Dirichlet energy); iterations: finished
    iterations; chart_count: number of charts; stop_reason: why the run
    stopped, "iteration_limit", "converged" (the estimated relative
    distance to the minimum below the tolerance), "zero_step" (no step
    lowers the energy any more: converged, also with tolerance 0), "cancelled",
    "error", or "not_run" before a run; seams: where the charts were cut,
    "input" (the UV seams, or the components), "auto" (automatic seams) or
    "extend" (the UV seams plus cuts): the seams are the edges whose two
    sides have different indices in ft."""

    uv: Any
    ft: Any
    energy: float
    iterations: int
    chart_count: int
    stop_reason: str = "not_run"
    seams: str = "input"

    def __repr__(self):
        return "<scaf.ParamResult uv %s, %d chart(s), energy %.6g after %d iteration(s), stop reason %s>" % (
            _shape(self.uv), self.chart_count, self.energy, self.iterations, self.stop_reason)


@dataclass(repr=False)
class AtlasResult:
    """What scaf.atlas returns. uv: #UV x 2 float64 in [0,1]^2 (certified:
    bijective, every two charts at least `padding` apart); ft: #F x 3
    int32; chart: #F int32 chart id of each input face; chart_distortion:
    E of each chart; energy: E of all charts; efficiency: total chart UV
    area / area of the unit square; min_gap: smallest distance between two
    charts (inf with one chart); iterations: finished iterations per phase
    {"settle": n, "compact": m}; stop_reasons: why each phase stopped
    {"settle": ..., "compact": ...} ("iteration_limit", "converged",
    "zero_step", "noise_floor", "distortion_limit", "packing_stalled",
    "cancelled", "error", "not_run" for a phase that did not take place); stop_reason:
    the reason of the last phase that ran; seams: "input", "auto" or
    "extend" (see ParamResult)."""

    uv: Any
    ft: Any
    chart: Any
    chart_count: int
    chart_distortion: Any
    energy: float
    efficiency: float
    min_gap: float
    padding: float
    iterations: Dict[str, int] = field(default_factory=dict)
    stop_reasons: Dict[str, str] = field(default_factory=dict)
    seams: str = "input"

    @property
    def stop_reason(self):
        compact = self.stop_reasons.get("compact", "not_run")
        return compact if compact != "not_run" else self.stop_reasons.get("settle", "not_run")

    def __repr__(self):
        return ("<scaf.AtlasResult uv %s, %d chart(s), efficiency %.4f, min gap %.6g, energy %.6g, "
                "iterations %s, stop reason %s>" % (_shape(self.uv), self.chart_count, self.efficiency,
                                                   self.min_gap, self.energy, self.iterations, self.stop_reason))


def area_matched_energy(V, F, UV, FT=None):
    """E of the map (V, F) -> UV, its UVs scaled to the surface's area: the
    figure every command and report shows (docs/energy.md; C:
    scaf_area_matched_energy). 4 at an isometry; math.inf when a UV
    triangle is flipped or flat. FT None: F indexes UV too."""
    v = _arrays.matrix(V, "V", 3, False)
    f = _arrays.matrix(F, "F", 3, True)
    uv = _arrays.matrix(UV, "UV", 2, False)
    ft = None
    if FT is not None:
        ft = _arrays.matrix(FT, "FT", 3, True)
        if ft.rows != f.rows:
            raise ValueError("FT has %d rows, F has %d: one row of UV indices per face" % (ft.rows, f.rows))
    elif uv.rows != v.rows:
        raise ValueError("UV has %d rows, V has %d: without FT, one UV per vertex" % (uv.rows, v.rows))
    out = ctypes.c_double()
    st = lib.scaf_area_matched_energy(v.ptr, v.rows, f.ptr, f.rows, uv.ptr, uv.rows,
                                      ft.ptr if ft is not None else None, ctypes.byref(out))
    if st != 0:
        _raise(st, "scaf_area_matched_energy: an index out of range, an empty mesh or a surface "
               "without area")
    return out.value


# --- handles -------------------------------------------------------------------

def _mesh_args(V, F, UV, FT):
    """Checked C buffers (V, F, UV or None, FT or None); ValueError first."""
    if (UV is None) != (FT is None):
        raise ValueError("UV and FT go together: give both or neither")
    v = _arrays.matrix(V, "V", 3, False)
    f = _arrays.matrix(F, "F", 3, True)
    uv = ft = None
    if UV is not None:
        uv = _arrays.matrix(UV, "UV", 2, False)
        ft = _arrays.matrix(FT, "FT", 3, True)
        if ft.rows != f.rows:
            raise ValueError("FT has %d rows, F has %d: one row of UV indices per face" % (ft.rows, f.rows))
    return v, f, uv, ft


class _Handle:
    _prefix = None     # of the C functions
    _defaults = None   # C function giving the default options
    _Options = None    # ctypes struct of the options

    def __init__(self, **options):
        self._h = None
        self._nf = 0  # faces of the current mesh, 0 without one
        # One call at a time: the C context is not thread-safe, and a call
        # from inside a progress callback (close() above all) would act on
        # a context in the middle of its run.
        self._lock = threading.Lock()
        h = getattr(lib, self._prefix + "new")(None)
        if not h:
            raise MemoryError("scaf: out of memory creating a context")
        self._h = h
        self._opts = getattr(lib, self._defaults)()
        if options:
            self.set_options(**options)

    @contextlib.contextmanager
    def _use(self):
        """The C pointer, held for one call (UsageError when closed or busy)."""
        if not self._lock.acquire(blocking=False):
            raise UsageError("this %s is busy: a run is in progress (inside a progress callback, use its "
                             "info argument; across threads, one call at a time)" % type(self).__name__,
                             1, _status_name(1))
        try:
            if not self._h:
                raise UsageError("this %s is closed" % type(self).__name__, 1, _status_name(1))
            yield self._h
        finally:
            self._lock.release()

    def _check(self, status):
        if status != _lib.SCAF_OK:
            msg = getattr(lib, self._prefix + "error")(self._h)
            _raise(status, msg.decode("utf-8", "replace") if msg else "")

    @property
    def options(self):
        """The current options as a dict (a copy)."""
        return _as_dict(self._opts)

    def set_options(self, **options):
        """Change some options (the others keep their values). UsageError,
        with the C message, when a value is out of range."""
        new = self._Options.from_buffer_copy(self._opts)
        _fill(new, options)
        with self._use() as h:
            self._check(getattr(lib, self._prefix + "set_options")(h, ctypes.byref(new)))
        self._opts = new

    def set_mesh(self, V, F, UV=None, FT=None):
        """Set the mesh: V #V x 3 positions, F #F x 3 vertex indices
        (counter-clockwise), optional UV #UV x 2 with FT #F x 3 whose seams
        define the charts. ValueError on a bad shape or dtype (before any C
        call); MeshError naming the chart when a chart cannot be mapped;
        UsageError on an index out of range."""
        v, f, uv, ft = _mesh_args(V, F, UV, FT)
        with self._use() as h:
            self._nf = 0  # the C context has no mesh after a failure
            self._check(getattr(lib, self._prefix + "set_mesh")(
                h, v.ptr, v.rows, f.ptr, f.rows, uv.ptr if uv else None, uv.rows if uv else 0,
                ft.ptr if ft else None))
            self._nf = f.rows
            self._mesh_opts = self._Options.from_buffer_copy(self._opts)  # in force for this mesh

    def close(self):
        """Free the C context now (idempotent). UsageError when called
        during a run (from its progress callback or another thread)."""
        if not self._h:
            return
        with self._use() as h:
            self._h = None
            getattr(lib, self._prefix + "destroy")(h)

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
        return False

    def __del__(self):
        h = getattr(self, "_h", None)  # (None when __init__ failed early)
        if h:
            self._h = None
            try:
                getattr(lib, self._prefix + "destroy")(h)
            except Exception:  # at interpreter exit `lib` may be gone already
                pass


class Param(_Handle):
    """A parametrization context (scaf_param_t): options as keyword
    arguments named like the C fields (energy, init, max_iterations,
    tolerance, box_scale, box_square, box_points_per_side, lambda_ratio,
    min_angle_deg, step_fraction, solver); energy, init and solver take names
    ("symmetric_dirichlet", "arap", "conformal"; "tutte", "harmonic", "mvc";
    "auto", "slim", "newton") or the C int values.

        with scaf.Param(energy="conformal") as p:
            p.set_mesh(V, F)
            p.run(20, progress=lambda info: print(info.iteration, info.energy))
            UV, FT = p.get_uv()
    """

    _prefix = "scaf_param_"
    _defaults = "scaf_options_default"
    _Options = _lib.Options

    def run(self, iterations=0, progress=None):
        """Run up to `iterations` SCAF iterations (<= 0: the option
        max_iterations), stopping early at the tolerance or at a zero step
        (no step lowers the energy: converged, also with tolerance 0);
        stop_reason says which. progress(info: IterationInfo) is called
        after each; a true return raises Cancelled (the map of the last
        iteration stays available)."""
        if isinstance(iterations, bool) or not isinstance(iterations, numbers.Integral):
            raise ValueError("iterations: expected an int, got %r" % (iterations,))
        n = max(min(int(iterations), _arrays.INT32_MAX), -1)
        with self._use() as h:
            status = _call_with_progress(_lib.PARAM_PROGRESS, IterationInfo, progress,
                                         lambda cb: lib.scaf_param_run(h, n, cb, None))
            self._check(status)

    @property
    def energy(self):
        with self._use() as h:
            return lib.scaf_param_energy(h)

    @property
    def chart_count(self):
        with self._use() as h:
            return lib.scaf_param_chart_count(h)

    @property
    def seams_used(self):
        """The seam source set_mesh used: "input" (the UV seams, or the
        components), "auto" or "extend"."""
        with self._use() as h:
            return _enum_name(lib.scaf_param_seams_used(h), _lib.SEAMS)

    @property
    def iterations(self):
        with self._use() as h:
            return lib.scaf_param_iterations(h)

    @property
    def stop_reason(self):
        """Why the last run stopped (see ParamResult.stop_reason)."""
        with self._use() as h:
            return _stop_reason_name(lib.scaf_param_stop_reason(h))

    @property
    def uv_count(self):
        with self._use() as h:
            return lib.scaf_param_uv_count(h)

    def set_handles(self, idx, targets, weight=HANDLE_WEIGHT_DEFAULT):
        """Soft positional constraints from the next run on: UV index
        idx[i] pulled towards targets[i] (n x 2, the units of get_uv's UV),
        weight: the dimensionless ratio of scaf_param_set_handles (default
        1e4: the handles dominate). The map stays bijective whatever the
        targets. An empty idx removes them; set_mesh drops them."""
        n = len(idx)
        i = _arrays.matrix([[int(k)] for k in idx], "idx", 1, True) if n else None
        t = _arrays.matrix(targets, "targets", 2, False) if n else None
        if n and t.rows != n:
            raise ValueError("targets has %d rows, idx has %d: one target per handle" % (t.rows, n))
        with self._use() as h:
            self._check(lib.scaf_param_set_handles(h, n, i.ptr if n else None, t.ptr if n else None,
                                                   float(weight)))

    def get_uv(self):
        """(UV #UV x 2, FT #F x 3) of the current map."""
        with self._use() as h:
            if self._nf <= 0:
                raise UsageError("set_mesh first: there is no map yet", 1, _status_name(1))
            uv = _arrays.Output(lib.scaf_param_uv_count(h), 2, False)
            ft = _arrays.Output(self._nf, 3, True)
            self._check(lib.scaf_param_get_uv(h, uv.ptr, ft.ptr))
            return uv.value(), ft.value()

    def result(self):
        """The current map and its numbers as a ParamResult."""
        uv, ft = self.get_uv()
        return ParamResult(uv, ft, self.energy, self.iterations, self.chart_count, self.stop_reason,
                           self.seams_used)


class Atlas(_Handle):
    """A texture atlas context (scaf_atlas_t): options as keyword arguments
    named like the C fields (padding, energy, init, init_input,
    settle_iterations, settle_tolerance, compact_iterations,
    distortion_tolerance, repack, pack_cells, box_scale, lambda_ratio,
    compact_lambda_ratio). Options take effect at the next set_mesh; run
    once per set_mesh.

        with scaf.Atlas(padding=2 / 512) as a:
            a.set_mesh(V, F, UV, FT)
            a.run()
            r = a.result()
    """

    _prefix = "scaf_atlas_"
    _defaults = "scaf_atlas_options_default"
    _Options = _lib.AtlasOptions

    def run(self, progress=None):
        """Run both phases. progress(info: AtlasIterationInfo) is called
        after each iteration; a true return raises Cancelled (the layout
        of the last iteration stays available, certified)."""
        with self._use() as h:
            status = _call_with_progress(_lib.ATLAS_PROGRESS, AtlasIterationInfo, progress,
                                         lambda cb: lib.scaf_atlas_run(h, cb, None))
            self._check(status)

    @property
    def chart_count(self):
        with self._use() as h:
            return lib.scaf_atlas_chart_count(h)

    @property
    def seams_used(self):
        """The seam source set_mesh used: "input", "auto" or "extend"."""
        with self._use() as h:
            return _enum_name(lib.scaf_atlas_seams_used(h), _lib.SEAMS)

    @property
    def uv_count(self):
        with self._use() as h:
            return lib.scaf_atlas_uv_count(h)

    @property
    def iterations(self):
        """Finished iterations per phase: {"settle": n, "compact": m}."""
        with self._use() as h:
            return {name: lib.scaf_atlas_iterations(h, i) for i, name in enumerate(_lib.ATLAS_PHASES)}

    @property
    def stop_reasons(self):
        """Why each phase of the run stopped: {"settle": ..., "compact": ...}
        (see AtlasResult)."""
        with self._use() as h:
            return {name: _stop_reason_name(lib.scaf_atlas_stop_reason(h, i))
                    for i, name in enumerate(_lib.ATLAS_PHASES)}

    @property
    def energy(self):
        with self._use() as h:
            return lib.scaf_atlas_energy(h)

    def _number(self, fn):
        with self._use() as h:
            x = fn(h)
            if math.isnan(x):  # no mesh (usage), or the certificate failed (a bug)
                msg = lib.scaf_atlas_error(h)
                _raise(8 if self._nf > 0 else 1, msg.decode("utf-8", "replace") if msg else "")
            return x

    @property
    def efficiency(self):
        """Packing efficiency of the normalized, certified layout."""
        return self._number(lib.scaf_atlas_packing_efficiency)

    @property
    def min_gap(self):
        """Smallest distance between two charts in the unit square (inf
        with one chart)."""
        return self._number(lib.scaf_atlas_min_chart_gap)

    def get_uv(self):
        """(UV #UV x 2 in [0,1]^2, FT #F x 3, chart #F) of the current,
        certified layout."""
        with self._use() as h:
            if self._nf <= 0:
                raise UsageError("set_mesh first: there is no layout yet", 1, _status_name(1))
            uv = _arrays.Output(lib.scaf_atlas_uv_count(h), 2, False)
            ft = _arrays.Output(self._nf, 3, True)
            chart = _arrays.Output(self._nf, None, True)
            self._check(lib.scaf_atlas_get_uv(h, uv.ptr, ft.ptr, chart.ptr))
            return uv.value(), ft.value(), chart.value()

    def chart_distortion(self):
        """E of each chart (#charts values)."""
        with self._use() as h:
            if self._nf <= 0:
                raise UsageError("set_mesh first: there are no charts yet", 1, _status_name(1))
            e = _arrays.Output(lib.scaf_atlas_chart_count(h), None, False)
            self._check(lib.scaf_atlas_chart_distortion(h, e.ptr))
            return e.value()

    def result(self):
        """The current layout and its numbers as an AtlasResult."""
        uv, ft, chart = self.get_uv()
        return AtlasResult(uv, ft, chart, self.chart_count, self.chart_distortion(), self.energy,
                           self.efficiency, self.min_gap, self._mesh_opts.padding, self.iterations,
                           self.stop_reasons, self.seams_used)


# --- one-call functions ----------------------------------------------------------

def param(V, F, UV=None, FT=None, *, energy="symmetric_dirichlet", init="mvc", iterations=None,
          progress=None, **options):
    """Bijective parametrization of a mesh with SCAF (scaf_param_*).

    V #V x 3 positions, F #F x 3 vertex indices (counter-clockwise); with
    UV #UV x 2 and FT #F x 3 the charts are the pieces cut along the UV
    seams (the UV values are not used), else one chart per connected
    component; seams="default" (cut open automatically what is not a disk:
    a closed mesh, handles), "input", "auto" or "extend" (see scaf_seams). energy: "symmetric_dirichlet" | "arap" | "conformal";
    init: "mvc" | "tutte" | "harmonic"; iterations: cap (default: the C default,
    50); more options as keywords (see Param). progress(IterationInfo)
    after each iteration, true to cancel. Returns a ParamResult; raises
    ValueError (bad arrays), MeshError, UsageError, NumericError,
    Cancelled (with .result: the map of the last finished iteration)."""
    options.update(energy=energy, init=init)
    if iterations is not None:
        options["max_iterations"] = iterations
    with Param(**options) as p:
        p.set_mesh(V, F, UV, FT)
        try:
            p.run(0, progress)
        except Cancelled as e:
            e.result = p.result()
            raise
        return p.result()


def atlas(V, F, UV=None, FT=None, *, padding=None, resolution=None, padding_texels=None,
          energy="symmetric_dirichlet", init="tutte", progress=None, **options):
    """Texture atlas of all charts in the unit square (scaf_atlas_*).

    Charts as in scaf.param. The padding (minimum distance between two
    charts in [0,1]^2) is `padding`, or `padding_texels / resolution`
    (e.g. resolution=1024, padding_texels=4, the default). More options
    as keywords (see Atlas: init_input=True starts from the given UVs,
    settle_iterations, compact_iterations, ...). progress(AtlasIterationInfo)
    after each iteration, true to cancel. Returns an AtlasResult; raises
    like scaf.param (Cancelled carries .result: the certified layout of
    the last finished iteration)."""
    if padding_texels is not None or resolution is not None:
        if padding is not None:
            raise ValueError("give either padding or resolution + padding_texels, not both")
        if padding_texels is None or resolution is None:
            raise ValueError("padding_texels and resolution go together")
        if not resolution >= 1 or not padding_texels >= 0:
            raise ValueError("resolution must be >= 1 and padding_texels >= 0")
        padding = padding_texels / resolution
    if padding is not None:
        options["padding"] = padding
    options.update(energy=energy, init=init)
    with Atlas(**options) as a:
        a.set_mesh(V, F, UV, FT)
        try:
            a.run(progress)
        except Cancelled as e:
            e.result = a.result()
            raise
        return a.result()
