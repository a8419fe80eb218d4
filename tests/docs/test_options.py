#!/usr/bin/env python3
"""tests/docs/test_options: every command's option table (tools/cli_options)
parses the same way, words its errors the same way, and is documented.

The ctest docs/test_options. For each command converted to an option
table, the table is read from the program itself (SCAF_LIST_OPTIONS=1
prints it, one option a line), then:
  - every option (long name, short letter) appears in `scaf CMD --help`,
    and every long name in the command's page(s) under docs/, so neither
    can drift from the table;
  - a misspelt long option (two letters swapped) exits 2 with
    "unknown option --XX; did you mean --NAME?";
  - every ranged number option given a value just outside its range exits
    2 with "scaf CMD: --NAME V is out of range: it must be ...", and
    `--NAME=V` says exactly the same as `--NAME V`;
  - a flag given a value (`--quiet=1`) exits 2 with "takes no value";
  - `--` ends the options: `scaf CMD -- --help` takes "--help" as an
    argument (no help printed, nonzero exit);
  - grouped short letters: `-FV VALUE` says the same as `-F -V VALUE`.
Then end to end: `scaf gen grid --size=3 -o A` and `--size 3 -o B` write
the same bytes, and `scaf tet IN -qo A` and `-q -o B` too (silent).

usage: test_options.py SOURCE_DIR SCAF_BINARY WORK_DIR
Exit 0 pass, 1 fail.
"""

import math
import os
import subprocess
import sys

# the page of the options every mesh-reading command shares (--input-format, --uv-set)
SHARED_PAGES = ["docs/formats.md"]
# command -> the docs pages that must name each of its options
COMMANDS = {
    "": ["docs/cli.md"],  # `scaf --version` ...: the global options
    "gen": ["docs/cli.md"],
    "tet": ["docs/3d.md"],
    "check": ["docs/check.md"],
    "info": ["docs/param.md", "docs/formats.md"],
    "flow": ["docs/3d.md"],
    "untangle": ["docs/3d.md"],
    "inflate": ["docs/3d.md"],
    "deform": ["docs/deform.md"],
    "param": ["docs/param.md"],
}


def run(scaf, args, env=None, cwd=None):
    e = dict(os.environ)
    e.pop("SCAF_LIST_OPTIONS", None)
    e.update(env or {})
    return subprocess.run([scaf] + args, capture_output=True, text=True, env=e, cwd=cwd)


def table(scaf, cmd):
    args = [cmd] if cmd else ["--version"]
    r = run(scaf, args, {"SCAF_LIST_OPTIONS": "1"})
    rows = []
    for line in r.stdout.splitlines():
        name, letter, kind, lo, hi, alias = line.split("\t")
        rows.append({"name": None if name == "-" else name, "letter": None if letter == "-" else letter,
                     "kind": kind, "min": lo, "max": hi, "alias": None if alias == "-" else alias})
    return r.returncode, rows


def outside(row):
    """A value just outside the option's range, or None."""
    lo, hi = row["min"], row["max"]
    if lo == "-":
        return None
    open_min = lo.startswith(">")
    lo, hi = float(lo.lstrip(">")), float(hi)
    if row["kind"] == "int":
        return str(int(lo) - 1) if lo > -2**31 else (str(int(hi) + 1) if hi < 2**31 - 1 else None)
    if open_min:
        return repr(lo) if not lo.is_integer() else str(int(lo))
    if math.isfinite(lo) and lo > -1e300:
        return "%.17g" % (lo - max(1.0, abs(lo)))
    return "%.17g" % (hi + max(1.0, abs(hi)))


