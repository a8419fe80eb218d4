"""python/tests/test_scaf: the Python binding against the build's libscaf.so.

Run by the ctest python/test_python (run_tests.sh) with SCAF_LIBRARY,
SCAF_BINARY (the `scaf` program, used to generate meshes), SCAF_LAYOUT_PROGRAM
(prints the C struct layouts) and SCAF_TEST_TMPDIR set. Every property of a
result is recomputed here in Python from the arrays (signed UV areas, unit
square, charts kept, packing efficiency, chart gap, per-chart distortion)
rather than trusted from the library's own numbers.
"""

import ctypes
import math
import os
import subprocess
import sys
import tempfile
import unittest

import scaf
from scaf import _arrays, _lib

np = _arrays.np
BINARY = os.environ.get("SCAF_BINARY")
TMP = os.environ.get("SCAF_TEST_TMPDIR") or tempfile.gettempdir()


def gen(name, size=None):
    """Path of an OBJ written by `scaf gen NAME`."""
    if not BINARY:
        raise unittest.SkipTest("SCAF_BINARY not set")
    d = tempfile.mkdtemp(prefix="py-", dir=TMP)
    path = os.path.join(d, "%s.obj" % name)
    cmd = [BINARY, "gen", name, "-o", path] + (["--size", str(size)] if size else [])
    subprocess.run(cmd, check=True)
    return path


def rows(a):
    return a.tolist() if hasattr(a, "tolist") else a


def signed_areas(UV, FT):
    UV, FT = rows(UV), rows(FT)
    out = []
    for a, b, c in FT:
        (u0, v0), (u1, v1), (u2, v2) = UV[a], UV[b], UV[c]
        out.append(0.5 * ((u1 - u0) * (v2 - v0) - (u2 - u0) * (v1 - v0)))
    return out


def dirichlet_parts(V, F, UV, FT, faces=None):
    """(A, B) with A = sum_f A_f |J_f|^2 / sum_f A_f and B = sum_f A_f
    |J_f^-1|^2 / sum_f A_f over `faces` (all: None), A_f the 3D area, J_f
    the Jacobian of the UV map. Scaling the UVs by s gives s^2 A + B / s^2."""
    V, F, UV, FT = rows(V), rows(F), rows(UV), rows(FT)
    a_sum = b_sum = den = 0.0
    for f in (range(len(F)) if faces is None else faces):
        p0, p1, p2 = (V[i] for i in F[f])
        e1 = [p1[k] - p0[k] for k in range(3)]
        e2 = [p2[k] - p0[k] for k in range(3)]
        l1 = math.sqrt(sum(x * x for x in e1))
        x2 = sum(e1[k] * e2[k] for k in range(3)) / l1
        y2 = math.sqrt(max(sum(x * x for x in e2) - x2 * x2, 0.0))
        area = 0.5 * l1 * y2
        (u0, v0), (u1, v1), (u2, v2) = (UV[i] for i in FT[f])
        # J = [d1 d2] X^-1 with X = [[l1, x2], [0, y2]] the triangle in its plane
        a, b, c, d = u1 - u0, u2 - u0, v1 - v0, v2 - v0
        j11, j12 = a / l1, (b - a * x2 / l1) / y2
        j21, j22 = c / l1, (d - c * x2 / l1) / y2
        fro = j11 * j11 + j12 * j12 + j21 * j21 + j22 * j22
        det = j11 * j22 - j12 * j21
        a_sum += area * fro
        b_sum += area * fro / (det * det)  # |J^-1|^2 of a 2 x 2 J
        den += area
    return a_sum / den, b_sum / den


def symmetric_dirichlet(V, F, UV, FT, faces=None):
    """sum_f A_f (|J|^2 + |J^-1|^2) / sum_f A_f: the energy E the library
    reports, recomputed."""
    a, b = dirichlet_parts(V, F, UV, FT, faces)
    return a + b


def input_charts(F, FT):
    """Chart label per face of a mesh with UVs: faces sharing an edge with
    the same UV indices on both sides are in one chart."""
    F, FT = rows(F), rows(FT)
    parent = list(range(len(F)))

    def find(i):
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    seen = {}
    for f, (tri, uvs) in enumerate(zip(F, FT)):
        for k in range(3):
            a, b = tri[k], tri[(k + 1) % 3]
            ta, tb = uvs[k], uvs[(k + 1) % 3]
            key = (min(a, b), max(a, b))
            side = (ta, tb) if a < b else (tb, ta)
            if key in seen:
                g, gside = seen[key]
                if gside == side:
                    parent[find(f)] = find(g)
            else:
                seen[key] = (f, side)
    return [find(f) for f in range(len(F))]


def boundary_segments(FT, chart):
    """{chart: [(uv index, uv index), ...]} boundary edges of each chart."""
    count = {}
    for f, t in enumerate(rows(FT)):
        for k in range(3):
            e = (min(t[k], t[(k + 1) % 3]), max(t[k], t[(k + 1) % 3]))
            count[e] = count.get(e, (0, chart[f]))
            count[e] = (count[e][0] + 1, chart[f])
    out = {}
    for e, (n, c) in count.items():
        if n == 1:
            out.setdefault(c, []).append(e)
    return out


def point_segment(p, a, b):
    dx, dy = b[0] - a[0], b[1] - a[1]
    t = ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / (dx * dx + dy * dy)
    t = min(1.0, max(0.0, t))
    return math.hypot(p[0] - a[0] - t * dx, p[1] - a[1] - t * dy)


def min_chart_gap(UV, FT, chart):
    """Smallest distance between boundary segments of two different charts
    (segments of different charts never cross in a valid atlas, so the
    distance is attained at an endpoint)."""
    UV = rows(UV)
    seg = boundary_segments(FT, rows(chart))
    charts = sorted(seg)
    best = math.inf
    for i, ci in enumerate(charts):
        for cj in charts[i + 1:]:
            for a, b in seg[ci]:
                for c, d in seg[cj]:
                    pa, pb, pc, pd = UV[a], UV[b], UV[c], UV[d]
                    best = min(best, point_segment(pa, pc, pd), point_segment(pb, pc, pd),
                               point_segment(pc, pa, pb), point_segment(pd, pa, pb))
    return best


