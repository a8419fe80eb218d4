"""The .glb `scaf atlas` writes, imported by Blender (headless).

The test document of gltf_tool goes through `scaf atlas -o out.glb`;
Blender's glTF importer must find a UV layer on every mesh with one UV
per loop, as many loops as the file has triangle corners, and the UVs the
file holds (blender_gltf_check.py). Skipped (exit 77) without Blender,
failing then under SCAF_REQUIRE_DATA (CI), as tests/blender does.
"""
import json
import os
import shutil
import subprocess
import sys

import gltf_tool as G
from scaf_run import expect, run, workdir


def main():
    blender = os.environ.get("SCAF_BLENDER") or shutil.which("blender")
    if not blender:
        if os.environ.get("SCAF_REQUIRE_DATA", "0") not in ("", "0"):
            print("FAIL: blender is not installed and SCAF_REQUIRE_DATA is set")
            sys.exit(1)
        print("SKIP: blender is not installed (scripts/setup.sh installs it)")
        sys.exit(77)
    doc, binbuf = G.make_scene()
    with workdir("gltf_blender") as d:
        src, out = os.path.join(d, "scene.glb"), os.path.join(d, "out.glb")
        G.save(src, doc, binbuf)
        rc, _, err = run(["atlas", src, "-o", out, "-q", "--iterations", "10",
                          "--compact-iterations", "3"])
        expect(rc == 0, "atlas: exit %d %s" % (rc, err))
        b, bufs = G.load(out)
        uvs, loops = {}, 0
        for me in b["meshes"]:
            rows = uvs.setdefault(me["name"], [])
            for pr in me["primitives"]:
                cs = G.corners(b, bufs, pr)
                t = G.values(b, bufs, pr["attributes"]["TEXCOORD_0"])
                rows += [[t[c][0], 1.0 - t[c][1]] for c in cs]
                loops += len(cs)
        exp = os.path.join(d, "expected.json")
        json.dump({"loops": loops, "uvs": uvs}, open(exp, "w"))
        check = os.path.join(os.path.dirname(os.path.abspath(__file__)), "blender_gltf_check.py")
        # Blender's Python is the system's: a Python first on PATH (pyenv,
        # a venv) would lend Blender its standard library, without numpy
        env = {k: v for k, v in os.environ.items() if not k.startswith(("PYENV", "VIRTUAL_ENV"))}
        env["PATH"] = "/usr/bin:/bin:" + env.get("PATH", "")
        p = subprocess.run([blender, "-b", "--factory-startup", "--python-exit-code", "1",
                            "--python", check, "--", out, exp],
                           stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=600, env=env)
        text = p.stdout.decode("utf-8", "replace")
        expect(p.returncode == 0 and "blender_gltf_check: ok" in text,
               "Blender import: exit %d\n%s" % (p.returncode, text[-3000:]))
    print("test_gltf_blender: ok (%d loops)" % loops)


if __name__ == "__main__":
    main()
