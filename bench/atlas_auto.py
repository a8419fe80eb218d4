#!/usr/bin/env python3
"""Automatic atlases: scaf's own seams against xatlas's automatic mode.

On closed/bunny, fertility, nefertiti-lowres, armadillo and seams/spot,
blub, human_neutral with their vt removed (stripped copies in a temporary
folder, never kept), at R px with a K-texel gap (default 1024 and 4), one
row per mesh and tool:

  charts      UV charts of the output (scaf check)
  efficiency  UV area / (longest side of the UV bounding box)^2 (scaf check)
  E mean, E p99   symmetric Dirichlet |J|^2 + |J^-1|^2 per triangle after
              scaling the UVs so that their total area is the 3D area
              ("area-matched"), area-weighted mean and 99th percentile
  seam        total 3D length of the seam edges (an edge of two faces whose
              corners' vt differ) / sqrt(3D area)
  mirrored    charts whose UV triangles are all clockwise (scaf check)
  gap         the smallest distance between two charts in texels (scaf check)
  bijective   scaf check's exact verdict
  s           wall time of the whole command (segmentation included)
  cpu         CPU time (user + system) of the command: on a shared
              machine the wall time follows the load, the CPU time less

With --versus BIN, a second scaf (e.g. main's build) runs on each mesh
right after the first (interleaved, so both see the same load) and a row
"versus" follows each scaf row, with the ratios of the two wall and CPU
times (first / second) in a last column.

scaf runs `scaf atlas IN -o OUT --seams auto` when the program has the
option; before that it segments with bench/segment_obj (mesh/chart_segment)
and runs `scaf atlas --init tutte` on the segmentation's vt seams, and says
so. xatlas runs when `node` and the npm package xatlas-wasm are usable (see
../shared/peers/xatlas/README.md: `npm install` in a copy of that folder,
passed as --xatlas DIR); its padding is raised until the measured gap is at
least K texels (up to 3 tries), since its padding is no guaranteed gap.
Without node or the package the xatlas rows are skipped with a note.

    bench/atlas_auto.py [--scaf BIN] [--segment BIN] [--data DIR]
                        [--xatlas DIR] [--resolution R] [--gap K]
                        [--only NAME[,NAME...]] [--refine OPTIONS]
                        [--versus BIN]

Prints a Markdown table (paste into bench/RESULTS-atlas.md).
"""
import argparse
import json
import math
import os
import resource
import shutil
import subprocess
import sys
import tempfile
import time

MESHES = [
    "closed/bunny.obj",
    "closed/fertility.off",
    "closed/nefertiti-lowres.obj",
    "closed/armadillo.obj",
    "seams/spot.obj",
    "seams/blub.obj",
    "seams/human_neutral.obj",
]


def strip_vt(src, dst):
    """Copy an OBJ keeping only v and f lines, faces by vertex index."""
    with open(src) as f, open(dst, "w") as out:
        for line in f:
            p = line.split()
            if not p:
                continue
            if p[0] == "v":
                out.write(line)
            elif p[0] == "f":
                out.write("f " + " ".join(t.split("/")[0] for t in p[1:]) + "\n")


def read_obj(path):
    V, T, F, FT = [], [], [], []
    with open(path) as f:
        for line in f:
            p = line.split()
            if not p:
                continue
            if p[0] == "v":
                V.append((float(p[1]), float(p[2]), float(p[3])))
            elif p[0] == "vt":
                T.append((float(p[1]), float(p[2])))
            elif p[0] == "f":
                vi = [int(t.split("/")[0]) for t in p[1:]]
                ti = [int(t.split("/")[1]) for t in p[1:]]
                vi = [a - 1 if a > 0 else len(V) + a for a in vi]
                ti = [a - 1 if a > 0 else len(T) + a for a in ti]
                for j in range(1, len(vi) - 1):
                    F.append((vi[0], vi[j], vi[j + 1]))
                    FT.append((ti[0], ti[j], ti[j + 1]))
    return V, T, F, FT