class LibraryTest(unittest.TestCase):
    def test_struct_layout_matches_c(self):
        prog = os.environ.get("SCAF_LAYOUT_PROGRAM")
        if not prog:
            self.skipTest("SCAF_LAYOUT_PROGRAM not set")
        out = subprocess.run([prog], check=True, capture_output=True, text=True).stdout.split("\n")
        sizes, fields, enums = {}, {}, {}
        for line in filter(None, out):
            t = line.split()
            if t[0] == "enum":
                enums[t[1]] = int(t[2])
            elif t[1] == "sizeof":
                sizes[t[0]] = int(t[2])
            else:
                fields.setdefault(t[0], []).append((t[1], int(t[2]), int(t[3])))
        self.assertEqual(set(sizes), set(_lib.STRUCTS))
        for cname, cls in _lib.STRUCTS.items():
            self.assertEqual(ctypes.sizeof(cls), sizes[cname], cname)
            mine = [(n.rstrip("_"), getattr(cls, n).offset, getattr(cls, n).size) for n, _ in cls._fields_]
            self.assertEqual(mine, fields[cname], cname)
        self.assertEqual(enums["SCAF_PHASE_COUNT"], _lib.PHASE_COUNT)
        self.assertEqual(enums["SCAF_ERR_INTERNAL"], max(_lib.STATUS_NAMES))
        self.assertEqual(enums["SCAF_ERR_CANCELLED"], _lib.SCAF_ERR_CANCELLED)
        self.assertEqual(enums["SCAF_ENERGY_CONFORMAL"], _lib.ENERGIES["conformal"])
        self.assertEqual(enums["SCAF_INIT_HARMONIC"], _lib.INITS["harmonic"])
        self.assertEqual(enums["SCAF_INIT_MVC"], _lib.INITS["mvc"])
        self.assertEqual(enums["SCAF_ATLAS_COMPACT"], len(_lib.ATLAS_PHASES) - 1)
        self.assertEqual(enums["SCAF_VOLUME_ITERATION"], len(_lib.VOLUME_PHASES) - 1)
        self.assertEqual(enums["SCAF_REPORT_MESSAGE_MAX"], _lib.REPORT_MESSAGE_MAX)
        self.assertEqual(enums["SCAF_SURFACE_FIRST_PAIRS"], _lib.SURFACE_FIRST_PAIRS)
        self.assertEqual(enums["sizeof"], ctypes.sizeof(_lib.c_enum))

    def test_version_is_the_programs(self):
        if not BINARY:
            self.skipTest("SCAF_BINARY not set")
        out = subprocess.run([BINARY, "--version"], check=True, capture_output=True, text=True).stdout
        self.assertEqual(out.strip(), "scaf " + scaf.__version__)
        if os.environ.get("SCAF_LIBRARY"):  # unset for an installed package (tests/install)
            self.assertTrue(os.path.samefile(scaf.library_path, os.environ["SCAF_LIBRARY"]))

    def test_missing_library_is_a_clear_import_error(self):
        env = dict(os.environ, SCAF_LIBRARY=os.path.join(TMP, "no-such-libscaf.so"))
        p = subprocess.run([sys.executable, "-c", "import scaf"], env=env, capture_output=True, text=True)
        self.assertNotEqual(p.returncode, 0)
        self.assertIn("ImportError", p.stderr)
        self.assertIn("SCAF_LIBRARY", p.stderr)
        self.assertIn("no-such-libscaf.so does not exist", p.stderr)

    def test_defaults_come_from_c(self):
        d = scaf.default_options()
        self.assertEqual(d["energy"], "symmetric_dirichlet")
        self.assertGreater(d["max_iterations"], 0)
        a = scaf.default_atlas_options()
        self.assertAlmostEqual(a["padding"], 4 / 1024)
        self.assertIs(a["repack"], True)


class ThreadsTest(unittest.TestCase):
    def test_set_threads(self):
        V, F, _, _ = scaf.read_obj(gen("hemisphere", 60))
        try:
            self.assertEqual(scaf.set_threads(2), 2)
            a = rows(scaf.param(V, F, iterations=3).uv)
            b = rows(scaf.param(V, F, iterations=3).uv)
            self.assertEqual(a, b)  # bit for bit, same count
            self.assertEqual(scaf.set_threads(1), 1)
            c = rows(scaf.param(V, F, iterations=3).uv)
            self.assertEqual(c, rows(scaf.param(V, F, iterations=3).uv))
            for bad in (-1, True, 1.5, "2"):
                with self.assertRaises(scaf.UsageError):
                    scaf.set_threads(bad)
        finally:
            scaf.set_threads(1)  # run_tests.sh runs with OPENBLAS_NUM_THREADS=1


class ParamTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.V, cls.F, cls.UV, cls.FT = scaf.read_obj(gen("hemisphere", 8))

    def check_map(self, r, nf):
        self.assertEqual(len(r.ft), nf)
        self.assertTrue(all(len(t) == 3 for t in rows(r.ft)))
        self.assertTrue(all(0 <= i < len(r.uv) for t in rows(r.ft) for i in t))
        areas = signed_areas(r.uv, r.ft)
        self.assertGreater(min(areas), 0.0, "a flipped or degenerate UV triangle")

    def test_param_disk(self):
        seen = []
        r = scaf.param(self.V, self.F, iterations=8, progress=seen.append)
        self.assertIsInstance(r, scaf.ParamResult)
        self.check_map(r, len(self.F))
        self.assertEqual(r.chart_count, 1)
        self.assertTrue(1 <= r.iterations <= 8)
        self.assertEqual([i.iteration for i in seen], list(range(1, r.iterations + 1)))
        self.assertEqual(seen[-1].energy, r.energy)
        self.assertTrue(all(i.total_after <= i.total_before for i in seen))
        self.assertEqual(set(seen[0].phase_seconds), set(_lib.PHASES))
        # the energy the library reports, recomputed from the arrays
        self.assertAlmostEqual(symmetric_dirichlet(self.V, self.F, r.uv, r.ft), r.energy, delta=1e-9 * r.energy)
        self.assertGreaterEqual(r.energy, 4.0)
        if np is not None:
            self.assertEqual(r.uv.dtype, np.float64)
            self.assertEqual(r.ft.dtype, np.int32)
            self.assertEqual(r.uv.shape[1], 2)

    def test_area_matched_energy(self):
        r = scaf.param(self.V, self.F, iterations=8)
        e = scaf.area_matched_energy(self.V, self.F, r.uv, r.ft)
        self.assertGreaterEqual(e, 4.0)
        # scale-free: the map shrunk into a small square reads the same
        uv = [[0.001 * a + 3.0, 0.001 * b - 1.0] for a, b in rows(r.uv)]
        self.assertAlmostEqual(scaf.area_matched_energy(self.V, self.F, uv, r.ft), e, delta=1e-9 * e)
        # near the optimizer's E for a converged disk, not 1e6 times it
        self.assertLess(abs(e - r.energy), 0.05 * r.energy)
        mirrored = [[-a, b] for a, b in rows(r.uv)]
        self.assertEqual(scaf.area_matched_energy(self.V, self.F, mirrored, r.ft), math.inf)
        with self.assertRaises(scaf.UsageError):
            scaf.area_matched_energy(self.V, [[0, 1, 10 ** 6]], r.uv, [[0, 1, 2]])

    def test_handles_pull_a_vertex_bijectively(self):
        with scaf.Param() as p:
            p.set_mesh(self.V, self.F)
            uv0, _ = p.get_uv()
            target = [float(uv0[0][0]) + 0.5, float(uv0[0][1]) + 0.25]
            p.set_handles([0], [target])
            p.run(10)
            uv, ft = p.get_uv()
            self.check_map(p.result(), len(self.F))
            self.assertLess(math.hypot(uv[0][0] - target[0], uv[0][1] - target[1]), 0.05)
            p.set_handles([], [])
            with self.assertRaises(scaf.UsageError):
                p.set_handles([10 ** 6], [target])
            with self.assertRaises(ValueError):
                p.set_handles([0, 1], [target])

    def test_lists_and_other_dtypes_give_the_same_map(self):
        if np is None:
            self.skipTest("numpy not available")
        a = scaf.param(self.V, self.F, iterations=3)
        b = scaf.param(self.V.tolist(), self.F.tolist(), iterations=3)
        c = scaf.param(self.V.astype(np.float32).astype(np.float64), self.F.astype(np.uint64), iterations=3)
        d = scaf.param(np.asfortranarray(self.V), self.F.astype(np.float64), iterations=3)
        self.assertTrue(np.array_equal(a.uv, b.uv) and np.array_equal(a.ft, b.ft))
        self.assertTrue(np.array_equal(a.uv, d.uv))
        self.check_map(c, len(self.F))

    def test_energies_and_inits(self):
        for energy in ("conformal", "arap"):
            r = scaf.param(self.V, self.F, energy=energy, iterations=3)
            self.check_map(r, len(self.F))
        for init in ("tutte", "mvc"):
            self.check_map(scaf.param(self.V, self.F, init=init, iterations=2), len(self.F))
        r1 = scaf.param(self.V, self.F, init="harmonic", iterations=2)
        r2 = scaf.param(self.V, self.F, init=_lib.INITS["harmonic"], iterations=2)
        self.assertEqual(rows(r1.uv), rows(r2.uv))
        # an int the C enum does not have is passed through and refused by C
        with self.assertRaises(scaf.UsageError) as cm:
            scaf.param(self.V, self.F, init=99)
        self.assertIn("init", str(cm.exception))

    def test_handle_and_context_manager(self):
        with scaf.Param(max_iterations=4) as p:
            self.assertEqual(p.chart_count, 0)
            p.set_mesh(self.V, self.F)
            p.run(2)
            self.assertEqual(p.iterations, 2)
            p.run()  # options' cap
            self.assertTrue(2 < p.iterations <= 6)
            uv, ft = p.get_uv()
            self.assertEqual(len(uv), p.uv_count)
            p.set_options(energy="conformal")
            self.assertEqual(p.options["energy"], "conformal")
        with self.assertRaises(scaf.UsageError):
            p.run()
        p.close()  # idempotent

    def test_unknown_and_bad_options(self):
        with self.assertRaises(TypeError):
            scaf.param(self.V, self.F, no_such_option=1)
        with self.assertRaises(ValueError):
            scaf.param(self.V, self.F, energy="nope")
        with self.assertRaises(scaf.UsageError) as cm:
            scaf.param(self.V, self.F, step_fraction=2.0)
        self.assertIn("step_fraction", str(cm.exception))
        with self.assertRaises(ValueError):
            scaf.Param(max_iterations="ten")

    def test_cancel(self):
        with self.assertRaises(scaf.Cancelled) as cm:
            scaf.param(self.V, self.F, iterations=20, progress=lambda info: info.iteration >= 3)
        e = cm.exception
        self.assertEqual(e.status, 7)
        self.assertEqual(e.result.iterations, 3)
        self.check_map(e.result, len(self.F))

    def test_stop_reason(self):
        V, F, _, _ = scaf.read_obj(gen("hemisphere", 4))
        self.assertEqual(scaf.param(V, F, iterations=2).stop_reason, "iteration_limit")
        self.assertEqual(scaf.param(V, F, iterations=100, tolerance=1e-2, solver="slim").stop_reason, "converged")
        self.assertEqual(scaf.param(V, F, iterations=100, tolerance=1e-2).stop_reason, "converged")
        # tolerance 0 does not mean "all iterations": a converged map ends
        # the run with a zero step, and the result says so
        seen = []
        r = scaf.param(V, F, iterations=1000, tolerance=0.0, progress=seen.append)
        self.assertEqual(r.stop_reason, "zero_step")
        self.assertLess(r.iterations, 1000)
        self.assertEqual(seen[-1].step, 0.0)
        self.assertIn("zero_step", repr(r))
        with self.assertRaises(scaf.Cancelled) as cm:
            scaf.param(V, F, iterations=10, progress=lambda info: info.iteration == 2)
        self.assertEqual(cm.exception.result.stop_reason, "cancelled")
        with scaf.Param() as p:
            p.set_mesh(V, F)
            self.assertEqual(p.stop_reason, "not_run")
            p.run(1)
            self.assertEqual(p.stop_reason, "iteration_limit")

    def test_exception_in_callback_cancels_and_is_reraised(self):
        calls = []

        def bad(info):
            calls.append(info.iteration)
            if info.iteration == 2:
                raise ZeroDivisionError("from the callback")

        with scaf.Param() as p:
            p.set_mesh(self.V, self.F)
            with self.assertRaises(ZeroDivisionError):
                p.run(10, progress=bad)
            self.assertEqual(calls, [1, 2])
            self.assertEqual(p.iterations, 2)  # the run stopped there
            uv, ft = p.get_uv()  # and its map is still there and valid
            self.assertGreater(min(signed_areas(uv, ft)), 0.0)
            p.run(1)
            self.assertEqual(p.iterations, 3)

    def test_ctrl_c_stops_a_run(self):
        # Deterministic: the SIGINT is raised from inside the progress call of
        # iteration 3 (signal.raise_signal runs Python's handler before it
        # returns), never by a timer racing the run.
        import signal

        V, F, _, _ = scaf.read_obj(gen("hemisphere", 30))

        def ctrl_c_at(k, then=None):
            def progress(info):
                if info.iteration == k:
                    signal.raise_signal(signal.SIGINT)
                return then
            return progress

        for then in (None, False, 0):
            with scaf.Param(tolerance=0.0, max_iterations=300) as p:
                p.set_mesh(V, F)
                with self.assertRaises(KeyboardInterrupt):
                    p.run(progress=ctrl_c_at(3, then))
                self.assertEqual(p.iterations, 3)  # stopped after the interrupted iteration
                self.assertIs(signal.getsignal(signal.SIGINT), signal.default_int_handler)
                uv, ft = p.get_uv()  # the map of the last iteration
                self.assertGreater(min(signed_areas(uv, ft)), 0.0)
        with scaf.Atlas() as a:
            a.set_mesh(V, F)
            with self.assertRaises(KeyboardInterrupt):
                a.run(progress=ctrl_c_at(2))
            self.assertIs(signal.getsignal(signal.SIGINT), signal.default_int_handler)

    def test_handle_is_refused_inside_its_own_callback(self):
        with scaf.Param() as p:
            p.set_mesh(self.V, self.F)
            with self.assertRaises(scaf.UsageError) as cm:
                p.run(5, progress=lambda info: p.close())  # would free a running context
            self.assertIn("busy", str(cm.exception))
            self.assertEqual(p.iterations, 1)  # cancelled after the first call
            p.run(1)  # still open and usable
            self.assertEqual(p.iterations, 2)

    def test_c_context_freed_deterministically(self):
        from scaf import _core

        real, destroyed = _core.lib, []

        class Spy:
            def __getattr__(self, name):
                fn = getattr(real, name)
                if name.endswith("_destroy"):
                    return lambda h: (destroyed.append(name), fn(h))[1]
                return fn

        _core.lib = Spy()
        try:
            with scaf.Param() as p:
                p.set_mesh(self.V, self.F)
                self.assertEqual(destroyed, [])
            self.assertEqual(destroyed, ["scaf_param_destroy"])
            p.close()  # idempotent
            self.assertEqual(len(destroyed), 1)
            a = scaf.Atlas()
            del a  # CPython frees at once
            self.assertEqual(destroyed, ["scaf_param_destroy", "scaf_atlas_destroy"])
            scaf.param(self.V, self.F, iterations=1)
            with self.assertRaises(scaf.MeshError):
                scaf.param([[0, 0, 0], [1, 0, 0], [2, 0, 0]], [[0, 1, 2]])  # degenerate
            self.assertEqual(destroyed[2:], ["scaf_param_destroy"] * 2)
        finally:
            _core.lib = real

    def test_two_threads_two_contexts(self):
        import threading

        ref = scaf.param(self.V, self.F, iterations=4)
        out = [None, None]

        def work(k):
            out[k] = scaf.param(self.V, self.F, iterations=4)

        threads = [threading.Thread(target=work, args=(k,)) for k in range(2)]
        for t in threads:
            t.start()
        for t in threads:
            t.join()
        # Not bit for bit: concurrent runs may differ from a sequential one
        # in the last digits (CHOLMOD's OpenMP regions are serialized through
        # libgomp's process-wide max-active-levels, which the other thread
        # may have restored meanwhile; see src/opt/cholmod_solver.c).
        for r in out:
            self.assertEqual(len(r.uv), len(ref.uv))
            self.assertGreater(min(signed_areas(r.uv, r.ft)), 0.0)
            self.assertAlmostEqual(r.energy, ref.energy, delta=1e-6 * ref.energy)


