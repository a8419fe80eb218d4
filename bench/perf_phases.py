#!/usr/bin/env python3
"""Where the CPU time of SCAF iterations goes, from a perf profile.

Groups the samples of `perf record --call-graph dwarf` taken inside
scaf_loop_step by phase -- named after the function scaf_loop_step calls
(the same cut as the loop's phase timers, but in CPU samples, which the load
of a shared machine does not inflate) -- and, inside each phase, by the
function the sample landed in (a symbol perf cannot name is shown by its
library, e.g. [libgomp]). The fill-reducing ordering (METIS, first
iteration only) is split from the symbolic analysis it is timed with.

    OPENBLAS_NUM_THREADS=1 perf record -F 1000 --call-graph dwarf,16384 -o aph.data \\
        build/scaf param MESH -o out.obj --init harmonic --iterations 10 --tolerance 0 --quiet
    perf script -i aph.data -F ip,sym,dso | bench/perf_phases.py

Prints a Markdown table: phase, samples, share of the iterations' samples,
share without the one-time ordering, and the top functions of the phase.
"""
import collections
import sys

ROOT = "scaf_loop_step"
# the function scaf_loop_step calls -> phase (prefix match, first wins)
CALLEES = [
    ("opt_chol_factor", "factorization"),
    ("opt_chol_analyze", "symbolic analysis"),
    ("opt_chol_solve", "solve"),
    ("opt_proxy_", "assembly"),
    ("opt_simplices_", "assembly"),
    ("opt_dof_", "assembly"),
    ("opt_line_search", "line search"),
    ("scaffold_", "scaffold rebuild"),
    ("opt_term_energy", "energy (reported E)"),
]
ORDERING_MARKS = ("cholmod_metis", "METIS_NodeND", "cholmod_nested_dissection", "cholmod_amd")
ORDERING = "ordering (METIS, first iteration)"
TOP = 6


def phase_of(frames):
    """frames: leaf first. Returns the phase of one sample, None if outside ROOT."""
    if ROOT not in frames:
        return None
    i = frames.index(ROOT)
    callee = frames[i - 1] if i > 0 else ROOT
    if any(m in frames[:i] for m in ORDERING_MARKS):
        return ORDERING
    for prefix, phase in CALLEES:
        if callee.startswith(prefix):
            return phase
    return "other"


def frame_name(words):
    """'ip sym (dso)' -> sym, or [library] when perf has no symbol."""
    sym = words[1] if len(words) >= 2 else "[unknown]"
    if sym == "[unknown]" and words[-1].startswith("("):
        lib = words[-1].strip("()").rsplit("/", 1)[-1].split(".so")[0]
        return "[%s]" % lib
    return sym


def samples(stream):
    """Yields the frames (leaf first) of each sample of `perf script -F ip,sym,dso`."""
    frames = []
    for line in stream:
        w = line.split()
        if not w:
            if frames:
                yield frames
            frames = []
        else:
            frames.append(frame_name(w))
    if frames:
        yield frames


def main():
    count = collections.Counter()
    leaves = collections.defaultdict(collections.Counter)
    for frames in samples(sys.stdin):
        ph = phase_of(frames)
        if ph is None:
            continue
        count[ph] += 1
        leaves[ph][frames[0]] += 1
    total = sum(count.values())
    if not total:
        print("perf_phases: no sample inside %s" % ROOT, file=sys.stderr)
        return 1
    steady = total - count[ORDERING]
    print("| phase | samples | share | share without the ordering | top functions (share of the phase) |")
    print("|---|---|---|---|---|")
    for ph, n in count.most_common():
        top = ", ".join("%s %.0f%%" % (s, 100.0 * k / n) for s, k in leaves[ph].most_common(TOP))
        rest = "-" if ph == ORDERING else "%.1f%%" % (100.0 * n / steady)
        print("| %s | %d | %.1f%% | %s | %s |" % (ph, n, 100.0 * n / total, rest, top))
    print("\n%d samples inside %s, %d without the ordering." % (total, ROOT, steady))
    return 0


if __name__ == "__main__":
    sys.exit(main())
