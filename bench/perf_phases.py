#!/usr/bin/env python3
"""Where the CPU time of SCAF iterations goes, from a perf profile.

Groups the samples of `perf record --call-graph dwarf` taken inside
scaf_loop_step by phase -- named after the function scaf_loop_step calls,
or the first named one below it (the same cut as the loop's phase timers, but in CPU samples, which the load
of a shared machine does not inflate) -- and, inside each phase, by the
function the sample landed in (a symbol perf cannot name is shown by its
library, e.g. [libgomp]). The fill-reducing ordering (METIS, first
iteration only) is split from the symbolic analysis it is timed with.

    OPENBLAS_NUM_THREADS=1 perf record -F 1000 --call-graph dwarf,16384 -o aph.data \\
        build/scaf param MESH -o out.obj --init harmonic --iterations 10 --tolerance 0 --quiet
    perf script -i aph.data -F ip,sym,dso | bench/perf_phases.py

Steady state, without the first iteration's one-time work: profile the
same command with 1 and with K + 1 iterations and subtract,

    perf script -i long.data -F ip,sym,dso | bench/perf_phases.py \\
        --minus short.txt --per-iteration 4000 10

(short.txt: `perf script -F ip,sym,dso` of the 1-iteration profile; 4000:
the -F sampling rate, 10: the iterations the difference spans, for a
column of CPU milliseconds per iteration).

Prints a Markdown table: phase, samples, share of the iterations' samples,
share without the one-time ordering, and the top functions of the phase;
then, per phase, the share of its samples by the library they landed in
(BLAS: OpenBLAS's kernels; scaf: the program and its library) and by kind
of work (page faults, malloc/free, CHOLMOD's transpose of A, zeroing,
BLAS kernels, each library's own code).
"""
import collections
import sys

ROOT = "scaf_loop_step"
# frames between scaf_loop_step and the leaf -> phase (prefix match; the
# frame nearest scaf_loop_step that matches decides: static helpers such as
# order_and_factor or simplex_fill, and tail calls, hide the direct callee)
CALLEES = [
    ("opt_chol_factor_vertices", None),  # analysis and factorization: look further down
    ("factor_numeric", "factorization"),
    ("opt_chol_factor", "factorization"),
    ("cholmod_factorize", "factorization"),
    ("opt_chol_analyze", "symbolic analysis"),
    ("opt_chol_solve", "solve"),
    ("opt_proxy_", "assembly"),
    ("simplex_fill", "assembly"),
    ("finish_pattern", "assembly"),
    ("opt_csc_", "assembly"),
    ("opt_simplices_", "assembly"),
    ("opt_dof_", "assembly"),
    ("opt_line_search", "line search"),
    ("scaffold_", "scaffold rebuild"),
    ("cdt_", "scaffold rebuild"),
    ("opt_term_energy", "energy (reported E)"),
    ("simplex_energy", "energy (reported E)"),
]
ORDERING_MARKS = ("cholmod_metis", "METIS_NodeND", "cholmod_nested_dissection", "cholmod_amd")
ORDERING = "ordering (METIS, first iteration)"
TOP = 6


def phase_of(frames):
    """frames: leaf first. Returns the phase of one sample, None if outside ROOT."""
    if ROOT not in frames:
        return None
    i = frames.index(ROOT)
    if any(m in frames[:i] for m in ORDERING_MARKS):
        return ORDERING
    for callee in reversed(frames[:i]):
        hit = next((phase for prefix, phase in CALLEES if callee.startswith(prefix)), "")
        if hit:
            return hit
        if hit is None:
            continue
    if any(f.startswith("opt_chol_factor_vertices") for f in frames[:i]):
        return "factorization"  # its own code: the pattern compare
    return "other"


def library_of(dso):
    """'(/usr/lib/.../libopenblasp-r0.3.21.so)' -> a short group name."""
    name = dso.strip("()").rsplit("/", 1)[-1]
    for mark, group in (("openblas", "BLAS"), ("lapack", "BLAS"), ("blas", "BLAS"),
                        ("cholmod", "CHOLMOD"), ("gomp", "libgomp"), ("libc.", "libc"),
                        ("libm.", "libm"), ("kernel", "kernel"), ("metis", "METIS")):
        if mark in name:
            return group
    return "scaf" if name.startswith("scaf") or "libscaf" in name else name


def frame_name(words):
    """'ip sym (dso)' -> sym, or [library] when perf has no symbol."""
    sym = words[1] if len(words) >= 2 else "[unknown]"
    if sym == "[unknown]" and words[-1].startswith("("):
        lib = words[-1].strip("()").rsplit("/", 1)[-1].split(".so")[0]
        return "[%s]" % lib
    return sym


