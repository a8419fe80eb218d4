#!/usr/bin/env bash
# Bounded fuzz smoke run of every fuzz/fuzz_* target (libFuzzer, clang):
# mesh readers, topology, CDT, the optimizer on tiny binary meshes, the
# `scaf deform --targets` JSON reader (also with long paths), the save path
# of `scaf edit` (fuzz_edit_save: request bodies, the input moved, deleted,
# rewritten with random text, the output linked to it), and
# the `scaf` commands' option values on meshes with extreme coordinates.
# By default the run is deterministic (what CI needs: the same inputs every
# run, so a red run is never the luck of the draw): libFuzzer with a fixed
# seed and a fixed number of runs per target (about 10-15 s each here).
#   FUZZ_SEED         libFuzzer -seed (default 1)
#   FUZZ_RUNS_SCALE   multiplies every target's run count (default 1)
# Exploring for new bugs instead (random unless FUZZ_SEED is set):
#   FUZZ_SECONDS      total seconds over the library fuzz targets
#   FUZZ_CLI_SECONDS  seconds of fuzz_cli, the commands (default 15)
#   FUZZ_JOBS         cmake build parallelism (default 2)
# Builds build-fuzz/ with -DSCAF_FUZZ=ON, runs every fuzz/fuzz_* target on a
# scratch copy of fuzz/corpus (so the seed corpus in git is not modified),
# and exits non-zero if any target crashes, leaks, times out or hits an
# error. Crashing inputs are left in build-fuzz/fuzz-artifacts/: fix the
# bug, then copy the input into fuzz/regressions/ (tests/mesh/
# test_fuzz_regressions.c parses every file there).
set -euo pipefail
cd "$(dirname "$0")/.."
explore="${FUZZ_SECONDS:+yes}"
seconds="${FUZZ_SECONDS:-60}"
seed="${FUZZ_SEED:-1}"
scale="${FUZZ_RUNS_SCALE:-1}"
# runs per target in the deterministic mode
runs_of() {
  case "$1" in
    fuzz_cli) echo 5000 ;;
    fuzz_param | fuzz_uv_numbers) echo 15000 ;;
    fuzz_cdt) echo 8000 ;;
    fuzz_mesh_parse) echo 1000000 ;;
    fuzz_topology) echo 700000 ;;
    fuzz_deform_targets) echo 1000000 ;;
    fuzz_deform_paths) echo 1000 ;; # each input expands to up to 65536 path points
    fuzz_edit_save) echo 600 ;; # each save syncs a file: ~10-50 runs a second
    *) echo 10000 ;;
  esac
}
cli_seconds="${FUZZ_CLI_SECONDS:-15}"
jobs="${FUZZ_JOBS:-2}"
if ! command -v clang >/dev/null 2>&1; then
  echo "fuzz_smoke: clang not found (install clang, see scripts/setup.sh)" >&2
  exit 1
fi
CC=clang CXX=clang++ cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSCAF_FUZZ=ON -DSCAF_TESTS=OFF \
  -DSCAF_BENCH=OFF >/dev/null
cmake --build build-fuzz -j"$jobs" >/dev/null
targets=(build-fuzz/fuzz/fuzz_*)
n=${#targets[@]}
[ -x build-fuzz/fuzz/fuzz_cli ] && n=$(( n - 1 )) # on its own budget
[ "$n" -ge 1 ] || n=1
per=$(( seconds / n ))
[ "$per" -ge 1 ] || per=1
art=build-fuzz/fuzz-artifacts
mkdir -p "$art"
status=0
for t in "${targets[@]}"; do
  name=$(basename "$t")
  work=build-fuzz/corpus-work/$name
  rm -rf "$work"
  mkdir -p "$work"
  # a target's own seeds (fuzz/corpus_NAME, e.g. binary meshes) or the
  # shared mesh files
  seeds=fuzz/corpus
  [ -d "fuzz/corpus_${name#fuzz_}" ] && seeds="fuzz/corpus_${name#fuzz_}"
  cp "$seeds"/* "$work"/ 2>/dev/null || true
  # a target's own dictionary (fuzz/NAME.dict) or the mesh keywords
  dict=fuzz/mesh.dict
  [ -f "fuzz/${name#fuzz_}.dict" ] && dict="fuzz/${name#fuzz_}.dict"
  time_s=$per
  extra=()
  if [ "$name" = fuzz_cli ]; then
    # the commands print their messages (and --help) on stdout/stderr:
    # closed for the target; libFuzzer and the sanitizers keep their output
    time_s=$cli_seconds
    extra=(-close_fd_mask=3)
  fi
  if [ -n "$explore" ]; then
    budget=(-max_total_time="$time_s")
    [ -n "${FUZZ_SEED:-}" ] && budget+=(-seed="$seed")
    echo "fuzz_smoke: $name for ${time_s}s"
  else
    runs=$(( $(runs_of "$name") * scale ))
    budget=(-seed="$seed" -runs="$runs")
    echo "fuzz_smoke: $name, $runs runs from seed $seed"
  fi
  if ! ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=1 UBSAN_OPTIONS=print_stacktrace=1 \
      "$t" ${extra[@]+"${extra[@]}"} "${budget[@]}" -max_len=4096 -rss_limit_mb=2048 -timeout=10 \
      -artifact_prefix="$art/$name-" -print_final_stats=1 -dict="$dict" "$work" fuzz/regressions \
      2>build-fuzz/"$name".log; then
    echo "fuzz_smoke: $name FAILED; log: build-fuzz/$name.log, inputs in $art/" >&2
    tail -n 40 build-fuzz/"$name".log >&2
    status=1
  else
    grep -E '^stat::number_of_executed_units|^Done' build-fuzz/"$name".log || true
  fi
done
[ "$status" -eq 0 ] && echo "fuzz_smoke: no crash"
exit "$status"
