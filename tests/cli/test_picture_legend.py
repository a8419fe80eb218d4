"""tests/cli/test_picture_legend: the legends of the pictures.

`scaf param --png/--svg` carry the distortion colour bar (monotone: red
rising, blue falling from E = 4 to 16, labelled ticks); `scaf atlas
--png/--svg` the unit square, the charts' numbers and the padding;
`--png-seams`, `scaf inflate --png` and `scaf untangle --png` captions on
every panel. The PNGs are decoded here (zlib + struct, no imaging library).
"""
import os
import struct
import sys
import xml.etree.ElementTree as ET
import zlib

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "formats"))
from scaf_run import expect, run, workdir  # noqa: E402

INK = (0x20, 0x20, 0x20)      # app/picture_legend: labels
GREY = (0x80, 0x80, 0x80)     # the unit square's border
SVG = "{http://www.w3.org/2000/svg}"


def read_png(path):
    """(width, height, rows of (r, g, b) tuples) of an 8-bit RGB/RGBA PNG."""
    data = open(path, "rb").read()
    expect(data[:8] == b"\x89PNG\r\n\x1a\n", path + " is a PNG")
    pos, idat, w = 8, b"", 0
    while pos < len(data):
        n, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        if kind == b"IHDR":
            w, h, depth, colour = struct.unpack(">IIBB", body[:10])
            expect(depth == 8 and colour in (2, 6), "8-bit RGB(A)")
            ch = 3 if colour == 2 else 4
        elif kind == b"IDAT":
            idat += body
        pos += 12 + n
    raw, stride, rows, prev = zlib.decompress(idat), w * ch, [], bytearray(w * ch)
    for y in range(h):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - ch] if i >= ch else 0
            b, c = prev[i], prev[i - ch] if i >= ch else 0
            if f == 1:
                line[i] = (line[i] + a) & 255
            elif f == 2:
                line[i] = (line[i] + b) & 255
            elif f == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append([tuple(line[x * ch:x * ch + 3]) for x in range(w)])
        prev = line
    return w, h, rows


def colour_bar_row(w, h, rows):
    """The row of the colour bar: the lowest row with >= w/2 saturated pixels."""
    for y in range(h - 1, -1, -1):
        sat = sum(1 for p in rows[y] if max(p) - min(p) > 60)
        if sat >= w // 2:
            return y
    return None


def check_param(d):
    st, _, err = run(["param", "hemisphere.obj", "-o", "p.obj", "--png", "p.png", "--svg",
                      "p.svg", "-q"], cwd=d)
    expect(st == 0, "param --png --svg: " + err)
    w, h, rows = read_png(os.path.join(d, "p.png"))
    y = colour_bar_row(w, h, rows)
    expect(y is not None and y > h * 0.85, "a colour bar below the layout (row %s of %d)" % (y, h))
    bar = [p for p in rows[y] if max(p) - min(p) > 60]
    reds, blues = [p[0] for p in bar], [p[2] for p in bar]
    expect(all(a <= b for a, b in zip(reds, reds[1:])), "red rises along the bar")
    expect(all(a >= b for a, b in zip(blues, blues[1:])), "blue falls along the bar")
    expect(bar[0][2] > 180 and bar[-1][0] > 230 and bar[-1][2] < 60, "blue to red: %r %r"
           % (bar[0], bar[-1]))
    labels = sum(1 for yy in range(y + 1, h) for p in rows[yy] if p == INK)
    expect(labels > 20, "tick labels under the bar (%d ink pixels)" % labels)
    # the scale spreads an optimized map's energies over several colours
    layout = {p for yy in range(0, int(h * 0.8)) for p in rows[yy] if max(p) - min(p) > 60}
    expect(len(layout) >= 8, "the layout shows %d distinct colours" % len(layout))
    root = ET.parse(os.path.join(d, "p.svg")).getroot()
    legend = root.find(".//%sg[@id='legend']" % SVG)
    expect(legend is not None, "the SVG has a legend group")
    scale = legend.findall("%srect[@class='scale']" % SVG)
    expect(len(scale) == 64, "64 colour steps")
    energies = [float(r.get("data-energy")) for r in scale]
    fills = [int(r.get("fill")[1:], 16) for r in scale]
    expect(all(a < b for a, b in zip(energies, energies[1:])), "energies increase")
    expect(all((a >> 16) <= (b >> 16) and (a & 255) >= (b & 255) for a, b in zip(fills, fills[1:])),
           "SVG colours monotone")
    ticks = [t.text for t in legend.findall("%stext[@class='tick']" % SVG)]
    expect(ticks == ["4", "4.4", "5", "6", "8", "16"], "tick labels: %r" % ticks)


