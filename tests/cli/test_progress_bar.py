"""tests/cli/test_progress_bar: the progress line of tools/cli_progress.

On a pseudo-terminal (python's pty module: stderr is a tty) `scaf param`,
`scaf atlas` and `scaf inflate` draw a self-overwriting line ("\\r" and
erase-to-end) with the phase, the bar, i/N or the criterion against the
tolerance, the energy and an ETA, and leave their summary line; on a pipe
the output has no control character and carries the per-iteration /
header lines it always had; -q draws nothing on a terminal either.
"""
import fcntl
import os
import pty
import re
import select
import struct
import subprocess
import sys
import termios

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "formats"))
from scaf_run import SCAF, expect, run, workdir  # noqa: E402

ERASE = "\033[K"


def run_tty(args, cwd):
    """Run scaf with stderr on a pseudo-terminal; (status, stderr text)."""
    master, slave = pty.openpty()
    # 200 columns: the line is cut at the terminal's width
    fcntl.ioctl(slave, termios.TIOCSWINSZ, struct.pack("HHHH", 50, 200, 0, 0))
    p = subprocess.Popen([SCAF] + args, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                         stderr=slave, cwd=cwd, env=dict(os.environ, SCAF_PROGRESS="every"))
    os.close(slave)
    out = b""
    while True:  # read until the child closed its end (EIO on Linux)
        r, _, _ = select.select([master], [], [], 600)
        if not r:
            p.kill()
            raise AssertionError("no output for 600 s: " + " ".join(args))
        try:
            chunk = os.read(master, 65536)
        except OSError:
            break
        if not chunk:
            break
        out += chunk
    os.close(master)
    return p.wait(), out.decode("utf-8", "replace").replace("\r\n", "\n")


def screen(text):
    """The lines a terminal shows at the end: "\\r" returns to the line's
    start, text overwrites, ERASE clears from the cursor to the end."""
    lines = []
    for raw in text.split("\n"):
        cur, pos = "", 0
        for k, part in enumerate(raw.split("\r")):
            if k:
                pos = 0
            pieces = part.split(ERASE)
            for j, piece in enumerate(pieces):
                if j:
                    cur = cur[:pos]
                cur = cur[:pos] + piece + cur[pos + len(piece):]
                pos += len(piece)
        lines.append(cur)
    return [ln for ln in lines if ln]


def bar_lines(text, cmd):
    """Every drawn progress line of scaf CMD (the text after a "\\r")."""
    return [seg.replace(ERASE, "") for seg in text.split("\r")
            if seg.startswith("scaf %s: " % cmd) and "ETA" in seg]


def check_param(d):
    st, err = run_tty(["param", "hemisphere.obj", "-o", "p.obj"], d)
    expect(st == 0, "param on a tty exits 0: %d\n%s" % (st, err))
    bars = bar_lines(err, "param")
    expect(bars, "param draws a progress line on a tty:\n%r" % err)
    expect(all(re.search(r"optimize \[[#.]{20}\]", b) for b in bars), "phase and bar: %r" % bars)
    judged = [b for b in bars if "criterion" in b]
    expect(judged, "the criterion against the tolerance (N is a cap): %r" % bars)
    expect(all(re.search(r"\(cap \d+\)", b) for b in bars[1:]), "the cap is said: %r" % bars)
    expect(any(re.search(r"criterion [0-9.e+-]+ -> 1e-05", b) for b in judged),
           "the tolerance 1e-5 (param's default): %r" % judged)
    expect(any(re.search(r"E [0-9.]+", b) for b in bars), "the energy: %r" % bars)
    shown = screen(err)
    expect(not any("ETA" in ln for ln in shown), "no progress line stays: %r" % shown)
    summary = [ln for ln in shown if re.match(r"scaf param: \d+ iterations, E [0-9.]+", ln)]
    expect(len(summary) == 1, "one summary line stays: %r" % shown)
    # the same number of iterations as the pipe's report says
    n_tty = int(re.match(r"scaf param: (\d+) iterations", summary[0]).group(1))
    st, _, perr = run(["param", "hemisphere.obj", "-o", "q.obj"], cwd=d)
    expect(st == 0, "param on a pipe")
    expect("\r" not in perr and "\033" not in perr, "no control character on a pipe: %r" % perr)
    expect("initial E" in perr, "the pipe keeps its header line: %r" % perr)
    n_pipe = int(re.search(r"scaf param: (\d+) iterations", perr).group(1))
    expect(n_tty == n_pipe, "the summary counts the iterations run: %d vs %d" % (n_tty, n_pipe))
    # -i N without a tolerance: the count is exact, i/N
    st, err = run_tty(["param", "hemisphere.obj", "-o", "p2.obj", "--tolerance", "0",
                       "--iterations", "3"], d)
    expect(st == 0, "param --tolerance 0: %d\n%s" % (st, err))
    bars = bar_lines(err, "param")
    expect(any(" 3/3 " in b and "[" + "#" * 20 + "]" in b for b in bars),
           "the last line is 3/3 with a full bar: %r" % bars)
    st, err = run_tty(["param", "-q", "hemisphere.obj", "-o", "p3.obj"], d)
    expect(st == 0 and err == "", "-q draws nothing on a tty: %r" % err)