def samples(stream):
    """Yields the frames (leaf first) and the leaf's library of each sample of
    `perf script -F ip,sym,dso`."""
    frames, lib = [], None
    for line in stream:
        w = line.split()
        if not w:
            if frames:
                yield frames, lib
            frames, lib = [], None
        else:
            if lib is None and w[-1] != "(inlined)":
                lib = library_of(w[-1])  # the leaf's, or its caller's when inlined
            frames.append(frame_name(w))
    if frames:
        yield frames, lib


def kind_of(frames, lib):
    """What a sample did, across libraries: the overheads of a supernodal
    factorization (page faults, malloc, CHOLMOD's transpose of A, zeroing)
    apart from the BLAS kernels and each library's own code."""
    if "asm_exc_page_fault" in frames:
        return "page faults"
    if any(f.startswith(MALLOC_MARKS) for f in frames):
        return "malloc/free"
    if "cholmod_transpose_sym" in frames or "cholmod_ptranspose" in frames:
        return "CHOLMOD transpose of A"
    if lib == "BLAS":
        return "BLAS kernels"
    if frames and "memset" in frames[0]:
        return "memset (zeroing)"
    if any("futex" in f for f in frames):
        return "futex"
    return lib + " code"


MALLOC_MARKS = ("malloc", "_int_malloc", "_int_free", "__GI___libc_free", "_mid_memalign",
                "_int_memalign", "malloc_consolidate", "__GI___libc_malloc", "unlink_chunk",
                "__libc_calloc", "_int_realloc", "__GI___libc_realloc")


def tally(stream):
    count = collections.Counter()
    leaves = collections.defaultdict(collections.Counter)
    libs = collections.defaultdict(collections.Counter)
    kinds = collections.defaultdict(collections.Counter)
    for frames, lib in samples(stream):
        ph = phase_of(frames)
        if ph is None:
            continue
        count[ph] += 1
        leaves[ph][frames[0]] += 1
        libs[ph][lib] += 1
        kinds[ph][kind_of(frames[:frames.index(ROOT)], lib)] += 1
    return count, leaves, libs, kinds


def minus(a, b):
    """a - b for (nested) Counters, keeping negative differences."""
    if isinstance(a, collections.Counter):
        out = collections.Counter()
        for k in set(a) | set(b):
            out[k] = a.get(k, 0) - b.get(k, 0)
        return out
    out = collections.defaultdict(collections.Counter)
    for k in set(a) | set(b):
        out[k] = minus(a.get(k, collections.Counter()), b.get(k, collections.Counter()))
    return out


def share_list(counter, n, top=None):
    items = sorted(((k, v) for k, v in counter.items() if v > 0), key=lambda kv: -kv[1])[:top]
    return ", ".join("%s %.0f%%" % (k, 100.0 * v / n) for k, v in items)


def main():
    args = sys.argv[1:]
    base, hz, its = None, 0.0, 0
    while args:
        if args[0] == "--minus" and len(args) > 1:
            base, args = args[1], args[2:]
        elif args[0] == "--per-iteration" and len(args) > 2:
            hz, its, args = float(args[1]), int(args[2]), args[3:]
        else:
            print(__doc__, file=sys.stderr)
            return 2
    count, leaves, libs, kinds = tally(sys.stdin)
    if base:
        with open(base) as f:
            b = tally(f)
        count, leaves, libs, kinds = (minus(x, y) for x, y in zip((count, leaves, libs, kinds), b))
        del count[ORDERING]  # one-time work: in both profiles
    total = sum(count.values())
    if total <= 0:
        print("perf_phases: no sample inside %s" % ROOT, file=sys.stderr)
        return 1
    steady = total - count[ORDERING]
    ms = "| ms per iteration " if its else ""
    print("| phase | samples %s| share | share without the ordering | top functions (share of the phase) |" % ms)
    print("|---|---|%s---|---|---|" % ("---|" if its else ""))
    for ph, n in sorted(count.items(), key=lambda kv: -kv[1]):
        if n <= 0:
            continue
        top = share_list(leaves[ph], n, TOP)
        rest = "-" if ph == ORDERING else "%.1f%%" % (100.0 * n / steady)
        per = "| %.1f " % (1000.0 * n / hz / its) if its else ""
        print("| %s | %d %s| %.1f%% | %s | %s |" % (ph, n, per, 100.0 * n / total, rest, top))
    print("\n%d samples inside %s, %d without the ordering%s.\n"
          % (total, ROOT, steady, " (%.1f ms per iteration)" % (1000.0 * steady / hz / its) if its else ""))
    print("| phase | by library the samples landed in (share of the phase) | by kind of work |")
    print("|---|---|---|")
    for ph, n in sorted(count.items(), key=lambda kv: -kv[1]):
        if n > 0:
            print("| %s | %s | %s |" % (ph, share_list(libs[ph], n), share_list(kinds[ph], n)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