def distortion_and_seams(path):
    """Area-matched symmetric Dirichlet (mean, p99) and seam length / sqrt(area)."""
    V, T, F, FT = read_obj(path)
    a3, auv, per = [], 0.0, []
    for (i, j, k), (a, b, c) in zip(F, FT):
        p, q, r = V[i], V[j], V[k]
        e1 = [q[d] - p[d] for d in range(3)]
        e2 = [r[d] - p[d] for d in range(3)]
        l1 = math.sqrt(sum(x * x for x in e1))
        cx = [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]]
        area = 0.5 * math.sqrt(sum(x * x for x in cx))
        # the triangle in its own plane: x along e1
        x2 = sum(e1[d] * e2[d] for d in range(3)) / l1 if l1 > 0 else 0.0
        y2 = 2 * area / l1 if l1 > 0 else 0.0
        u1 = (T[b][0] - T[a][0], T[b][1] - T[a][1])
        u2 = (T[c][0] - T[a][0], T[c][1] - T[a][1])
        auv_f = 0.5 * (u1[0] * u2[1] - u1[1] * u2[0])
        auv += abs(auv_f)
        a3.append(area)
        per.append((l1, x2, y2, u1, u2))
    A = sum(a3)
    s = math.sqrt(A / auv) if auv > 0 else 1.0
    E = []
    for area, (l1, x2, y2, u1, u2) in zip(a3, per):
        if area <= 0 or l1 <= 0 or y2 <= 0:
            continue
        # J = [u1 u2] [[l1, x2], [0, y2]]^-1, UVs scaled by s
        inv = ((1 / l1, -x2 / (l1 * y2)), (0.0, 1 / y2))
        J = [[s * (u1[r] * inv[0][0] + u2[r] * inv[1][0]), s * (u1[r] * inv[0][1] + u2[r] * inv[1][1])] for r in range(2)]
        det = J[0][0] * J[1][1] - J[0][1] * J[1][0]
        fro = sum(J[r][c] ** 2 for r in range(2) for c in range(2))
        e = fro + fro / (det * det) if det != 0 else float("inf")
        E.append((e, area))
    Atot = sum(a for _, a in E)
    mean = sum(e * a for e, a in E) / Atot
    E.sort()
    acc, p99 = 0.0, E[-1][0]
    for e, a in E:
        acc += a
        if acc >= 0.99 * Atot:
            p99 = e
            break
    # seams: an edge of two faces whose corners' vt differ
    side = {}
    seam = 0.0
    for (vi, ti) in zip(F, FT):
        for k in range(3):
            a, b = vi[k], vi[(k + 1) % 3]
            ta, tb = ti[k], ti[(k + 1) % 3]
            key = (min(a, b), max(a, b))
            pair = (ta, tb) if a < b else (tb, ta)
            if key in side:
                if side[key] != pair:
                    seam += math.dist(V[a], V[b])
            else:
                side[key] = pair
    return mean, p99, seam / math.sqrt(A)


def scaf_check(scaf, path):
    r = subprocess.run([scaf, "check", "--json", path], capture_output=True, text=True)
    j = json.loads(r.stdout)
    j["exit"] = r.returncode
    return j


def has_seams_option(scaf):
    r = subprocess.run([scaf, "atlas", "--help"], capture_output=True, text=True)
    return "--seams" in r.stdout


def child_cpu():
    u = resource.getrusage(resource.RUSAGE_CHILDREN)
    return u.ru_utime + u.ru_stime


def run_scaf(args, mesh, tmp, name, scaf=None, tool="scaf"):
    scaf = scaf or args.scaf
    out = os.path.join(tmp, name + "_" + tool + ".obj")
    t0 = time.monotonic()
    c0 = child_cpu()
    if has_seams_option(scaf):
        cmd = [scaf, "atlas", mesh, "-o", out, "--seams", "auto", "--quiet",
               "--resolution", str(args.resolution), "--padding-texels", str(args.gap)]
        c0 = child_cpu()
        r = subprocess.run(cmd, capture_output=True, text=True)
        how = "scaf atlas --seams auto"
    else:
        seg = os.path.join(tmp, name + "_seg.obj")
        r = subprocess.run([args.segment, mesh, seg], capture_output=True, text=True)
        if r.returncode == 0:
            cmd = [args.scaf, "atlas", seg, "-o", out, "--init", "tutte", "--quiet",
                   "--resolution", str(args.resolution), "--padding-texels", str(args.gap)] + args.refine.split()
            r = subprocess.run(cmd, capture_output=True, text=True)
        how = ("segment_obj + scaf atlas " + args.refine).strip()
    seconds = time.monotonic() - t0
    cpu = child_cpu() - c0
    if r.returncode != 0:
        return {"tool": tool, "how": how, "error": (r.stderr or r.stdout).strip()[:200]}
    return metrics(args, out, tool, how, seconds, {"cpu": cpu})


def metrics(args, out, tool, how, seconds, extra=None):
    c = scaf_check(args.scaf, out)
    mean, p99, seam = distortion_and_seams(out)
    row = {"tool": tool, "how": how, "charts": c.get("charts"), "efficiency": c.get("packing_efficiency"),
           "E": mean, "p99": p99, "seam": seam, "mirrored": c.get("mirrored_charts"),
           "gap": (c.get("min_chart_gap") or 0.0) * args.resolution, "bijective": c["exit"] == 0,
           "seconds": seconds}
    if extra:
        row.update(extra)
    return row


