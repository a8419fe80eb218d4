"""`scaf param|atlas|check|info -`: the mesh read from the standard input.

Each case pipes a generated mesh into the program and checks the result the
way a user would (the output passes `scaf check`, the reported counts equal
those of the same file read by name), and that an empty or compressed
standard input is refused with exit 3, a terminal-free message and no
output file.
"""
import json
import os
import sys

from scaf_run import expect, run, workdir


def main():
    with workdir("stdin") as d:
        a = os.path.join(d, "a.obj")
        rc, _, err = run(["gen", "hemisphere", "-s", "6", "-o", a])
        expect(rc == 0, "gen: " + err)
        text = open(a, "rb").read()

        # cat a.obj | scaf param - -o - > b.obj: a bijective map on stdout
        rc, out, err = run(["param", "-", "-o", "-", "-q", "--iterations", "5"], stdin=text)
        expect(rc == 0, "param - -o -: exit %d: %s" % (rc, err))
        b = os.path.join(d, "b.obj")
        open(b, "wb").write(out)
        rc, _, err = run(["check", b])
        expect(rc == 0, "check of param's stdout: exit %d %s" % (rc, err))
        # the input's v lines kept byte for byte (the OBJ rewrite of the piped text)
        vin = [l for l in text.splitlines() if l.startswith(b"v ")]
        vout = [l for l in out.splitlines() if l.startswith(b"v ")]
        expect(vin == vout and vin, "param -: the v lines changed")

        # atlas from stdin to a file; check reads it from stdin too
        c = os.path.join(d, "c.obj")
        rc, _, err = run(["atlas", "-", "-o", c, "-q", "--iterations", "5",
                          "--compact-iterations", "2"], stdin=text)
        expect(rc == 0, "atlas -: exit %d: %s" % (rc, err))
        rc, out, err = run(["check", "--json", "-"], stdin=open(c, "rb").read())
        expect(rc == 0 and json.loads(out)["bijective"] is True, "check - of the atlas: " + err)

        # info - equals info FILE (but for the name)
        rc1, j1, _ = run(["info", "--json", a])
        rc2, j2, err = run(["info", "--json", "-"], stdin=text)
        expect(rc1 == 0 and rc2 == 0, "info -: " + err)
        j1, j2 = json.loads(j1), json.loads(j2)
        j1.pop("input", None)
        j2.pop("input", None)
        expect(j1 == j2, "info - differs from info FILE")

        # OFF sniffed from the first bytes, and forced by --input-format
        off = b"OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n"
        rc, out, err = run(["info", "--json", "-"], stdin=off)
        expect(rc == 0 and json.loads(out)["faces"] == 2, "info - (OFF sniffed): " + err)
        rc, out, err = run(["info", "--json", "--input-format", "obj", "-"], stdin=off)
        expect(rc == 3 and "<stdin>" in err, "--input-format obj on OFF data: exit %d %s" % (rc, err))
        rc, _, err = run(["info", "--input-format", "stl", "-"], stdin=off)
        expect(rc == 2 and "--input-format" in err, "--input-format stl: exit %d" % rc)

        # empty stdin: exit 3, says so, nothing written
        e = os.path.join(d, "e.obj")
        for cmd in (["param", "-", "-o", e], ["atlas", "-", "-o", e], ["check", "-"],
                    ["info", "-"]):
            rc, out, err = run(cmd, stdin=b"")
            expect(rc == 3, "%s on empty stdin: exit %d" % (cmd[0], rc))
            expect("standard input is empty" in err, "%s: message: %s" % (cmd[0], err))
            expect(out == b"", "%s: wrote to stdout on empty input" % cmd[0])
            expect(not os.path.exists(e), "%s: output file left on empty input" % cmd[0])
        rc, out, err = run(["param", "-", "-o", "-"], stdin=b"")
        expect(rc == 3 and out == b"", "param - -o - on empty stdin: exit %d" % rc)

        # gzip on stdin: refused, with the way around it
        import gzip
        rc, _, err = run(["info", "-"], stdin=gzip.compress(text))
        expect(rc == 3 and "zcat" in err, "gzip stdin: exit %d %s" % (rc, err))
    print("test_stdin: ok")


if __name__ == "__main__":
    main()