def check_atlas(d):
    st, err = run_tty(["atlas", "hemisphere.obj", "-o", "a.obj"], d)
    expect(st == 0, "atlas on a tty exits 0: %d\n%s" % (st, err))
    bars = bar_lines(err, "atlas")
    phases = [re.match(r"scaf atlas: (\w+) ", b).group(1) for b in bars]
    for ph in ("segment", "settle", "compact"):
        expect(ph in phases, "atlas phase %s drawn: %r" % (ph, phases))
    expect(phases.index("segment") < phases.index("settle") < phases.index("compact"),
           "phases in order: %r" % phases)
    expect(any("efficiency" in b for b in bars), "compaction shows the efficiency")
    shown = screen(err)
    expect(not any("ETA" in ln for ln in shown), "no progress line stays: %r" % shown)
    expect(sum(1 for ln in shown if re.match(r"scaf atlas: \d+ charts, \d+\+\d+ iterations",
                                             ln)) == 1, "atlas summary stays: %r" % shown)
    st, _, perr = run(["atlas", "hemisphere.obj", "-o", "b.obj"], cwd=d)
    expect(st == 0 and "\r" not in perr and "\033" not in perr, "atlas pipe clean: %r" % perr)


def check_inflate(d):
    st, err = run_tty(["inflate", "icosphere.obj", "-o", "i.obj", "--iterations", "4", "--scale", "1.5"], d)
    expect(st == 0, "inflate on a tty exits 0: %d\n%s" % (st, err))
    bars = bar_lines(err, "inflate")
    expect(any(" 4/4 " in b for b in bars), "inflate i/N (exact count): %r" % bars)
    shown = screen(err)
    expect(not any(re.match(r"scaf inflate: iteration \d+:", ln) for ln in shown),
           "no per-iteration lines on a tty: %r" % shown)
    expect(any("bounding-box diagonal" in ln for ln in shown), "summary stays: %r" % shown)
    st, _, perr = run(["inflate", "icosphere.obj", "-o", "j.obj", "--iterations", "4", "--scale", "1.5"], cwd=d)
    expect(st == 0 and len(re.findall(r"scaf inflate: iteration \d+:", perr)) == 4,
           "the pipe keeps one line per iteration: %r" % perr)
    expect("\r" not in perr and "\033" not in perr, "inflate pipe clean")


def main():
    with workdir("progress") as d:
        for name, size in (("hemisphere", "8"), ("icosphere", "2")):
            st, _, err = run(["gen", name, "--size", size, "-o", name + ".obj"], cwd=d)
            if st != 0:
                raise AssertionError("scaf gen %s: %s" % (name, err))
        check_param(d)
        check_atlas(d)
        check_inflate(d)
    print("progress bar: ok")


if __name__ == "__main__":
    main()