def check_command(src, scaf, cmd, pages, errors):
    prefix = [cmd] if cmd else []
    label = "scaf " + cmd if cmd else "scaf"
    rc, rows = table(scaf, cmd)
    if rc != 0 or not rows:
        errors.append("%s: SCAF_LIST_OPTIONS=1 gave exit %d and %d options" % (label, rc, len(rows)))
        return
    helptext = run(scaf, prefix + ["--help"]).stdout
    doc = ""
    for p in pages + SHARED_PAGES:
        with open(os.path.join(src, p), encoding="utf-8") as f:
            doc += f.read()
    for row in rows:
        for name in (row["name"], row["alias"]):
            if name and name not in helptext:
                errors.append("%s --help does not list %s" % (label, name))
            if name and name != "--help" and name not in doc:
                errors.append("%s: %s is in no page of %s" % (label, name, ", ".join(pages)))
        if row["letter"] and ("%s," % row["letter"]) not in helptext and row["letter"] + " " not in helptext:
            errors.append("%s --help does not list %s" % (label, row["letter"]))

    longs = [r["name"] for r in rows if r["name"] and len(r["name"]) >= 8]
    if longs:
        name = longs[0]
        typo = name[:3] + name[4] + name[3] + name[5:]
        r = run(scaf, prefix + [typo])
        want = "unknown option %s; did you mean %s?" % (typo, name)
        if r.returncode != 2 or want not in r.stderr:
            errors.append("%s %s: exit %d, %r (want 2 and %r)" % (label, typo, r.returncode, r.stderr, want))

    for row in rows:
        v = outside(row) if row["kind"] in ("int", "double") else None
        if v is None:
            continue
        a = run(scaf, prefix + [row["name"], v])
        b = run(scaf, prefix + [row["name"] + "=" + v])
        want = "scaf %s: %s %s is out of range: it must be " % (cmd, row["name"], v)
        if a.returncode != 2 or not a.stderr.startswith(want):
            errors.append("%s %s %s: exit %d, %r (want 2 and %r...)" % (label, row["name"], v, a.returncode,
                                                                      a.stderr, want))
        if (b.returncode, b.stderr) != (a.returncode, a.stderr):
            errors.append("%s %s=%s says %r, with a space %r" % (label, row["name"], v, b.stderr, a.stderr))

    flags = [r for r in rows if r["kind"] == "flag"]
    for row in flags[:1]:
        r = run(scaf, prefix + [row["name"] + "=1"])
        if r.returncode != 2 or "%s takes no value" % row["name"] not in r.stderr:
            errors.append("%s %s=1: exit %d, %r" % (label, row["name"], r.returncode, r.stderr))

    if cmd:
        r = run(scaf, prefix + ["--", "--help"])
        if r.returncode == 0 or "usage:" in r.stdout:
            errors.append("%s -- --help: exit %d, printed %r (-- must end the options)" % (label, r.returncode,
                                                                                         r.stdout[:80]))
        values = [r["letter"] for r in rows if r["letter"] and r["kind"] == "string"]
        fl = [r["letter"] for r in flags if r["letter"]]
        if values and fl:
            bad = "/nonexistent-dir/x"
            g = run(scaf, prefix + [fl[0] + values[0][1], bad])
            s = run(scaf, prefix + [fl[0], values[0], bad])
            if (g.returncode, g.stderr) != (s.returncode, s.stderr) or "unknown option" in g.stderr:
                errors.append("%s %s%s: exit %d %r, apart: exit %d %r" % (label, fl[0], values[0][1], g.returncode,
                                                                         g.stderr, s.returncode, s.stderr))


def same_files(a, b):
    with open(a, "rb") as fa, open(b, "rb") as fb:
        return fa.read() == fb.read()


def end_to_end(scaf, work, errors):
    os.makedirs(work, exist_ok=True)
    a, b = os.path.join(work, "a.obj"), os.path.join(work, "b.obj")
    ra = run(scaf, ["gen", "grid", "--size=3", "-o", a])
    rb = run(scaf, ["gen", "grid", "--size", "3", "-o", b])
    if ra.returncode or rb.returncode or not same_files(a, b):
        errors.append("scaf gen --size=3 and --size 3 differ (exit %d, %d)" % (ra.returncode, rb.returncode))
    ball = os.path.join(work, "ball.obj")
    run(scaf, ["gen", "icosphere", "--size", "1", "-o", ball])
    ma, mb = os.path.join(work, "a.mesh"), os.path.join(work, "b.mesh")
    ra = run(scaf, ["tet", ball, "-qo", ma, "--box-cells=2"])
    rb = run(scaf, ["tet", ball, "-q", "-o", mb, "--box-cells", "2"])
    if ra.returncode or rb.returncode or ra.stderr or not same_files(ma, mb):
        errors.append("scaf tet -qo and -q -o differ (exit %d %r, %d)" % (ra.returncode, ra.stderr, rb.returncode))
    r = run(scaf, ["--versoin"])
    if r.returncode != 2 or "did you mean --version?" not in r.stderr:
        errors.append("scaf --versoin: exit %d, %r" % (r.returncode, r.stderr))


def main(argv):
    src, scaf, work = argv[1], argv[2], argv[3]
    errors = []
    for cmd, pages in COMMANDS.items():
        check_command(src, scaf, cmd, pages, errors)
    end_to_end(scaf, work, errors)
    for e in errors:
        print("FAIL: " + e)
    if not errors:
        print("option tables of %s: parsing, errors, --help and docs agree" %
              ", ".join(c or "scaf" for c in COMMANDS))
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
