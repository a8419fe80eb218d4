"""glTF 2.0 in and out: `scaf atlas` / `scaf param` on a generated document.

The document (gltf_tool.make_scene: two meshes, three primitives, one of
them unindexed, normals, tangents, colours, a second UV set, a skin with
joints, weights and inverse bind matrices, an animation, two materials,
a morph target, extras and an extension) is written as .glb and as .gltf;
scaf writes each back with TEXCOORD_0 added. Compared, parsed: everything
but meshes, accessors, buffer views and buffers is equal as JSON (nodes,
scenes, skins, animations, materials, extras, extensions, asset); every
primitive keeps its material, mode, extras and targets count, and every
attribute (and morph target) has, at every triangle corner, the value it
had at that corner in the input (un-splitting through the new indices);
accessors used by skins and animations read the same values; POSITION's
min / max are those of its values; every accessor lies inside its buffer
view and every view inside its buffer; vertex attributes keep a 4-byte
stride. The output's UVs pass `scaf check`. Bad inputs (not glTF, a
truncated .glb, a POINTS primitive, Draco compression, an index out of
range, an absurd accessor count, glTF output of an OBJ input) give their
exit status and message and leave no file.
"""
import copy
import json
import os
import sys

import gltf_tool as G
from scaf_run import expect, run, workdir

SAME = ["asset", "scene", "scenes", "nodes", "skins", "animations", "materials", "extras",
        "extensionsUsed", "textures", "images", "samplers", "cameras"]


def compare(src, out, label):
    a, abufs = G.load(src)
    b, bbufs = G.load(out)
    for key in SAME:
        expect(a.get(key) == b.get(key), "%s: '%s' changed:\n%s\n%s" % (
            label, key, json.dumps(a.get(key)), json.dumps(b.get(key))))
    # data the skin and animation point to
    for skin_a, skin_b in zip(a["skins"], b["skins"]):
        expect(G.values(a, abufs, skin_a["inverseBindMatrices"]) ==
               G.values(b, bbufs, skin_b["inverseBindMatrices"]), label + ": inverse bind matrices")
    for an_a, an_b in zip(a["animations"], b["animations"]):
        for sa, sb in zip(an_a["samplers"], an_b["samplers"]):
            for k in ("input", "output"):
                expect(G.values(a, abufs, sa[k]) == G.values(b, bbufs, sb[k]),
                       label + ": animation " + k)
    # buffers, views, accessors valid
    for k, v in enumerate(b["bufferViews"]):
        expect(v.get("byteOffset", 0) + v["byteLength"] <= len(bbufs[v["buffer"]]),
               "%s: buffer view %d outside its buffer" % (label, k))
    for k in range(len(b["accessors"])):
        G.values(b, bbufs, k)  # asserts the accessor lies in its view
    # meshes: per-corner values through the new indices
    expect(len(a["meshes"]) == len(b["meshes"]), label + ": mesh count")
    for mi, (ma, mb) in enumerate(zip(a["meshes"], b["meshes"])):
        expect({k: v for k, v in ma.items() if k != "primitives"} ==
               {k: v for k, v in mb.items() if k != "primitives"}, label + ": mesh fields")
        expect(len(ma["primitives"]) == len(mb["primitives"]), label + ": primitive count")
        for pj, (pa, pb) in enumerate(zip(ma["primitives"], mb["primitives"])):
            w = "%s mesh %d primitive %d" % (label, mi, pj)
            for k in ("material", "extras"):
                expect(pa.get(k) == pb.get(k), w + ": " + k)
            expect(pa.get("mode", 4) == pb.get("mode", 4), w + ": mode")  # 4 is the default
            expect(set(pb["attributes"]) == set(pa["attributes"]) | {"TEXCOORD_0"},
                   w + ": attributes " + str(sorted(pb["attributes"])))
            ca, cb = G.corners(a, abufs, pa), G.corners(b, bbufs, pb)
            expect(len(ca) == len(cb), w + ": triangle count changed")
            pairs = [(pa["attributes"][n], pb["attributes"][n]) for n in pa["attributes"]]
            for ta, tb in zip(pa.get("targets", []), pb.get("targets", [])):
                pairs += [(ta[n], tb[n]) for n in ta]
            expect(len(pa.get("targets", [])) == len(pb.get("targets", [])), w + ": targets")
            for xa, xb in pairs:
                va, vb = G.values(a, abufs, xa), G.values(b, bbufs, xb)
                expect(all(va[i] == vb[j] for i, j in zip(ca, cb)),
                       "%s: accessor %d -> %d differs at a corner" % (w, xa, xb))
                acc_b = b["accessors"][xb]
                view = b["bufferViews"][acc_b["bufferView"]]
                expect(view.get("byteStride", 4) % 4 == 0 and view.get("byteOffset", 0) % 4 == 0,
                       w + ": vertex attribute not 4-byte aligned")
            pos = b["accessors"][pb["attributes"]["POSITION"]]
            vals = G.values(b, bbufs, pb["attributes"]["POSITION"])
            expect(pos["min"] == [min(v[c] for v in vals) for c in range(3)] and
                   pos["max"] == [max(v[c] for v in vals) for c in range(3)],
                   w + ": POSITION min/max")
            uv = G.values(b, bbufs, pb["attributes"]["TEXCOORD_0"])
            expect(len(uv) == len(vals), w + ": TEXCOORD_0 count")
            # the new vertices: at least the input's, and each one used
            expect(len(set(cb)) == len(vals) and len(vals) >= len(set(ca)), w + ": vertex split")
            if not label.startswith("param"):  # an atlas lies in the unit square
                expect(all(0.0 <= c <= 1.0 for t in uv for c in t), w + ": UVs outside [0, 1]")


