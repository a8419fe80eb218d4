#!/bin/sh
# bench/compare_outputs.sh: do two builds of `scaf` write the same bytes?
#
# usage: bench/compare_outputs.sh BASE_SCAF NEW_SCAF [MESH...]
#
# Runs `scaf param` (default options, plus an SVG with the scaffold drawn)
# and `scaf atlas` (default options) with both binaries on every mesh given,
# by default every mesh of $DATA/disk and $DATA/seams (DATA defaults to
# /work/shared/data), and compares the files with cmp. A mesh the base
# binary refuses (nonzero exit) is skipped, and reported, if the new one
# exits with the same status. Outputs are kept under $OUT (default: a fresh
# temporary directory); with KEEP_BASE=1 and an existing $OUT/base, the base
# outputs there are reused instead of recomputed. Exit 0 when everything is
# identical, 1 otherwise. Runs `nice`d, one process at a time.
set -u
if [ $# -lt 2 ]; then
    sed -n '2,14p' "$0" | sed 's/^# \{0,1\}//'
    exit 2
fi
BASE=$1
NEW=$2
shift 2
DATA=${DATA:-/work/shared/data}
OUT=${OUT:-$(mktemp -d)}
if [ $# -eq 0 ]; then
    set -- "$DATA"/disk/*.obj "$DATA"/disk/*.off "$DATA"/seams/*.obj
fi
mkdir -p "$OUT/base" "$OUT/new"
export OPENBLAS_NUM_THREADS=1

# run BIN DIR NAME CMD ARGS...: outputs to DIR/NAME.*, exit status to DIR/NAME.rc
run() {
    bin=$1 dir=$2 name=$3
    shift 3
    nice "$bin" "$@" --quiet >"$dir/$name.log" 2>&1
    echo $? >"$dir/$name.rc"
}

fail=0
for mesh in "$@"; do
    [ -f "$mesh" ] || continue
    m=$(basename "$mesh")
    m=${m%.*}
    for cmd in param atlas; do
        name=$m.$cmd
        extra=
        [ $cmd = param ] && extra="--svg-scaffold"
        for side in base new; do
            bin=$BASE
            [ $side = new ] && bin=$NEW
            if [ $side = base ] && [ "${KEEP_BASE:-0}" = 1 ] && [ -f "$OUT/base/$name.rc" ]; then
                continue
            fi
            svg=
            [ $cmd = param ] && svg="--svg $OUT/$side/$name.svg"
            rm -f "$OUT/$side/$name.obj" "$OUT/$side/$name.svg"
            # shellcheck disable=SC2086
            run "$bin" "$OUT/$side" "$name" $cmd "$mesh" -o "$OUT/$side/$name.obj" $svg $extra
        done
        rb=$(cat "$OUT/base/$name.rc") rn=$(cat "$OUT/new/$name.rc")
        if [ "$rb" != 0 ]; then
            if [ "$rn" = "$rb" ]; then
                echo "skip   $name (both exit $rb)"
            else
                echo "DIFF   $name: exit $rb before, $rn after"
                fail=1
            fi
            continue
        fi
        ok=1
        for ext in obj svg; do
            [ -f "$OUT/base/$name.$ext" ] || continue
            cmp -s "$OUT/base/$name.$ext" "$OUT/new/$name.$ext" || ok=0
        done
        if [ "$rn" = 0 ] && [ $ok = 1 ]; then
            echo "same   $name"
        else
            echo "DIFF   $name (exit $rn)"
            fail=1
        fi
    done
done
echo "outputs in $OUT"
exit $fail