class InputTest(unittest.TestCase):
    V = [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0.5]]
    F = [[0, 1, 2], [0, 2, 3]]

    def calls_of(self, fn):
        """Names of the C functions `fn` calls, and its exception."""
        from scaf import _core

        real, called = _core.lib, []

        class Spy:
            def __getattr__(self, name):
                called.append(name)
                return getattr(real, name)

        _core.lib = Spy()
        try:
            fn()
        except Exception as e:  # noqa: BLE001
            return called, e
        finally:
            _core.lib = real
        return called, None

    def test_bad_shapes_and_dtypes_raise_value_error_before_c(self):
        bad = [
            ([[0, 0], [1, 0], [1, 1]], self.F),        # V not n x 3
            (self.V, [[0, 1, 2, 3]]),                   # F not n x 3
            (self.V, [[0, 1], [1, 2]]),
            (self.V, [[0, 1.5, 2]]),                    # non-integer index
            ([[0, 0, 0], [1, 0], [1, 1, 0]], self.F),  # ragged
            (self.V, []),                               # no faces
            ([["a", "b", "c"]] * 4, self.F),            # not numbers
            (self.V, [[0, 1, 2 ** 40]]),                # outside int32
            (42, self.F),
        ]
        if np is not None:
            bad += [
                (np.zeros((4, 3), dtype=complex), self.F),
                (np.zeros((2, 4, 3)), self.F),
                (self.V, np.array([[0, 1, 2]], dtype=bool)),
                (np.array(self.V, dtype=object), self.F),
            ]
        for V, F in bad:
            for fn in (lambda: scaf.param(V, F), lambda: scaf.atlas(V, F)):
                called, e = self.calls_of(fn)
                self.assertIsInstance(e, ValueError, (V, F))
                self.assertNotIsInstance(e, scaf.Error, (V, F))
                self.assertFalse([n for n in called if "set_mesh" in n or "_run" in n], called)

    def test_uv_and_ft_go_together(self):
        for UV, FT in (([[0, 0]], None), (None, [[0, 0, 0]])):
            with self.assertRaises(ValueError):
                scaf.atlas(self.V, self.F, UV, FT)
        with self.assertRaises(ValueError):  # FT must have one row per face
            scaf.atlas(self.V, self.F, [[0, 0], [1, 0], [1, 1], [0, 1]], [[0, 1, 2]])

    def test_index_out_of_range_is_a_usage_error_naming_the_face(self):
        with self.assertRaises(scaf.UsageError) as cm:
            scaf.param(self.V, [[0, 1, 2], [0, 2, 7]])
        self.assertIsInstance(cm.exception, ValueError)
        self.assertIn("face 1", str(cm.exception))

    def test_small_list_mesh(self):
        r = scaf.param(self.V, self.F, iterations=2)
        self.assertGreater(min(signed_areas(r.uv, r.ft)), 0)

    def test_closed_chart_is_a_mesh_error_naming_the_chart(self):
        # with the components as they are (seams="input")
        V, F, _, _ = scaf.read_obj(gen("tetrahedron"))
        for fn in (scaf.param, scaf.atlas):
            with self.assertRaises(scaf.MeshError) as cm:
                fn(V, F, seams="input")
            self.assertIn("chart 0", str(cm.exception))
            self.assertIn("closed", str(cm.exception))
            self.assertEqual(cm.exception.status, 4)
        # a disk, then a closed tetrahedron far away: chart 1 is named
        V2 = rows(self.V) + [[x + 10, y, z] for x, y, z in rows(V)]
        F2 = rows(self.F) + [[a + 4, b + 4, c + 4] for a, b, c in rows(F)]
        with self.assertRaises(scaf.MeshError) as cm:
            scaf.atlas(V2, F2, seams="input")
        self.assertIn("chart 1", str(cm.exception))

    def test_closed_mesh_without_uvs_is_cut_by_default(self):
        # scaf.atlas(V, F) and scaf.param(V, F) on a closed mesh, no UVs
        V, F, _, _ = scaf.read_obj(gen("icosphere", 3))
        p = scaf.param(V, F, iterations=5)
        self.assertEqual(p.seams, "auto")
        self.assertEqual(p.chart_count, 1)
        self.assertGreater(min(signed_areas(p.uv, p.ft)), 0)
        self.assertGreater(len(p.uv), len(rows(V)))  # seam vertices split
        a = scaf.atlas(V, F, settle_iterations=5, compact_iterations=3)
        self.assertEqual(a.seams, "auto")
        self.assertGreater(min(signed_areas(a.uv, a.ft)), 0)
        self.assertEqual(len(a.chart), len(rows(F)))

    def test_read_obj_errors(self):
        d = tempfile.mkdtemp(prefix="py-", dir=TMP)
        path = os.path.join(d, "bad.obj")
        with open(path, "w") as fp:
            fp.write("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n")
        with self.assertRaises(scaf.InputError) as cm:
            scaf.read_obj(path)
        self.assertIn("bad.obj:4", str(cm.exception))
        with self.assertRaises(scaf.InputError):
            scaf.read_obj(os.path.join(d, "missing.obj"))


class AtlasTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.V, cls.F, cls.UV, cls.FT = scaf.read_obj(gen("cubesphere", 6))
        cls.seen = []
        cls.r = scaf.atlas(cls.V, cls.F, cls.UV, cls.FT, resolution=512, padding_texels=2,
                           progress=cls.seen.append)

    def test_cube_sphere_atlas(self):
        r, nf = self.r, len(self.F)
        self.assertIsInstance(r, scaf.AtlasResult)
        self.assertEqual(r.chart_count, 6)
        self.assertEqual(r.padding, 2 / 512)
        uv = rows(r.uv)
        self.assertTrue(all(0.0 <= x <= 1.0 for p in uv for x in p), "UV outside [0,1]^2")
        self.assertGreater(min(signed_areas(r.uv, r.ft)), 0.0)
        # every face keeps its chart: the input seams and the output charts
        # are the same partition of the faces
        chart = rows(r.chart)
        self.assertEqual(len(chart), nf)
        pairs = set(zip(input_charts(self.F, self.FT), chart))
        self.assertEqual(len(pairs), 6)
        self.assertEqual(len({a for a, _ in pairs}), 6)
        self.assertEqual(len({b for _, b in pairs}), 6)
        self.assertEqual(set(chart), set(range(6)))
        # efficiency = total UV area / unit square, recomputed
        self.assertAlmostEqual(sum(signed_areas(r.uv, r.ft)), r.efficiency, delta=1e-9)
        self.assertGreater(r.efficiency, 0.3)
        # the chart gap, recomputed by brute force over boundary segments
        gap = min_chart_gap(r.uv, r.ft, chart)
        self.assertAlmostEqual(gap, r.min_gap, delta=1e-12)
        self.assertGreaterEqual(gap, r.padding * (1 - 1e-9))
        # per-chart distortion and total energy, recomputed. The library
        # measures them before the uniform scaling into the unit square, so
        # one unknown factor s must explain all seven numbers: E(s) = s^2 A
        # + B / s^2. Solve t = s^2 from the chart that determines it best,
        # check every other number with it.
        dist = rows(r.chart_distortion)
        self.assertEqual(len(dist), 6)
        parts = [dirichlet_parts(self.V, self.F, r.uv, r.ft, [f for f in range(nf) if chart[f] == c])
                 for c in range(6)]
        values = list(zip(parts, dist)) + [(dirichlet_parts(self.V, self.F, r.uv, r.ft), r.energy)]
        (a, b), e = max(values, key=lambda v: (v[1] ** 2 - 4 * v[0][0] * v[0][1]) / v[1] ** 2)
        disc = math.sqrt(max(e * e - 4 * a * b, 0.0))
        fits = []
        for t in ((e + disc) / (2 * a), (e - disc) / (2 * a)):
            fits.append(max(abs(a_ * t + b_ / t - e_) / e_ for (a_, b_), e_ in values))
        self.assertLess(min(fits), 1e-7, "no single scale explains the reported energies")
        self.assertTrue(all(e_ >= 4.0 for e_ in dist))
        # the progress calls: phases in order, counted as reported
        its = r.iterations
        self.assertEqual(len(self.seen), its["settle"] + its["compact"])
        self.assertEqual([i.iteration for i in self.seen], list(range(1, len(self.seen) + 1)))
        self.assertEqual([i.phase for i in self.seen], ["settle"] * its["settle"] + ["compact"] * its["compact"])

    def test_lists_in_lists_out(self):
        r = scaf.atlas(rows(self.V), rows(self.F), rows(self.UV), rows(self.FT), padding=2 / 512)
        self.assertEqual(rows(r.uv), rows(self.r.uv))
        self.assertEqual(rows(r.chart), rows(self.r.chart))

    def test_components_without_uvs_are_charts(self):
        V, F, _, _ = scaf.read_obj(gen("hemisphere", 4))
        V2 = rows(V) + [[x + 5.0, y, z] for x, y, z in rows(V)]
        F2 = rows(F) + [[a + len(V), b + len(V), c + len(V)] for a, b, c in rows(F)]
        # seams="input": the components are the charts (automatic seams would segment them)
        r = scaf.atlas(V2, F2, padding=0.0, compact_iterations=3, seams="input")
        self.assertEqual(r.chart_count, 2)
        self.assertEqual(rows(r.chart), [0] * len(F) + [1] * len(F))
        self.assertGreater(min(signed_areas(r.uv, r.ft)), 0.0)
        self.assertGreater(min_chart_gap(r.uv, r.ft, rows(r.chart)), 0.0)

    def test_init_input_from_a_previous_result(self):
        r = scaf.atlas(self.V, self.F, self.r.uv, self.r.ft, init_input=True, compact_iterations=3)
        self.assertEqual(r.chart_count, 6)
        self.assertGreater(min(signed_areas(r.uv, r.ft)), 0.0)
        self.assertEqual(len(set(zip(rows(self.r.chart), rows(r.chart)))), 6)  # same partition

    def test_padding_arguments(self):
        with self.assertRaises(ValueError):
            scaf.atlas(self.V, self.F, self.UV, self.FT, padding=0.01, resolution=1024, padding_texels=4)
        with self.assertRaises(ValueError):
            scaf.atlas(self.V, self.F, self.UV, self.FT, padding_texels=4)
        with self.assertRaises(scaf.UsageError) as cm:
            scaf.atlas(self.V, self.F, self.UV, self.FT, padding=0.5)
        self.assertIn("padding", str(cm.exception))

    def test_stop_reasons(self):
        known = {"iteration_limit", "tolerance", "converged", "zero_step", "distortion_limit",
                 "packing_stalled", "noise_floor"}
        self.assertEqual(set(self.r.stop_reasons), {"settle", "compact"})
        self.assertIn(self.r.stop_reasons["settle"], known)
        self.assertIn(self.r.stop_reasons["compact"], known)
        self.assertEqual(self.r.stop_reason, self.r.stop_reasons["compact"])
        r = scaf.atlas(self.V, self.F, self.UV, self.FT, settle_iterations=1, compact_iterations=0)
        self.assertEqual(r.stop_reasons, {"settle": "iteration_limit", "compact": "not_run"})
        self.assertEqual(r.stop_reason, "iteration_limit")

    def test_cancel_keeps_a_certified_layout(self):
        with self.assertRaises(scaf.Cancelled) as cm:
            scaf.atlas(self.V, self.F, self.UV, self.FT, progress=lambda i: i.iteration == 2)
        r = cm.exception.result
        self.assertEqual(r.iterations["compact"], 0)
        self.assertEqual(r.stop_reasons, {"settle": "cancelled", "compact": "not_run"})
        self.assertTrue(all(0.0 <= x <= 1.0 for p in rows(r.uv) for x in p))
        self.assertGreater(min(signed_areas(r.uv, r.ft)), 0.0)
        self.assertGreaterEqual(min_chart_gap(r.uv, r.ft, rows(r.chart)), r.padding * (1 - 1e-9))

    def test_exception_in_callback(self):
        calls = []

        def bad(info):
            calls.append(info)
            raise RuntimeError("stop")

        with scaf.Atlas() as a:
            a.set_mesh(self.V, self.F, self.UV, self.FT)
            with self.assertRaises(RuntimeError):
                a.run(bad)
            self.assertEqual(len(calls), 1)  # never called again after raising
            uv, ft, chart = a.get_uv()
            self.assertGreater(min(signed_areas(uv, ft)), 0.0)
            with self.assertRaises(scaf.UsageError):  # once per set_mesh
                a.run()

    def test_handle_numbers_match_result(self):
        with scaf.Atlas(padding=2 / 512, compact_iterations=5) as a:
            a.set_mesh(self.V, self.F, self.UV, self.FT)
            start = a.result()  # the starting layout is available (certified)
            self.assertEqual(start.iterations, {"settle": 0, "compact": 0})
            a.run()
            r = a.result()
            self.assertLessEqual(r.iterations["compact"], 5)
            self.assertEqual(a.efficiency, r.efficiency)
            self.assertEqual(a.min_gap, r.min_gap)
        self.assertIn("6 chart", repr(r))


