#!/usr/bin/env python3
"""Fig. 12: the models of Smith and Schaefer, run to convergence.

disk/camel_b.obj is the paper's camel (2,032 vertices, 3,576 faces). The
horse, cow and triceratops are not public as cut disks: bad/cow.obj has the
cow's 5,804 faces but is closed with a pinched vertex, which scaf param
refuses (exit 4, named; shown below); stand-ins: disk/camelhead.off for the
horse, seams/spot.obj (a closed cow, cut into one disk by scaf's automatic
seams) for the cow, disk/hand_lowres.obj for the triceratops. The paper
stops at the energies Smith and Schaefer reached (not given in the paper);
scaf runs to its convergence test. Claims: bijective (scaf check),
converged."""
from common import Figure, Skip, read_json, report_rows, run

PAPER = ("Four models of Smith and Schaefer (horse, camel, cow, triceratops), stopped at the same energy "
         "their method reached: visually identical results (Table 1: 30 SLIM + 10 Newton iterations each; "
         "camel 0.52 s + 1.13 s, horse 8.26 s + 12.03 s).")
MODELS = [("disk/camel_b.obj", [], "Camel (Fig. 12)", False),
          ("disk/camelhead.off", [], "Horse (Fig. 12)", True),
          ("seams/spot.obj", ["--seams", "auto"], "Cow (Fig. 12)", True),
          ("disk/hand_lowres.obj", [], "Tricera (Fig. 12)", True)]


def body(fig):
    lines = ["| paper's model | scaf's model | faces | iterations (SLIM / Newton) | final E | seconds |",
             "|---|---|---|---|---|---|"]
    nums = {}
    for rel, extra, paper_model, stand_in in MODELS:
        try:
            mesh = fig.data(rel)
        except Skip as e:
            print("skip %s: %s" % (rel, e))
            continue
        name = rel.split("/")[-1].split(".")[0]
        out, rep = fig.tmp("fig12_%s.obj" % name), fig.tmp("fig12_%s.json" % name)
        png = "fig12_%s.png" % name
        fig.scaf("param", mesh, "-o", out, "--report", rep, "--png", fig.path(png), "--png-size", 260,
                 "--checker", "--quiet", *extra)
        d = read_json(rep)
        chk = fig.check_uv(out)
        fig.claim("%s: bijective (scaf check)" % name, chk["bijective"])
        fig.claim("%s: converged (%s)" % (name, d["stop_reason"]), d["stop_reason"] in ("converged", "zero_step"))
        fig.picture(png, "%s (for the %s): E %.4f" % (rel.split("/")[-1], paper_model.split(" ")[0].lower(),
                                                      d["final_energy"]))
        slim = sum(1 for i in d["iterations"] if i.get("solver") == "slim")
        lines.append("| %s | %s%s | %d | %d (%d / %d) | %.6f | %.2f |" % (
            paper_model.split(" ")[0], rel, " (automatic seams)" if extra else "", d["mesh"]["faces"],
            d["iteration_count"], slim, d["iteration_count"] - slim, d["final_energy"], d["seconds"]))
        fig.row(rel + (" (auto seams)" if extra else ""), paper_model, stand_in, v=d["mesh"]["vertices"],
                f=d["mesh"]["faces"], it=d["iteration_count"], seconds=d["seconds"],
                it_seconds=d["median_seconds_per_iteration"], **report_rows(d))
        nums[name] = {"iterations": d["iteration_count"], "E": d["final_energy"], "seconds": d["seconds"],
                      "slim": slim}
    if not nums:
        fig.skip("none of the models is present")
    cow = None
    try:
        cowp = fig.data("bad/cow.obj")
        code, _, err, _ = fig.scaf("param", cowp, "-o", fig.tmp("cow.obj"), "--quiet", ok=(0, 4))
        cow = (code, (err.strip().splitlines()[-1] if err.strip() else "").replace(cowp, "bad/cow.obj"))
    except Skip:
        pass
    fig.rec["numbers"] = nums
    cam = nums.get("camel_b")
    fig.rec["headline"] = {"paper": "camel 30 + 10 it., 1.65 s; visually identical to Smith-Schaefer",
                           "scaf": ("camel E %.4f in %d it. (%d SLIM), %.2f s; " % (
                               cam["E"], cam["iterations"], cam["slim"], cam["seconds"]) if cam else "") +
                           "%d models bijective" % len(nums)}
    fig.rec["scaf"] = ("`scaf param` with default options, to convergence (not to Smith and Schaefer's "
                       "energies, which the paper does not list):\n\n" + "\n".join(lines) +
                       ("" if not cow else "\n\nbad/cow.obj (the cow's 5,804 faces, closed, one pinched vertex): "
                        "exit %d, `%s`." % cow))
    fig.rec["differs"] = (
        "Only the camel is the paper's model. The stopping rule differs: scaf stops at its own convergence "
        "test (relative distance to the minimum below 1e-5), not at Smith and Schaefer's energies, so the "
        "maps are at (or past) the paper's; the iteration counts are of the same order (camel: the paper "
        "30 + 10).")


if __name__ == "__main__":
    run(Figure("12", "Fig. 12: Smith and Schaefer's models", PAPER), body)
