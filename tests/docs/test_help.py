#!/usr/bin/env python3
"""tests/docs/test_help: the help texts and docs/cli.md tell the whole truth.

The ctest docs/test_help. The exit codes are read from the enum of
tools/exit_codes.h (the source, not the table the help prints), then:
  - `scaf --help` and the help of param, atlas, check, deform, flow and
    edit list every code on a line of its own ("  CODE  meaning");
  - docs/cli.md's exit status table has exactly these codes;
  - `scaf param --help` and `scaf atlas --help` name the input formats
    (OBJ, OFF, PLY, .gz) and the stopping rules (stop_reason names);
  - `scaf atlas --help` gives the default of --resolution and of
    --padding-texels.

usage: test_help.py SOURCE_DIR SCAF_BINARY
Exit 0 pass, 1 fail.
"""

import re
import subprocess
import sys


def main(argv):
    src, scaf = argv[1], argv[2]
    with open(src + "/tools/exit_codes.h", encoding="utf-8") as f:
        header = f.read()
    enum = re.search(r"enum\s*\{(.*?)\};", header, re.S).group(1)
    codes = sorted({int(c) for c in re.findall(r"\bEXIT_\w+\s*=\s*(\d+)", enum)})
    errors = []
    if 8 not in codes or 70 not in codes:
        errors.append("tools/exit_codes.h: expected codes 8 and 70 among %s" % codes)

    helps = {}
    for cmd in ([], ["param"], ["atlas"], ["check"], ["deform"], ["flow"], ["edit"], ["untangle"],
                ["inflate"]):
        r = subprocess.run([scaf] + cmd + ["--help"], capture_output=True, text=True)
        name = " ".join(["scaf"] + cmd)
        if r.returncode != 0:
            errors.append("%s --help: exit status %d" % (name, r.returncode))
        helps[name] = r.stdout
        listed = {int(c) for c in re.findall(r"^\s+(\d+)\s+\S", r.stdout.split("Exit status:")[-1], re.M)}
        missing = [c for c in codes if c not in listed]
        if "Exit status:" not in r.stdout or missing:
            errors.append("%s --help: exit codes %s not listed" % (name, missing or codes))

    with open(src + "/docs/cli.md", encoding="utf-8") as f:
        page = f.read()
    table = page.split("## Exit status of `scaf`")[-1].split("\n## ")[0]
    in_page = sorted({int(c) for c in re.findall(r"^\|\s*(\d+)\s*\|", table, re.M)})
    if in_page != codes:
        errors.append("docs/cli.md exit status table has %s, tools/exit_codes.h %s" % (in_page, codes))

    for name in ("scaf param", "scaf atlas"):
        h = helps[name]
        for word in ("OBJ", "OFF", "PLY", ".gz", "iteration_limit", "zero_step", "stop_reason"):
            if word not in h:
                errors.append("%s --help does not mention %s" % (name, word))
    if "tolerance" not in helps["scaf param"]:
        errors.append("scaf param --help does not explain the tolerance stop")
    atlas = helps["scaf atlas"]
    for opt, default in (("--resolution", "1024"), ("--padding-texels", "4")):
        m = re.search(re.escape(opt) + r"\s.*?\(default (\S+?)\)", atlas, re.S)
        if not m or m.group(1) != default:
            errors.append("scaf atlas --help: %s should say (default %s)" % (opt, default))

    for e in errors:
        print("FAIL: " + e)
    if not errors:
        print("help texts list exit codes %s; docs/cli.md agrees; formats, stopping rules and defaults named"
              % codes)
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
