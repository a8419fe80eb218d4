#!/usr/bin/env python3
"""Fig. 14: the result does not depend on the orientation of the start.

Tutte's start of disk/camel_b.obj (the paper's camel; --small: a generated
hemisphere), turned by N angles spread over the circle (20 by default, the
paper's 1000 with --rotations 1000), each run 50 SCAF iterations from the
turned start through the Python API (scaf.Atlas with init_input: the
start given as is, one chart, no packing or compaction, the tolerance off,
so exactly 50 iterations as in the paper). The scaffold box is
axis-aligned, so a turned start meets another box. Claims: every E within
1e-4 relatively of the converged E (scaf param to convergence), and the map
of every tenth run bijective (scaf check on its OBJ)."""
import math
import os

from common import Figure, import_scaf, mean_std, run, write_obj

PAPER = ("1000 randomly rotated Tutte starts of the camel, 50 iterations each: the isometric distortion of "
         "the results has minimum 0.1086, maximum 0.1107, mean 0.1095 and standard deviation 3.2698e-4.")


def body(fig):
    if fig.args.small:
        mesh = fig.gen("hemisphere", 8, fig.tmp("hemisphere8.obj"))
        name, n = "generated hemisphere (384 faces)", fig.args.rotations or 4
    else:
        mesh = fig.data("disk/camel_b.obj")
        name, n = "disk/camel_b.obj", fig.args.rotations or 20
    conv = fig.tmp("fig14_converged.obj")
    _, _, err, _ = fig.scaf("param", mesh, "-o", conv, "--init", "tutte", "--tolerance", 1e-9,
                            "--png", fig.path("fig14_converged.png"), "--png-size", 300, "--checker")
    scaf = import_scaf()
    V, F, _, _ = scaf.read_obj(mesh)
    with scaf.Param(init="tutte", tolerance=1e-9) as p:
        p.set_mesh(V, F)
        U0, FT = p.get_uv()
        p.run(200)
        e_conv = p.energy
    energies = []
    for k in range(n):
        # angles spread evenly (with an offset so that 0 and 90 degrees are not both hit)
        t = 2 * math.pi * (k + 0.5) / n
        c, s = math.cos(t), math.sin(t)
        U = [[c * x - s * y, s * x + c * y] for x, y in U0]
        with scaf.Atlas(init_input=True, settle_iterations=50, settle_tolerance=0.0, compact_iterations=0,
                        repack=0) as a:
            a.set_mesh(V, F, U, FT)
            a.run()
            energies.append(a.energy)
            if k % 10 == 0:
                uv, ft, _ = a.get_uv()
                out = fig.tmp("fig14_rotation%d.obj" % k)
                write_obj(out, V, F, uv, ft)
                chk = fig.check_uv(out)
                fig.claim("rotation %d (%.1f degrees): the map after 50 iterations is bijective (scaf check)" %
                          (k, math.degrees(t)), chk["bijective"])
                os.remove(out)
    m, s = mean_std(energies)
    worst = max(abs(e - e_conv) / e_conv for e in energies)
    fig.claim("all %d rotated starts end within 1e-4 of the converged E %.6f (worst %.1e)" % (n, e_conv, worst),
              worst < 1e-4)
    fig.picture("fig14_converged.png", "the converged map (E %.6f); every rotated start ends at it" % e_conv)
    fig.rec["numbers"] = {"rotations": n, "E": energies, "E_converged": e_conv, "min": min(energies),
                          "max": max(energies), "mean": m, "std": s, "worst_relative": worst}
    fig.rec["headline"] = {"paper": "1000 rotations: E-4 min 0.1086, max 0.1107, mean 0.1095, std 3.3e-4",
                           "scaf": "%d rotations: E-4 min %.6f, max %.6f, mean %.6f, std %.1e" % (
                               n, min(energies) - 4, max(energies) - 4, m - 4, s)}
    fig.rec["scaf"] = (
        "%d starts on %s turned by evenly spread angles, 50 iterations each: E - 4 has min %.6f, max %.6f, mean %.6f, "
        "**std %.1e** (the paper: 0.1086, 0.1107, 0.1095, 3.3e-4; the paper does not define its \"isometric "
        "distortion\": read here as E less its isometric value 4, which its values, about 0.11, fit). The "
        "converged E is "
        "%.6f; the worst run ends %.1e from it relatively." %
        (n, name, min(energies) - 4, max(energies) - 4, m - 4, s, e_conv, worst))
    if not fig.args.small:
        fig.rec["differs"] = (
            "scaf's spread is %.0f times smaller than the paper's (std %.1e against 3.3e-4): after SLIM "
            "stalls scaf switches to projected Newton (its default solver), so 50 iterations reach the "
            "minimum from every start, where the paper's 50 SLIM iterations stop short of it by amounts "
            "that depend on the start; scaf's mean E - 4 is lower (%.4f against 0.1095) for the same "
            "reason." % (3.2698e-4 / max(s, 1e-300), s, m - 4))


if __name__ == "__main__":
    run(Figure("14", "Fig. 14: orientation independence", PAPER), body)