@unittest.skipIf(np is None, "numpy absent: the whole suite already runs without it")
class SplitSeamsTest(unittest.TestCase):
    """scaf.split_seams on an atlas of a sphere cut into 6 charts: one new
    vertex per distinct (vertex, UV) corner pair, faces and UVs preserved."""

    def test_atlas_split_per_uv(self):
        V, F, UV, FT = scaf.read_obj(gen("cubesphere", 4))
        r = scaf.atlas(V, F, UV, FT, settle_iterations=2, compact_iterations=0)
        vmap, idx, uvs = scaf.split_seams(F, r.ft, r.uv)
        F, FT, vmap, idx, uvs, ruv = rows(F), rows(r.ft), rows(vmap), rows(idx), rows(uvs), rows(r.uv)
        self.assertEqual(len(idx), len(F))
        pairs = {(F[f][k], FT[f][k]) for f in range(len(F)) for k in range(3)}
        self.assertEqual(len(vmap), len(pairs))          # one vertex per distinct pair
        self.assertGreater(len(vmap), len(V))            # seam vertices were split
        self.assertEqual(len(uvs), len(vmap))
        seen = set()
        for f in range(len(F)):
            for k in range(3):
                n = idx[f][k]
                self.assertEqual(vmap[n], F[f][k])           # the same 3D vertex
                self.assertEqual(list(uvs[n]), list(ruv[FT[f][k]]))  # the corner's UV
                seen.add(n)
        self.assertEqual(seen, set(range(len(vmap))))    # every new vertex used
        # numbered by first appearance
        firsts = []
        for row in idx:
            for n in row:
                if n not in firsts:
                    firsts.append(n)
        self.assertEqual(firsts, list(range(len(vmap))))

    def test_bad_shapes_are_named(self):
        with self.assertRaisesRegex(ValueError, "FT: 1 rows, F has 2"):
            scaf.split_seams([[0, 1, 2], [0, 2, 3]], [[0, 1, 2]], [[0, 0], [1, 0], [1, 1]])
        with self.assertRaisesRegex(ValueError, "FT: UV index 5 outside 0..2"):
            scaf.split_seams([[0, 1, 2]], [[0, 1, 5]], [[0, 0], [1, 0], [1, 1]])


