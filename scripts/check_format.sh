#!/usr/bin/env bash
# Fails when a C/C++ source of the project is not formatted as .clang-format
# says (clang-format from Debian 12, version 14). With --fix, formats them.
set -euo pipefail
cd "$(dirname "$0")/.."
if ! command -v clang-format >/dev/null 2>&1; then
  echo "check_format: clang-format not found (install it: scripts/setup.sh)" >&2
  exit 1
fi
mapfile -t files < <(git ls-files '*.c' '*.h' '*.cpp' 2>/dev/null || find src tools include tests bench examples fuzz python -name '*.[ch]' -o -name '*.cpp')
if [ "${1:-}" = "--fix" ]; then
  clang-format -i --style=file "${files[@]}"
  exit 0
fi
bad=0
for f in "${files[@]}"; do
  if ! clang-format --style=file --dry-run -Werror "$f" >/dev/null 2>&1; then
    echo "check_format: $f is not formatted (run: bash scripts/check_format.sh --fix)" >&2
    bad=$((bad + 1))
  fi
done
if [ "$bad" -gt 0 ]; then
  echo "check_format: $bad file(s) not formatted as .clang-format says" >&2
  exit 1
fi
echo "check_format: ${#files[@]} files formatted"