def bad_cases(d, doc, binbuf):
    """(file name, bytes or (doc, bin), expected exit, words in the message)."""
    out = []
    out.append(("text.gltf", b"hello, not a glTF\n", 3, ["not glTF"]))
    out.append(("empty_object.gltf", b"{}", 3, ["glTF"]))
    p = os.path.join(d, "full.glb")
    G.save(p, doc, binbuf)
    whole = open(p, "rb").read()
    out.append(("truncated.glb", whole[:len(whole) // 2], 3, ["glTF"]))
    pts = copy.deepcopy(doc)
    pts["meshes"][1]["primitives"][0]["mode"] = 0
    out.append(("points.glb", (pts, binbuf), 4, ["mesh 1 primitive 0", "POINTS"]))
    draco = copy.deepcopy(doc)
    draco["meshes"][0]["primitives"][0]["extensions"] = {
        "KHR_draco_mesh_compression": {"bufferView": 0, "attributes": {"POSITION": 0}}}
    draco["extensionsUsed"] = draco["extensionsUsed"] + ["KHR_draco_mesh_compression"]
    out.append(("draco.glb", (draco, binbuf), 4, ["mesh 0 primitive 0", "Draco"]))
    # an index past the vertices: the quad's uint8 indices point at 200
    bad_index = copy.deepcopy(doc)
    ind = bad_index["meshes"][1]["primitives"][1]["indices"]
    view = bad_index["bufferViews"][bad_index["accessors"][ind]["bufferView"]]
    patched = bytearray(binbuf)
    patched[view["byteOffset"] + 2] = 200
    out.append(("bad_index.glb", (bad_index, bytes(patched)), 3,
                ["mesh 1 primitive 1", "out of range"]))
    huge = copy.deepcopy(doc)
    huge["accessors"][huge["meshes"][0]["primitives"][0]["attributes"]["POSITION"]]["count"] = 10**9
    out.append(("huge_count.glb", (huge, binbuf), 3, ["mesh 0 primitive 0"]))
    deep = copy.deepcopy(doc)  # refused before tinygltf's recursive walk of extras
    nest = []
    for _ in range(600):  # past scaf's 512 levels, within Python's recursion limit
        nest = [nest]
    deep["extras"]["deep"] = nest
    out.append(("deep.gltf", (deep, binbuf), 3, ["nested"]))
    return out


def check_primitive_table(r, doc, label):
    """The report's gltf_primitives: every primitive of the document once,
    in mesh order, its faces a contiguous run of face_chart, its charts the
    charts of those faces."""
    table = r.get("gltf_primitives")
    expect(table is not None, label + ": no gltf_primitives in the report")
    want = [(mi, pj) for mi, m in enumerate(doc["meshes"]) for pj in range(len(m["primitives"]))]
    expect([(p["mesh"], p["primitive"]) for p in table] == want,
           label + ": primitives %r" % [(p["mesh"], p["primitive"]) for p in table])
    expect(table[1]["mesh_name"] == doc["meshes"][table[1]["mesh"]].get("name", ""), label + ": name")
    fc, first = r["face_chart"], 0
    for p in table:
        expect(p["first_face"] == first and p["faces"] > 0, label + ": face ranges")
        charts = sorted(set(fc[first:first + p["faces"]]))
        expect(p["charts"] == charts, label + ": charts of mesh %d primitive %d: %r vs %r"
               % (p["mesh"], p["primitive"], p["charts"], charts))
        first += p["faces"]
    expect(first == len(fc), label + ": the primitives cover every face")
    try:  # the documented schema (docs/schemas) accepts it
        import jsonschema
    except ImportError:
        return
    here = os.path.dirname(os.path.abspath(__file__))
    schema = json.load(open(os.path.join(here, "..", "..", "docs", "schemas",
                                         r["command"] + ".schema.json")))
    jsonschema.validate(r, schema)


def main():
    doc, binbuf = G.make_scene()
    with workdir("gltf") as d:
        for ext in ("glb", "gltf"):
            src = os.path.join(d, "scene." + ext)
            G.save(src, doc, binbuf)
            for cmd in ("atlas", "param"):
                out = os.path.join(d, "%s_out.%s" % (cmd, ext))
                rep = os.path.join(d, "%s_%s.json" % (cmd, ext))
                args = [cmd, src, "-o", out, "--iterations", "10", "--threads", "1",
                        "--report", rep]
                rc, _, err = run(args + (["--compact-iterations", "3"] if cmd == "atlas" else []))
                expect(rc == 0, "%s %s: exit %d %s" % (cmd, ext, rc, err))
                expect("mesh 1 'cap' primitive 1" in err, "%s: no primitive table: %s" % (cmd, err))
                compare(src, out, "%s .%s" % (cmd, ext))
                check_primitive_table(json.load(open(rep)), doc, "%s .%s" % (cmd, ext))
                rc, cout, err = run(["check", "--json", out])
                expect(rc == 0 and json.loads(cout)["bijective"] is True,
                       "check of %s: exit %d %s" % (out, rc, err))
                if cmd == "atlas":
                    rc, iout, err = run(["info", "--json", out])
                    j = json.loads(iout)
                    expect(j["format"] == "glTF" and j["uv_source"] == "glTF TEXCOORD_0",
                           "info of the output: " + str(j.get("uv_source")))
        # .glb in, .gltf out (and the other way) keep the document too
        rc, _, err = run(["atlas", os.path.join(d, "scene.glb"), "-o", os.path.join(d, "x.gltf"),
                          "--iterations", "5", "--compact-iterations", "0"])
        expect(rc == 0, "glb -> gltf: " + err)
        compare(os.path.join(d, "scene.glb"), os.path.join(d, "x.gltf"), "glb -> gltf")
        # --uv-set 1: TEXCOORD_1 (the grid's own) read as input UVs, and rewritten
        o1 = os.path.join(d, "set1.glb")
        rc, _, err = run(["atlas", os.path.join(d, "atlas_out.glb"), "-o", o1, "--uv-set", "0",
                          "--init", "input", "--iterations", "3", "--compact-iterations", "0"])
        expect(rc == 0, "--init input from the glTF's TEXCOORD_0: exit %d %s" % (rc, err))
        # stdin: the .glb piped in, glTF out
        o2 = os.path.join(d, "stdin.glb")
        rc, _, err = run(["atlas", "-", "-o", o2, "--iterations", "5", "--compact-iterations", "0"],
                         stdin=open(os.path.join(d, "scene.glb"), "rb").read())
        expect(rc == 0, "atlas - (glb on stdin): exit %d %s" % (rc, err))
        compare(os.path.join(d, "scene.glb"), o2, "stdin glb")
        # OBJ in, glTF out: refused before any work
        obj = os.path.join(d, "g.obj")
        run(["gen", "grid", "-o", obj])
        rc, _, err = run(["param", obj, "-o", os.path.join(d, "g.glb")])
        expect(rc == 2 and "not glTF" in err and not os.path.exists(os.path.join(d, "g.glb")),
               "OBJ -> glb: exit %d %s" % (rc, err))
        # bad inputs
        for name, content, code, words in bad_cases(d, doc, binbuf):
            p = os.path.join(d, name)
            if isinstance(content, bytes):
                open(p, "wb").write(content)
            else:
                G.save(p, *content)
            o = os.path.join(d, "bad_out.glb")
            rc, _, err = run(["atlas", p, "-o", o, "--iterations", "2"])
            expect(rc == code, "%s: exit %d (expected %d): %s" % (name, rc, code, err))
            for wd in words:
                expect(wd in err, "%s: message lacks '%s': %s" % (name, wd, err))
            expect(not os.path.exists(o), name + ": an output file was left")
            rc2, _, _ = run(["info", p])
            expect(rc2 == code, "%s: info exit %d" % (name, rc2))
        left = [f for f in os.listdir(d) if f.startswith(".")]
        expect(not left, "temporary files left: " + str(left))
    print("test_gltf: ok")


if __name__ == "__main__":
    main()