class DragTest(unittest.TestCase):
    """scaf.Drag on two hemispheres side by side (two charts, no UVs: seams="input"
    keeps the components as charts; automatic seams would segment them)."""

    @classmethod
    def setUpClass(cls):
        V, F, _, _ = scaf.read_obj(gen("hemisphere", 4))
        cls.V = rows(V) + [[x + 5.0, y, z] for x, y, z in rows(V)]
        cls.F = rows(F) + [[a + len(V), b + len(V), c + len(V)] for a, b, c in rows(F)]

    def valid(self, d):
        """Positive areas in layout units; the certified output recomputed:
        in [0,1]^2, positive areas, every chart gap >= the padding."""
        uv, ft, chart = d.get_uv()
        self.assertGreater(min(signed_areas(uv, ft)), 0.0)
        out = d.output()
        self.assertTrue(all(0.0 <= x <= 1.0 for p in rows(out.uv) for x in p))
        self.assertGreater(min(signed_areas(out.uv, out.ft)), 0.0)
        pad = d.options["padding"]
        self.assertGreaterEqual(min_chart_gap(out.uv, out.ft, rows(out.chart)), pad * (1 - 1e-9))
        self.assertAlmostEqual(sum(signed_areas(out.uv, out.ft)), out.efficiency, delta=1e-9)

    def test_drag_chart_onto_the_other(self):
        with scaf.Drag(seams="input") as d:
            d.set_mesh(self.V, self.F)
            self.assertEqual((d.chart_count, d.face_count), (2, len(self.F)))
            if np is not None:
                self.assertIsInstance(d.uv, np.ndarray)
                self.assertEqual(d.uv.shape, (d.uv_count, 2))
            c0, c1 = d.chart_info(0).centroid, d.chart_info(1).centroid
            d.move_chart(0, c1[0] - c0[0], c1[1] - c0[1])
            self.assertTrue(d.chart_info(0).held)
            err0 = d.max_handle_error
            seen = []
            for _ in range(6):
                d.step(1, progress=seen.append)
                self.valid(d)
            self.assertEqual([i.iteration for i in seen], list(range(1, 7)))
            self.assertLess(d.max_handle_error, 0.8 * err0)
            n0 = d.chart_info(0).centroid
            self.assertLess(math.dist(n0, c1), 0.8 * math.dist(c0, c1))
            self.assertGreater(math.dist(d.chart_info(1).centroid, c1), 0.0)  # pushed

    def test_pinned_vertex_keeps_its_coordinates(self):
        with scaf.Drag(seams="input") as d:
            d.set_mesh(self.V, self.F)
            charts = list(rows(d.uv_charts())) if np is None else d.uv_charts().tolist()
            v = charts.index(1)  # a vertex of the chart that gets pushed
            d.pin_vertex(v)
            self.assertTrue(d.is_pinned(v))
            self.assertEqual(d.pinned_count, 1)
            before = rows(d.uv)[v]
            c0, c1 = d.chart_info(0).centroid, d.chart_info(1).centroid
            d.move_chart(0, c1[0] - c0[0], c1[1] - c0[1])
            moved = rows(d.uv)
            for _ in range(6):  # one iteration each (the callback cannot read d)
                d.step(1)
                self.assertEqual(list(rows(d.uv)[v]), list(before))  # the same doubles
            self.assertNotEqual(rows(d.uv), moved)
            d.pin_vertex(v, False)
            self.assertEqual(d.pinned_count, 0)
            with self.assertRaises(scaf.UsageError):
                d.pin_vertex(d.uv_count)

    def test_vertex_rotation_cancel_undo(self):
        with scaf.Drag(seams="input") as d:
            d.set_mesh(self.V, self.F)
            before = rows(d.uv)
            d.checkpoint()
            x, y = before[0]
            d.move_vertices([0], [[x + 0.05, y]])
            d.move_chart(1, angle=0.3)
            self.assertEqual(d.handle_count, 2)
            d.step(2)
            mid = rows(d.uv)
            self.assertNotEqual(mid, before)
            d.step(2)
            self.assertEqual(d.iterations, 4)
            d.cancel()
            self.assertEqual(rows(d.uv), mid)  # bit for bit
            d.undo()
            self.assertEqual(rows(d.uv), before)
            self.assertEqual((d.iterations, d.undo_count), (0, 0))
            with self.assertRaises(scaf.UsageError):
                d.undo()
            d.clear_handles()
            self.assertEqual(d.handle_count, 0)
            d.compact(3)
            self.valid(d)
            # energy = area-weighted mean of the face energies
            fe = rows(d.face_energy())
            uv, ft, _ = d.get_uv()
            areas = []
            for f in range(len(self.F)):
                p0, p1, p2 = (self.V[i] for i in self.F[f])
                e1 = [p1[k] - p0[k] for k in range(3)]
                e2 = [p2[k] - p0[k] for k in range(3)]
                cx = [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]]
                areas.append(0.5 * math.sqrt(sum(c * c for c in cx)))
            mean = sum(a * e for a, e in zip(areas, fe)) / sum(areas)
            self.assertAlmostEqual(mean, d.energy, delta=1e-9 * d.energy)

    def test_rigid_move_transform_redo(self):
        with scaf.Drag(seams="input") as d:
            d.set_mesh(self.V, self.F)
            charts = list(rows(d.uv_charts())) if np is None else d.uv_charts().tolist()
            before = rows(d.uv)
            c0, c1 = d.chart_info(0).centroid, d.chart_info(1).centroid
            d.checkpoint()
            d.rigid_begin(0)
            reached = d.rigid_move(c1[0] - c0[0], c1[1] - c0[1])  # onto chart 1
            d.rigid_end()
            self.assertEqual(reached, 1.0)
            self.assertEqual(d.iterations, 0)  # no SCAF iteration
            after = rows(d.uv)
            self.valid(d)
            size = max(abs(x) for p in before for x in p)
            for c in (0, 1):  # each chart translated, shape kept
                vs = [v for v, k in enumerate(charts) if k == c]
                t = [after[vs[0]][k] - before[vs[0]][k] for k in range(2)]
                for v in vs:
                    for k in range(2):
                        self.assertLessEqual(abs(after[v][k] - before[v][k] - t[k]), 1e-12 * size)
                if c == 1:
                    self.assertGreater(math.hypot(*t), 0.0)  # pushed aside
            d.undo()
            self.assertEqual(rows(d.uv), before)
            self.assertEqual(d.redo_count, 1)
            d.redo()
            self.assertEqual(rows(d.uv), after)  # bit for bit
            with self.assertRaises(scaf.UsageError):
                d.redo()
            d.checkpoint()
            self.assertEqual(d.transform([0, 1], angle=0.7), 1.0)
            self.valid(d)
            self.assertEqual(d.transform(1, factor=0.8, pivot=(0.0, 0.0)), 1.0)
            self.valid(d)
            turned = rows(d.uv)
            with self.assertRaises(scaf.UsageError) as cm:
                d.transform([0], flip="u")  # a mirror: refused
            self.assertIn("remirror", str(cm.exception))
            self.assertEqual(rows(d.uv), turned)
            self.assertEqual(d.transform([0], flip="v", remirror=True), 1.0)
            self.valid(d)
            with self.assertRaises(ValueError):
                d.transform([0], flip="w")
            with self.assertRaises(scaf.UsageError):
                d.transform([2], angle=1.0)
            self.assertEqual(d.energy_cap, 1.25)
            d.energy_cap = 2.0
            self.assertEqual(d.energy_cap, 2.0)
            with self.assertRaises(scaf.UsageError):
                d.energy_cap = 0.5
            self.assertEqual(d.capped_count, 0)

    def test_errors(self):
        d = scaf.Drag(start="input", seams="input")
        self.assertEqual(d.options["start"], "input")
        with self.assertRaises(scaf.UsageError) as cm:
            d.set_mesh(self.V, self.F)  # no UVs to start from
        self.assertIn("START_INPUT", str(cm.exception))
        with self.assertRaises(scaf.UsageError):
            d.step(1)
        d.set_options(start="layout")
        d.set_mesh(self.V, self.F)
        with self.assertRaises(scaf.UsageError) as cm:
            d.move_chart(2, 1.0)
        self.assertIn("chart 2 does not exist", str(cm.exception))
        with self.assertRaises(scaf.UsageError):
            d.move_vertex(d.uv_count, 0.0, 0.0)
        with self.assertRaises(scaf.UsageError) as cm:
            d.move_vertex(0, math.nan, 0.0)
        self.assertIn("not finite", str(cm.exception))
        with self.assertRaises(ValueError):
            d.move_vertex("a", 0.0, 0.0)
        with self.assertRaises(scaf.UsageError):
            d.step(0)
        with self.assertRaises(scaf.UsageError):
            d.set_options(undo_depth=0)
        with self.assertRaises(ValueError):
            d.set_options(start="nowhere")
        self.assertEqual(d.handle_count, 0)
        d.close()
        with self.assertRaises(scaf.UsageError):
            d.uv


