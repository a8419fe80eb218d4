#!/usr/bin/env python3
"""tests/docs/test_report_schemas: every report says what it is, and is it.

The ctest docs/test_report_schemas. Runs each command that writes a JSON
report (`--report` or `--json`) on small generated meshes and validates
the output against its JSON Schema in docs/schemas/ (Debian's
python3-jsonschema, Draft 2020-12; the schemas forbid keys they do not
list, so a new or renamed key without a schema update fails). Also:
  - every schema is itself valid, and every report's "schema" is the
    SCAF_REPORT_SCHEMA of src/base/json_write.h, which docs/reports.md names;
  - a key the schema does not know makes validation fail (the check bites);
  - the same quantity has the same key: "energy" (area-matched) agrees
    between `scaf atlas --report` and `scaf check --json` of its output
    to 1e-9, and between `scaf param` and `check` likewise.

usage: test_report_schemas.py SOURCE_DIR SCAF_BINARY BUILD_DIR
Exit 0 pass, 1 fail, 77 skip (no jsonschema module; a failure under
SCAF_REQUIRE_DATA=1, as CI sets it).
"""

import json
import os
import re
import shutil
import subprocess
import sys
import tempfile


def main(argv):
    src, scaf, build = argv[1], argv[2], argv[3]
    try:
        import jsonschema
    except ImportError:
        if os.environ.get("SCAF_REQUIRE_DATA", "0") not in ("", "0"):
            print("FAIL: python3-jsonschema is missing and SCAF_REQUIRE_DATA is set")
            return 1
        print("python3-jsonschema not installed: skipped")
        return 77
    with open(os.path.join(src, "src/base/json_write.h"), encoding="utf-8") as f:
        version = re.search(r'#define SCAF_REPORT_SCHEMA "([^"]+)"', f.read()).group(1)
    with open(os.path.join(src, "docs/reports.md"), encoding="utf-8") as f:
        if version not in f.read():
            print("FAIL: docs/reports.md does not name the current schema %s" % version)
            return 1
    schemas = {}
    folder = os.path.join(src, "docs/schemas")
    for name in sorted(os.listdir(folder)):
        with open(os.path.join(folder, name), encoding="utf-8") as f:
            s = json.load(f)
        jsonschema.Draft202012Validator.check_schema(s)
        schemas[name.split(".")[0]] = s

    tmp_root = os.path.join(build, "test-tmp")
    os.makedirs(tmp_root, exist_ok=True)
    tmp = tempfile.mkdtemp(prefix="schemas.", dir=tmp_root)
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1")
    errors, checked = [], []

    def run(*args, stdout=None):
        r = subprocess.run([scaf] + list(args), cwd=tmp, env=env, capture_output=True, text=True,
                           timeout=300)
        if r.returncode not in (0, 1):
            raise RuntimeError("scaf %s: exit %d: %s" % (" ".join(args), r.returncode, r.stderr.strip()))
        if stdout:
            with open(os.path.join(tmp, stdout), "w") as f:
                f.write(r.stdout)

    def load(name):
        with open(os.path.join(tmp, name), encoding="utf-8") as f:
            return json.load(f)

    def validate(command, report, label):
        if command not in schemas:
            errors.append("%s: no docs/schemas/%s.schema.json" % (label, command))
            return
        if report.get("schema") != version or report.get("command") != command:
            errors.append("%s: schema %r command %r, expected %r %r" % (
                label, report.get("schema"), report.get("command"), version, command))
        try:
            jsonschema.validate(report, schemas[command])
            checked.append(label)
        except jsonschema.ValidationError as e:
            errors.append("%s does not match docs/schemas/%s.schema.json: %s at %s" % (
                label, command, e.message, "/".join(str(p) for p in e.absolute_path)))

    try:
        run("gen", "hemisphere", "--size", "8", "-o", "hemi.obj")
        run("gen", "cubesphere", "--size", "4", "-o", "cube.obj")
        run("gen", "spiral", "-o", "spiral.obj")
        run("param", "hemi.obj", "-o", "hemi_uv.obj", "--iterations", "5", "--report", "param.json", "--quiet")
        run("atlas", "cube.obj", "-o", "cube_atlas.obj", "--report", "atlas.json", "--quiet")
        run("check", "--json", "cube_atlas.obj", stdout="check.json")
        run("check", "--json", "hemi_uv.obj", stdout="check_param.json")
        run("info", "--json", "cube.obj", stdout="info.json")
        run("deform", "spiral.obj", "--targets", "spiral.targets.json", "-o", "spiral_out.obj",
            "--iterations", "3", "--report", "deform.json", "--quiet")
        for command, name in (("param", "param.json"), ("atlas", "atlas.json"), ("check", "check.json"),
                              ("check", "check_param.json"), ("info", "info.json"),
                              ("deform", "deform.json")):
            validate(command, load(name), name)

        # the validation bites: an unknown key, a wrong type
        bad = dict(load("atlas.json"), packing_ratio=0.5)
        try:
            jsonschema.validate(bad, schemas["atlas"])
            errors.append("an atlas report with an unknown key passed its schema")
        except jsonschema.ValidationError:
            pass
        # one quantity, one key, one value
        for rep, chk in (("atlas.json", "check.json"), ("param.json", "check_param.json")):
            e1, e2 = load(rep)["energy"], load(chk)["energy"]
            if not (isinstance(e1, float) and isinstance(e2, float) and abs(e1 - e2) <= 1e-9 * e2):
                errors.append("energy of %s (%r) and of %s (%r) differ" % (rep, e1, chk, e2))
            elif not e1 >= 4.0:
                errors.append("energy of %s is %r, below an isometry's 4" % (rep, e1))
    except (RuntimeError, subprocess.TimeoutExpired) as e:
        errors.append(str(e))
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    for e in errors:
        print("FAIL: " + e)
    if errors:
        return 1
    print("%s: %d reports match their schemas (%s); energy agrees between commands"
          % (version, len(checked), ", ".join(checked)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
