#!/usr/bin/env python3
"""ARAP and conformal runs of `scaf param`, one binary against another.

For each mesh and energy, runs every binary given (default options but
--energy; interleaved: mesh by mesh, energy by energy, binary by binary)
with OPENBLAS_NUM_THREADS=1 and prints one Markdown row per run: stop
reason, iterations, final criterion, the energy being minimized (computed
here from the output OBJ, per unit of 3D area), the reported symmetric
Dirichlet E, the first Newton iteration, the smallest det J (UV area / 3D
area of a triangle; also relative to the mean, since conformal is
scale-free), CPU (user + system) and wall seconds.

    bench/energies_newton.py --bin before=OLD/scaf --bin after=build/scaf \\
        [--barrier before=cubic] [--data ../shared/data] [--out DIR]

The meshes: disk/camel_b.obj, disk/camelhead.off, disk/hand_lowres.obj of
the shared data, and the punctured icosphere of tests/app/test_param_energies
(`scaf gen icosphere --size 3` without its first face). The ARAP value uses
the barrier of the binary: --barrier NAME=cubic for (0.1/det - 1)^3 (main
before the logarithmic barrier), the default is -ln(det / 0.1)^3.
"""
import argparse
import json
import math
import os
import resource
import subprocess
import sys
import time


def punctured_icosphere(scaf, out):
    full = out + ".full.obj"
    subprocess.run([scaf, "gen", "icosphere", "--size", "3", "-o", full], check=True)
    lines, skipped = [], False
    for line in open(full):
        if line.startswith("f ") and not skipped:
            skipped = True
            continue
        lines.append(line)
    with open(out, "w") as f:
        f.writelines(lines)
    os.remove(full)


def read_obj(path):
    V, T, F = [], [], []
    for line in open(path):
        p = line.split()
        if not p:
            continue
        if p[0] == "v":
            V.append([float(x) for x in p[1:4]])
        elif p[0] == "vt":
            T.append([float(x) for x in p[1:3]])
        elif p[0] == "f":
            F.append([tuple(int(y) - 1 for y in x.split("/")[:2]) for x in p[1:]])
    return V, T, F


def measure(path, cubic):
    """Smallest det J, the same over the mean det, ARAP (with its barrier,
    and without it), conformal energy, per unit of 3D area of the output OBJ."""
    V, T, F = read_obj(path)
    lo, a3sum, a2sum, ea, ep, ec = math.inf, 0.0, 0.0, 0.0, 0.0, 0.0
    for f in F:
        A, B, C = (V[x[0]] for x in f)
        p, q, r = (T[x[1]] for x in f)
        e1 = [B[k] - A[k] for k in range(3)]
        e2 = [C[k] - A[k] for k in range(3)]
        cx = e1[1] * e2[2] - e1[2] * e2[1]
        cy = e1[2] * e2[0] - e1[0] * e2[2]
        cz = e1[0] * e2[1] - e1[1] * e2[0]
        a3 = 0.5 * math.sqrt(cx * cx + cy * cy + cz * cz)
        l1 = math.sqrt(sum(x * x for x in e1))
        x2 = sum(e2[k] * e1[k] for k in range(3)) / l1
        y2 = 2 * a3 / l1
        du1 = [q[0] - p[0], q[1] - p[1]]
        du2 = [r[0] - p[0], r[1] - p[1]]
        # J maps the triangle's own frame, (l1, 0) and (x2, y2), to the UV edges
        J = [[du1[i] / l1, (du2[i] - du1[i] * x2 / l1) / y2] for i in range(2)]
        a, b, c, d = J[0][0], J[0][1], J[1][0], J[1][1]
        det = a * d - b * c
        E, Fm, G, H = (a + d) / 2, (a - d) / 2, (c + b) / 2, (c - b) / 2
        s0 = math.hypot(E, H) + math.hypot(Fm, G)
        s1 = math.hypot(E, H) - math.hypot(Fm, G)
        if det >= 0.1:
            bar = 0.0
        elif det <= 0:
            bar = math.inf
        else:
            bar = (0.1 / det - 1) ** 3 if cubic else -math.log(det / 0.1) ** 3
        ep += a3 * ((s0 - 1) ** 2 + (s1 - 1) ** 2)
        ea += a3 * ((s0 - 1) ** 2 + (s1 - 1) ** 2 + bar)
        ec += a3 * (a * a + b * b + c * c + d * d) / (2 * det)
        a3sum += a3
        a2sum += det * a3  # UV area
        lo = min(lo, det)
    return lo, lo * a3sum / a2sum, ea / a3sum, ep / a3sum, ec / a3sum


def run(scaf, mesh, energy, out):
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1", OMP_NUM_THREADS="1")
    r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.monotonic()
    subprocess.run([scaf, "param", mesh, "-o", out + ".obj", "--energy", energy, "--report",
                    out + ".json", "--quiet"], check=True, env=env)
    wall = time.monotonic() - t0
    r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (r1.ru_utime - r0.ru_utime) + (r1.ru_stime - r0.ru_stime)
    return json.load(open(out + ".json")), cpu, wall


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--bin", action="append", required=True, help="NAME=path of a scaf binary")
    ap.add_argument("--barrier", action="append", default=[], help="NAME=cubic")
    ap.add_argument("--data", default=os.path.join(os.path.dirname(__file__), "../../shared/data"))
    ap.add_argument("--out", default="/tmp/energies_newton")
    args = ap.parse_args()
    bins = [b.split("=", 1) for b in args.bin]
    cubic = {b.split("=", 1)[0] for b in args.barrier if b.endswith("=cubic")}
    os.makedirs(args.out, exist_ok=True)
    ico = os.path.join(args.out, "ico_hole.obj")
    punctured_icosphere(bins[-1][1], ico)
    meshes = [("ico_hole", ico)] + [
        (n, os.path.join(args.data, "disk", f))
        for n, f in [("hand_lowres", "hand_lowres.obj"), ("camel_b", "camel_b.obj"),
                     ("camelhead", "camelhead.off")]]
    print("| mesh | energy | binary | stop | its | criterion | own energy (arap: without "
          "barrier) | SD E | first Newton "
          "| min det J | min det / mean | CPU s | wall s |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for name, path in meshes:
        for energy in ("arap", "conformal"):
            for tag, scaf in bins:
                out = os.path.join(args.out, "%s-%s-%s" % (tag, name, energy))
                r, cpu, wall = run(scaf, path, energy, out)
                lo, lo_rel, ea, ep, ec = measure(out + ".obj", tag in cubic)
                first = next((i["iteration"] for i in r["iterations"] if i["solver"] == "newton"),
                             "-")
                own = "%.8g (%.8g)" % (ea, ep) if energy == "arap" else "%.8g" % ec
                print("| %s | %s | %s | %s | %d | %.2g | %s | %.6g | %s | %.3g | %.3g | %.2f | %.2f |"
                      % (name, energy, tag, r["stop_reason"], r["iteration_count"],
                         r["final_criterion"], own, r["final_energy"], first, lo, lo_rel, cpu,
                         wall))
                sys.stdout.flush()


if __name__ == "__main__":
    main()