class WithoutNumpyTest(unittest.TestCase):
    """The package with numpy hidden: lists in, lists out."""

    def test_lists_only(self):
        path = gen("cubesphere", 4)
        code = (
            "import sys\n"
            "sys.modules['numpy'] = None\n"  # makes `import numpy` fail
            "import scaf\n"
            "from scaf import _arrays\n"
            "assert _arrays.np is None\n"
            "V, F, UV, FT = scaf.read_obj(%r)\n"
            "assert type(V) is list and type(UV) is list\n"
            "r = scaf.atlas(V, F, UV, FT)\n"
            "assert type(r.uv) is list and type(r.uv[0]) is list and type(r.chart) is list\n"
            "assert r.chart_count == 6 and len(r.ft) == len(F)\n"
            "p = scaf.param(V, F, UV, FT, iterations=3)\n"
            "print(r.chart_count, repr(r.uv[0][0]), p.chart_count, len(p.uv))\n" % path
        )
        p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=os.environ)
        self.assertEqual(p.returncode, 0, p.stderr)
        charts, u0, pcharts, nuv = p.stdout.split()
        self.assertEqual((charts, pcharts), ("6", "6"))
        V, F, UV, FT = scaf.read_obj(path)
        r = scaf.atlas(V, F, UV, FT)
        self.assertEqual(float(u0), float(r.uv[0][0]))


if __name__ == "__main__":
    unittest.main()
