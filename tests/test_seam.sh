#!/usr/bin/env bash
# tests/test_seam.sh [ROOT] — production code reads no environment variable
# outside the suite's one test seam, common/core/test_hooks.cpp: a test
# reaches the program through that file's functions or through flags.
# Production code is common/, reference/, demos/ and exercises/ (tests/,
# fuzz/ and a demo's own test, demos/<name>/*_test.cpp, are test code).
# ROOT defaults to the repository.  --self-test plants a getenv in a demo of
# a scratch tree and passes only if the check fails there, naming that file
# (and not the getenv planted in the demo's test).
set -u
if [ "${1:-}" = --self-test ]; then
  d=$(mktemp -d) && mkdir -p "$d/demos/x" "$d/common/core" || exit 2
  trap 'rm -rf "$d"' EXIT
  echo 'const char* v = std::getenv("TS_X");' > "$d/demos/x/x.cpp"
  echo 'const char* t = std::getenv("TMPDIR");' > "$d/demos/x/x_test.cpp"  # the demo's test may
  echo 'const char* w = std::getenv("TS_Y");' > "$d/common/core/test_hooks.cpp"  # the seam itself may
  out=$(bash "$0" "$d"); rc=$?
  if [ "$rc" = 1 ] && grep -q 'demos/x/x.cpp' <<<"$out" && ! grep -q '^  common/core/test_hooks' <<<"$out" &&
     ! grep -q 'demos/x/x_test.cpp' <<<"$out"; then
    echo "test_seam --self-test: a planted getenv in a demo fails the check; the seam's and the demo test's do not"
    exit 0
  fi
  echo "FAIL: the check did not catch a planted getenv (exit $rc):"; echo "$out"; exit 1
fi
root=${1:-$(dirname "$0")/..}
cd "$root" || { echo "test_seam: no folder $root"; exit 2; }
hits=$(grep -rnE '\b(std::)?(getenv|secure_getenv|_wgetenv|_dupenv_s)\s*\(' \
         --include='*.cpp' --include='*.hpp' --include='*.h' --include='*.c' --include='*.inl' \
         common reference demos exercises 2>/dev/null | grep -v '^common/core/test_hooks\.cpp:' |
         grep -v '^demos/[^/]*/[^/]*_test\.cpp:')
if [ -n "$hits" ]; then
  echo "FAIL: environment read outside common/core/test_hooks.cpp (add a function there instead):"
  echo "$hits" | sed 's/^/  /'
  exit 1
fi
echo "test_seam: every environment variable is read in common/core/test_hooks.cpp"