def xatlas_usable(d):
    if not d or not shutil.which("node"):
        return False
    return os.path.isdir(os.path.join(d, "node_modules", "xatlas-wasm")) and os.path.exists(os.path.join(d, "run.mjs"))


def run_xatlas(args, mesh, tmp, name):
    out = os.path.join(tmp, name + "_xatlas.obj")
    pad = args.gap
    row = None
    for _ in range(3):
        t0 = time.monotonic()
        c0 = child_cpu()
        r = subprocess.run(["node", "run.mjs", "auto", mesh, out, str(pad), str(args.resolution)],
                           cwd=args.xatlas, capture_output=True, text=True)
        seconds = time.monotonic() - t0
        if r.returncode != 0:
            return {"tool": "xatlas", "how": "xatlas-wasm auto", "error": r.stderr.strip()[:200]}
        row = metrics(args, out, "xatlas", "xatlas-wasm auto, padding %d" % pad, seconds,
                      {"cpu": child_cpu() - c0})
        if row["gap"] >= args.gap:
            break
        pad += 1
    return row


def fmt(row, name, ratio=""):
    if "error" in row:
        return "| %s | %s | failed: %s | | | | | | | | | | |" % (name, row["tool"], row["error"].replace("|", "/"))
    return "| %s | %s | %d | %.3f | %.3f | %.2f | %.2f | %s | %.1f | %s | %.1f | %.1f | %s |" % (
        name, row["tool"], row["charts"], row["efficiency"], row["E"], row["p99"], row["seam"],
        row["mirrored"], row["gap"], "yes" if row["bijective"] else "no", row["seconds"],
        row.get("cpu", float("nan")), ratio)


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--scaf", default=os.path.join(here, "..", "build", "scaf"))
    ap.add_argument("--segment", default=os.path.join(here, "..", "build", "bench", "segment_obj"))
    ap.add_argument("--data", default=os.environ.get("SCAF_DATA_DIR", os.path.join(here, "..", "..", "shared", "data")))
    ap.add_argument("--xatlas", default=None, help="folder with run.mjs and node_modules/xatlas-wasm")
    ap.add_argument("--resolution", type=int, default=1024)
    ap.add_argument("--gap", type=int, default=4)
    ap.add_argument("--only", default=None)
    ap.add_argument("--refine", default="--max-distortion 4.2 --split-charts",
                    help="chart splitting options of scaf atlas in the segment_obj path")
    ap.add_argument("--versus", default=None, help="a second scaf binary run right after each scaf run")
    args = ap.parse_args()
    meshes = MESHES
    if args.only:
        keep = args.only.split(",")
        meshes = [m for m in MESHES if os.path.splitext(os.path.basename(m))[0] in keep]
    use_xatlas = xatlas_usable(args.xatlas)
    print("| mesh | tool | charts | efficiency | E mean | E p99 | seam | mirrored | gap (texels) | bijective | s | cpu s | s, cpu ratio |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    hows = set()
    with tempfile.TemporaryDirectory(prefix="atlas_auto_") as tmp:
        for rel in meshes:
            src = os.path.join(args.data, rel)
            if not os.path.exists(src):
                print("| %s | missing, skipped | | | | | | | | | |" % rel)
                continue
            name = os.path.splitext(os.path.basename(rel))[0]
            mesh = src
            if rel.endswith(".obj"):
                mesh = os.path.join(tmp, name + ".obj")
                strip_vt(src, mesh)
            row = run_scaf(args, mesh, tmp, name)
            hows.add(row["how"])
            if args.versus:
                other = run_scaf(args, mesh, tmp, name, args.versus, "versus")
                ratio = ""
                if "error" not in row and "error" not in other:
                    ratio = "%.2f, %.2f" % (row["seconds"] / other["seconds"], row["cpu"] / other["cpu"])
                print(fmt(row, name, ratio), flush=True)
                print(fmt(other, name), flush=True)
            else:
                print(fmt(row, name), flush=True)
            if use_xatlas:
                print(fmt(run_xatlas(args, mesh, tmp, name), name), flush=True)
    print()
    print("scaf ran as: %s. xatlas: %s." % (", ".join(sorted(hows)),
          "xatlas-wasm (npm) automatic mode" if use_xatlas else "not available (node or the npm package missing), skipped"))


if __name__ == "__main__":
    sys.exit(main())
