#!/usr/bin/env bash
# scripts/check_layers.sh: passes a tree that keeps the layering, and fails,
# naming the file and the layers, on an upward include (injected into a copy
# of the real src/), on a tools/ file including opt/ (and on an allow-list
# entry no longer needed) and on an upward call (two tiny objects built
# here).
#   test_check_layers.sh SOURCE_DIR [CC]
set -euo pipefail
src="$1"
cc="${2:-cc}"
script="$src/scripts/check_layers.sh"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

# ---- the real tree's includes keep the layering ----
bash "$script" "$src" >"$tmp/out" || fail "the real tree has an upward include: $(cat "$tmp/out")"

# ---- an upward include in a copy of the real tree ----
mkdir "$tmp/tree"
cp -r "$src/src" "$src/tools" "$tmp/tree/"
line=$(($(wc -l <"$tmp/tree/src/geom/predicates.c") + 1))
echo '#include "app/param.h"' >>"$tmp/tree/src/geom/predicates.c"
rc=0
bash "$script" "$tmp/tree" >"$tmp/out" 2>&1 || rc=$?
[ "$rc" -eq 1 ] || fail "upward include: exit $rc, expected 1"
grep -q "^src/geom/predicates.c:$line: includes \"app/param.h\" (app), but geom may use only base, geom$" "$tmp/out" ||
  fail "upward include not named: $(cat "$tmp/out")"
[ "$(grep -c ' includes ' "$tmp/out")" -eq 1 ] || fail "more than the injected include reported: $(cat "$tmp/out")"

# ---- tools/ including scaffold/, opt/ or geom/ outside the allow-list ----
rm -rf "$tmp/tree" && mkdir "$tmp/tree"
cp -r "$src/src" "$src/tools" "$tmp/tree/"
line=$(($(wc -l <"$tmp/tree/tools/cmd_flow.c") + 1))
echo '#include "opt/cmcf.h"' >>"$tmp/tree/tools/cmd_flow.c"
rc=0
bash "$script" "$tmp/tree" >"$tmp/out" 2>&1 || rc=$?
[ "$rc" -eq 1 ] || fail "tools/ including opt/: exit $rc, expected 1"
grep -q "^tools/cmd_flow.c:$line: includes \"opt/cmcf.h\" (opt), but tools/ stands on the public API" "$tmp/out" ||
  fail "tools/ including opt/ not named: $(cat "$tmp/out")"
[ "$(grep -c ' includes ' "$tmp/out")" -eq 1 ] || fail "more than the injected include reported: $(cat "$tmp/out")"
# an allow-listed file that no longer needs it is reported, to be struck off
cp "$src/tools/cmd_flow.c" "$tmp/tree/tools/cmd_flow.c"
sed -i '/#include "geom\//d' "$tmp/tree/tools/cmd_check.c"
rc=0
bash "$script" "$tmp/tree" >"$tmp/out" 2>&1 || rc=$?
[ "$rc" -eq 1 ] || fail "stale allow-list entry: exit $rc, expected 1"
grep -q "^tools/cmd_check.c: allow-listed for scaffold/opt/geom includes but has none" "$tmp/out" ||
  fail "stale allow-list entry not named: $(cat "$tmp/out")"

# ---- calls: objects laid out as CMake builds them ----
t="$tmp/calls"
mkdir -p "$t/src/geom" "$t/src/app" "$t/tools" "$t/b/CMakeFiles/scaf_obj.dir/src/geom" \
  "$t/b/CMakeFiles/scaf_obj.dir/src/app" "$t/b/CMakeFiles/scaf.dir/tools"
printf 'int geom_fn(void);\nint app_fn(void) { return geom_fn(); }\n' >"$t/src/app/a.c"
printf 'int geom_fn(void) { return 1; }\n' >"$t/src/geom/g.c"
printf '#include "app/a.h"\nint app_fn(void);\nint main(void) { return app_fn(); }\n' >"$t/tools/main.c"
for f in src/app/a.c src/geom/g.c; do
  "$cc" -c "$t/$f" -o "$t/b/CMakeFiles/scaf_obj.dir/$f.o"
done
"$cc" -c -x c - -o "$t/b/CMakeFiles/scaf.dir/tools/main.c.o" <<<'int app_fn(void); int main(void) { return app_fn(); }'
bash "$script" --build "$t/b" "$t" >"$tmp/out" || fail "downward calls reported: $(cat "$tmp/out")"
# now geom calls up into app
printf 'int app_fn(void);\nint geom_fn(void) { return 1; }\nint geom_up(void) { return app_fn(); }\n' >"$t/src/geom/g.c"
"$cc" -c "$t/src/geom/g.c" -o "$t/b/CMakeFiles/scaf_obj.dir/src/geom/g.c.o"
rc=0
bash "$script" --build "$t/b" "$t" >"$tmp/out" 2>&1 || rc=$?
[ "$rc" -eq 1 ] || fail "upward call: exit $rc, expected 1"
grep -q '^src/geom/g.c: uses app_fn (defined in src/app/a.c, app), but geom may use only base, geom$' "$tmp/out" ||
  fail "upward call not named: $(cat "$tmp/out")"

# ---- bad usage ----
rc=0
bash "$script" "$tmp/nowhere" >/dev/null 2>&1 || rc=$?
[ "$rc" -eq 2 ] || fail "missing root: exit $rc, expected 2"
echo "check_layers: all cases pass"