def check_atlas(d):
    st, _, err = run(["atlas", "cubesphere.obj", "-o", "a.obj", "--png", "a.png", "--svg", "a.svg",
                      "--report", "a.json", "-q"], cwd=d)
    expect(st == 0, "atlas --png --svg: " + err)
    w, h, rows = read_png(os.path.join(d, "a.png"))
    expect(h > w, "a legend strip below the unit square (%dx%d)" % (w, h))
    expect(rows[0][w // 2] == GREY and rows[w - 1][w // 2] == GREY and rows[w // 2][0] == GREY
           and rows[w // 2][w - 1] == GREY, "the unit square's border")
    numbers = sum(1 for yy in range(1, w - 1) for p in rows[yy] if p == INK)
    expect(numbers > 6 * 10, "chart numbers on the square (%d ink pixels)" % numbers)
    strip = sum(1 for yy in range(w, h) for p in rows[yy] if p == INK)
    expect(strip > 30, "the padding's label and bar in the strip (%d ink pixels)" % strip)
    root = ET.parse(os.path.join(d, "a.svg")).getroot()
    expect(root.find(".//%srect[@id='unit-square']" % SVG) is not None, "SVG unit square")
    import json
    ncharts = json.load(open(os.path.join(d, "a.json")))["mesh"]["charts"]
    nums = root.findall(".//%sg[@id='chart-numbers']/%stext" % (SVG, SVG))
    expect(sorted(int(t.text) for t in nums) == list(range(ncharts)),
           "one number per chart: %d texts, %d charts" % (len(nums), ncharts))
    line = root.find(".//%sg[@id='padding']/%sline" % (SVG, SVG))
    expect(line is not None and float(line.get("data-padding")) > 0, "the padding marked")


def captions(path, panels):
    """Ink pixels in the top rows of each panel (where the captions are)."""
    w, h, rows = read_png(path)
    pw = w // panels
    return [sum(1 for yy in range(0, 16) for x in range(k * pw, (k + 1) * pw)
                if rows[yy][x] == INK) for k in range(panels)]


def check_captions(d):
    st, _, err = run(["atlas", "cubesphere.obj", "-o", "s.obj", "--png-seams", "s.png", "-q"],
                     cwd=d)
    expect(st == 0, "atlas --png-seams: " + err)
    ink = captions(os.path.join(d, "s.png"), 3)
    expect(all(n > 20 for n in ink), "front, back, atlas captions: %r" % ink)
    st, _, err = run(["inflate", "icosphere.obj", "--scale", "1.5", "--iterations", "2", "-o",
                      "i.obj", "--png", "i.png", "-q"], cwd=d)
    expect(st == 0, "inflate --png: " + err)
    ink = captions(os.path.join(d, "i.png"), 2)
    expect(all(n > 20 for n in ink), "input, inflated captions: %r" % ink)


def main():
    with workdir("legend") as d:
        for name, size in (("hemisphere", "8"), ("cubesphere", "6"), ("icosphere", "2")):
            st, _, err = run(["gen", name, "--size", size, "-o", name + ".obj"], cwd=d)
            if st != 0:
                raise AssertionError("scaf gen %s: %s" % (name, err))
        check_param(d)
        check_atlas(d)
        check_captions(d)
    print("picture legends: ok")


if __name__ == "__main__":
    main()
