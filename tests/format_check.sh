#!/usr/bin/env bash
# tests/format_check.sh [ROOT] — the C++ sources keep the style .clang-format
# states: no line over 120 columns (characters, not bytes), everywhere; and,
# where clang-format 14 is installed (the version the tree was formatted
# with: another version may format the same code differently), no change
# clang-format would make.  The sources are the files git tracks in common/,
# demos/, reference/, exercises/, tests/ and fuzz/ (every file on disk when
# ROOT is not a git work tree).  --self-test plants an over-long line in a
# scratch tree and passes only if the check fails there, naming that file.
set -u
if [ "${1:-}" = --self-test ]; then
  d=$(mktemp -d) && mkdir -p "$d/demos/x" || exit 2
  trap 'rm -rf "$d"' EXIT
  cp "$(dirname "$0")/../.clang-format" "$d/"
  printf 'int a;  // %0130d\n' 0 > "$d/demos/x/x.cpp"
  out=$(bash "$0" "$d"); rc=$?
  if [ "$rc" = 1 ] && grep -q 'demos/x/x.cpp:1' <<<"$out"; then
    echo "format_check --self-test: a 143-column line in demos/ fails the check"; exit 0
  fi
  echo "FAIL: the check did not catch a planted long line (exit $rc):"; echo "$out"; exit 1
fi
root=${1:-$(dirname "$0")/..}
cd "$root" || { echo "format_check: no folder $root"; exit 2; }
dirs=(common demos reference exercises tests fuzz)
if git rev-parse --is-inside-work-tree >/dev/null 2>&1 && [ -z "${1:-}" ]; then
  mapfile -t files < <(git ls-files -- "${dirs[@]}" | grep -E '\.(cpp|hpp|h|c)$')
else
  mapfile -t files < <(find "${dirs[@]}" -type f \( -name '*.cpp' -o -name '*.hpp' -o -name '*.h' -o -name '*.c' \) 2>/dev/null | sort)
fi
# perl counts characters (-CSD: UTF-8), as clang-format counts columns; awk may count bytes.
long=$(perl -CSD -ne 'chomp; printf "  %s:%d: %d columns\n", $ARGV, $., length if length > 120; close ARGV if eof' "${files[@]}")
if [ -n "$long" ]; then
  echo "FAIL: lines over 120 columns (.clang-format's ColumnLimit):"
  echo "$long"
  exit 1
fi
cf=$(command -v clang-format-14 || command -v clang-format || true)
if [ -n "$cf" ] && "$cf" --version | grep -q 'version 14\.'; then
  changes=$("$cf" --dry-run "${files[@]}" 2>&1 | grep -c 'warning:')
  if [ "$changes" -gt 0 ]; then
    echo "FAIL: clang-format 14 would change $changes places; run clang-format -i on:"
    "$cf" --dry-run "${files[@]}" 2>&1 | sed -n 's/^\([^:]*\):.*warning:.*/  \1/p' | sort -u
    exit 1
  fi
  echo "format_check: ${#files[@]} files, no line over 120 columns, clang-format 14 changes nothing"
else
  echo "format_check: ${#files[@]} files, no line over 120 columns (no clang-format 14: its check skipped)"
fi
