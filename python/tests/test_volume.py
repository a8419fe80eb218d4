"""Tests of the 3D functions (scaf.inflate, untangle, flow, check_surface,
check_tets) on meshes written by `scaf gen`: results checked with the exact
checkers (and the checkers on cases counted by hand), progress callbacks
and cancellation as scaf.param has them, bad options refused by C with a
message, and examples/volume_example.py run (its meshio part when meshio
is installed)."""

import os
import subprocess
import sys
import unittest

import scaf
from scaf import _arrays
from test_scaf import BINARY, TMP, gen, rows

np = _arrays.np
EXAMPLE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "examples",
                       "volume_example.py")


def diagonal(X):
    lo = [min(p[k] for p in X) for k in range(3)]
    hi = [max(p[k] for p in X) for k in range(3)]
    return sum((h - l) ** 2 for l, h in zip(lo, hi)) ** 0.5


class VolumeTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.ico = scaf.read_obj(gen("icosphere", 2))[:2]
        cls.dented = scaf.read_obj(gen("dented", 4))[:2]

    def test_inflate_grows_with_every_tet_positive(self):
        V, F = self.ico
        seen = []
        r = scaf.inflate(V, F, scale=1.5, iterations=4, tets=True, progress=seen.append)
        self.assertEqual([i.step for i in seen], [1, 2, 3, 4])
        self.assertTrue(all(i.phase == "iteration" and i.tets > 0 for i in seen))
        self.assertEqual(r.iterations, 4)
        X = rows(r.positions)
        self.assertEqual(len(X), len(rows(V)))
        self.assertAlmostEqual(r.diagonal_before, diagonal(rows(V)), places=12)
        self.assertAlmostEqual(r.diagonal_after, diagonal(X), places=12)
        self.assertGreater(r.diagonal_after, 1.2 * r.diagonal_before)
        self.assertTrue(scaf.check_surface(X, F).intersection_free)
        P, T, label = r.tets
        t = scaf.check_tets(P, T)
        self.assertTrue(t.valid)
        self.assertEqual(t.positive, len(rows(T)))
        self.assertEqual(set(rows(label)), {1, 2})
        self.assertEqual(rows(P)[: len(X)], X)  # the surface's vertices first
        for p in X:
            for k in range(3):
                self.assertTrue(r.box_lo[k] < p[k] < r.box_hi[k])

    def test_inflate_cancel_keeps_the_last_iteration(self):
        V, F = self.ico
        with self.assertRaises(scaf.Cancelled) as c:
            scaf.inflate(V, F, iterations=5, progress=lambda i: i.step == 2)
        self.assertEqual(c.exception.result.iterations, 2)
        self.assertTrue(scaf.check_surface(c.exception.result.positions, F).intersection_free)

    def test_callback_exception_is_reraised(self):
        V, F = self.ico

        def boom(info):
            raise RuntimeError("from the callback")
        with self.assertRaisesRegex(RuntimeError, "from the callback"):
            scaf.inflate(V, F, iterations=3, progress=boom)

    def test_untangle_frees_the_dented_sphere(self):
        V, F = self.dented
        before = scaf.check_surface(V, F)
        self.assertFalse(before.intersection_free)
        self.assertGreater(before.pairs, 0)
        self.assertEqual(len(before.first_pairs), min(before.pairs, 16))
        phases = []
        u = scaf.untangle(V, F, iterations=10, verify=True, progress=lambda i: phases.append(i.phase))
        self.assertEqual(u.input_pairs, before.pairs + before.degenerate_faces)
        self.assertEqual(phases.count("flow_step"), u.flow_steps)
        self.assertEqual(phases.count("iteration"), u.iterations)
        self.assertTrue(scaf.check_surface(u.positions, F).intersection_free)
        self.assertTrue(scaf.check_surface(u.flowed, F).intersection_free)
        self.assertLess(u.rms, u.flowed_rms)
        # already free: unchanged
        again = scaf.untangle(u.positions, F)
        self.assertEqual(again.stop_reason, "already_free")
        self.assertEqual(rows(again.positions), rows(u.positions))
        with self.assertRaises(scaf.Cancelled):
            scaf.untangle(V, F, progress=lambda i: True)

    def test_flow_until_free(self):
        V, F = self.dented
        r = scaf.flow(V, F, steps=40, until_free=True)
        self.assertGreater(r.input_defects, 0)
        self.assertEqual(r.defects, 0)
        self.assertTrue(1 <= r.steps < 40)
        self.assertTrue(scaf.check_surface(r.positions, F).intersection_free)
        if r.steps > 1:
            with self.assertRaisesRegex(scaf.NumericError, "still intersects itself"):
                scaf.flow(V, F, steps=r.steps - 1, until_free=True)
        with self.assertRaises(scaf.Cancelled) as c:
            scaf.flow(V, F, steps=5, progress=lambda i: i.step == 3)
        self.assertEqual(c.exception.result.steps, 3)

    def test_bad_options_fail_with_a_message(self):
        V, F = self.ico
        with self.assertRaisesRegex(scaf.UsageError, "scale -1"):
            scaf.inflate(V, F, scale=-1)
        with self.assertRaisesRegex(scaf.UsageError, "box_scale"):
            scaf.inflate(V, F, box_scale=0.5)
        with self.assertRaisesRegex(ValueError, "solver"):
            scaf.inflate(V, F, solver="auto")
        with self.assertRaisesRegex(scaf.UsageError, "tolerance"):
            scaf.untangle(V, F, tolerance=1.5)
        with self.assertRaisesRegex(scaf.UsageError, "steps"):
            scaf.flow(V, F, steps=0)
        with self.assertRaises(TypeError):
            scaf.untangle(V, F, no_such_option=1)
        with self.assertRaises(TypeError):
            scaf.inflate(V, F, struct_size=8)
        with self.assertRaisesRegex(ValueError, "F"):
            scaf.inflate(V, [[0, 1]])
        with self.assertRaisesRegex(scaf.MeshError, "open"):
            scaf.inflate(V, rows(F)[:-1])

    def test_tet_mesh(self):
        V, F = self.ico
        P, T, label = scaf.tet_mesh(V, F, box_cells=3)
        self.assertEqual(rows(P)[: len(rows(V))], rows(V))
        self.assertTrue(scaf.check_tets(P, T).valid)
        self.assertEqual(set(rows(label)), {1, 2})
        with self.assertRaisesRegex(scaf.UsageError, "box_cells"):
            scaf.tet_mesh(V, F, box_cells=0)

    def test_checks_by_hand(self):
        V = [[0, 0, 0], [2, 0, 0], [0, 2, 0], [0.5, 0.5, -1], [0.5, 0.5, 1], [3, 3, 0]]
        r = scaf.check_surface(V, [[0, 1, 2], [3, 4, 5]])
        self.assertFalse(r.intersection_free)
        self.assertEqual((r.pairs, r.crossing_pairs, r.first_pairs), (1, 1, [(0, 1)]))
        self.assertFalse(r.closed)
        P = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]
        t = scaf.check_tets(P, [[0, 1, 2, 3], [0, 2, 1, 3], [0, 1, 2, 2]])
        self.assertFalse(t.valid)
        self.assertEqual((t.positive, t.inverted, t.degenerate, t.first_bad), (1, 1, 1, 1))
        self.assertTrue(scaf.check_tets(P, [[0, 1, 2, 3]]).valid)
        with self.assertRaisesRegex(scaf.MeshError, "tet 0 references vertex 7"):
            scaf.check_tets(P, [[0, 1, 2, 7]])

    def test_volume_example_runs(self):
        if not os.path.exists(EXAMPLE):
            self.skipTest("examples/volume_example.py is not next to these tests")
        if np is None:
            self.skipTest("the example uses numpy")
        out = os.path.join(TMP, "py-volume-example")
        p = subprocess.run([sys.executable, EXAMPLE, out], capture_output=True, text=True)
        self.assertEqual(p.returncode, 0, p.stdout + p.stderr)
        self.assertIn("all checks hold", p.stdout)
        try:
            import meshio  # noqa: F401
        except ImportError:
            self.assertIn("meshio: not installed", p.stdout)
            return
        self.assertIn("meshio: inflated", p.stdout)
        if BINARY:  # the tets meshio wrote, checked by `scaf check`
            c = subprocess.run([BINARY, "check", out + ".mesh"], capture_output=True, text=True)
            self.assertEqual(c.returncode, 0, c.stdout + c.stderr)
            self.assertIn("every tet positively oriented", c.stdout)


if __name__ == "__main__":
    unittest.main()
