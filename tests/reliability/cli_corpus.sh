#!/usr/bin/env bash
# tests/reliability/cli_corpus.sh DEMO CORPUS — every malformed file of the
# corpus through a real demo (`DEMO --texture FILE --png out.png`): exit
# status 2, exactly one line on stderr naming the file and what is wrong,
# nothing on stdout, no out.png.  Also: every good file renders; a missing
# file, a directory, a FIFO, a device and a file without read permission are
# refused the same way; the GL library fallbacks (TS_HIDE_GL_LIBS).
set -u
DEMO=$(readlink -f "${1:?usage: cli_corpus.sh DEMO CORPUS}")
CORPUS=$(readlink -f "${2:?usage: cli_corpus.sh DEMO CORPUS}")
BACKEND=${TS_TEST_BACKEND:-osmesa}
T=$(mktemp -d "${TMPDIR:-/tmp}/ts_cli_corpus.XXXXXX")
chmod 755 "$T"
trap 'rm -rf "$T"' EXIT
mkdir "$T/work"
failures=0 checks=0 skipped=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
pass() { checks=$((checks + 1)); }

# refused NAME FILE PHRASE [env...]: the demo must refuse FILE.
refused() {
  local name=$1 file=$2 phrase=$3; shift 3
  (cd "$T/work" && timeout 60 env "$@" "$DEMO" --backend "$BACKEND" --texture "$file" --png out.png \
     >"$T/out" 2>"$T/err")
  local rc=$?
  if [ "$rc" -ne 2 ]; then fail "$name: exit status $rc, want 2: $(cat "$T/err")"
  elif [ "$(wc -l <"$T/err")" -ne 1 ]; then fail "$name: $(wc -l <"$T/err") lines on stderr, want 1:"; cat "$T/err"
  elif ! grep -qF -- "$file" "$T/err"; then fail "$name: the line does not name $file: $(cat "$T/err")"
  elif ! grep -qF -- "$phrase" "$T/err"; then fail "$name: the line lacks '$phrase': $(cat "$T/err")"
  elif [ -s "$T/out" ]; then fail "$name: wrote to stdout"
  elif [ -n "$(ls -A "$T/work")" ]; then fail "$name: left files: $(ls -A "$T/work")"; rm -rf "$T/work"/* "$T/work"/.[!.]*
  else pass; fi
}

# ------------------------------------------------ the committed corpus
bad=0 good=0
while IFS=$'\t' read -r name kind phrase; do
  if [ "$kind" = error ]; then
    bad=$((bad + 1))
    refused "$name" "$CORPUS/$name" "$phrase"
  else
    good=$((good + 1))
    (cd "$T/work" && timeout 60 "$DEMO" --backend "$BACKEND" --texture "$CORPUS/$name" --png "$T/good.png" \
       --size 96x48 --quiet >"$T/out" 2>"$T/err")
    rc=$?
    if [ "$rc" -ne 0 ] || [ ! -s "$T/good.png" ]; then fail "$name: good file, exit status $rc: $(cat "$T/err")"
    else pass; fi
    rm -f "$T/good.png"
  fi
done <"$CORPUS/MANIFEST"
for f in "$CORPUS"/regressions/*; do
  [ -f "$f" ] || continue
  (cd "$T/work" && timeout 60 "$DEMO" --backend "$BACKEND" --texture "$f" --png "$T/r.png" --quiet >/dev/null 2>"$T/err")
  rc=$?
  if [ "$rc" -ne 0 ] && [ "$rc" -ne 2 ]; then fail "regression $(basename "$f"): exit status $rc: $(cat "$T/err")"; else pass; fi
  rm -f "$T/r.png"
done

# ------------------------------------------------ not files
refused missing "$T/nosuch.png" "No such file"
mkdir "$T/adir.png"
refused directory "$T/adir.png" "is a directory"
mkfifo "$T/fifo.png"
refused fifo "$T/fifo.png" "not a regular file"
refused device /dev/zero "not a regular file"
cp "$CORPUS/good_rgb8_1x1.png" "$T/secret.png"
chmod 000 "$T/secret.png"
if [ "$(id -u)" -ne 0 ]; then
  refused unreadable "$T/secret.png" "Permission denied"
elif command -v setpriv >/dev/null && setpriv --reuid=65534 --regid=65534 --clear-groups test -x "$DEMO" 2>/dev/null; then
  # Root reads anything: run this one case as nobody (uid 65534).
  chmod 777 "$T/work"
  refused unreadable "$T/secret.png" "Permission denied" setpriv --reuid=65534 --regid=65534 --clear-groups
else
  echo "SKIP: unreadable file: running as root and $DEMO is not executable by nobody (uid 65534)"
  skipped=$((skipped + 1))
fi

# ------------------------------------------------ GL libraries missing
run_demo() { (cd "$T/work" && timeout 120 env "$@" >"$T/out" 2>"$T/err"); rc=$?; }
run_demo TS_HIDE_GL_LIBS=osmesa "$DEMO" --backend auto --png "$T/fallback.png" --size 64x64
if [ "$rc" -ne 0 ] || [ ! -s "$T/fallback.png" ]; then fail "no OSMesa, auto: exit status $rc: $(cat "$T/err")"
elif ! grep -q "using the EGL backend" "$T/err"; then fail "no OSMesa, auto: no note about EGL: $(cat "$T/err")"
else pass; fi
# --quiet silences the note too: nothing on stderr, nothing on stdout.
run_demo TS_HIDE_GL_LIBS=osmesa "$DEMO" --backend auto --png "$T/fallback2.png" --size 64x64 --quiet
if [ "$rc" -ne 0 ] || [ -s "$T/err" ] || [ -s "$T/out" ]; then
  fail "no OSMesa, auto, --quiet: status $rc, stderr: $(cat "$T/err"), stdout: $(head -2 "$T/out")"; else pass; fi
run_demo TS_HIDE_GL_LIBS=osmesa "$DEMO" --backend osmesa --png out.png
if [ "$rc" -ne 2 ] || [ "$(wc -l <"$T/err")" -ne 1 ] || ! grep -q "libosmesa6" "$T/err"; then
  fail "no OSMesa, --backend osmesa: status $rc: $(cat "$T/err")"; else pass; fi
run_demo TS_HIDE_GL_LIBS=osmesa,egl,hidden "$DEMO" --backend auto --png out.png
if [ "$rc" -ne 2 ] || [ "$(wc -l <"$T/err")" -ne 1 ] || ! grep -q "libosmesa6" "$T/err" || ! grep -q "libegl1" "$T/err"; then
  fail "no GL at all: want exit 2 and one line naming the packages, got $rc: $(cat "$T/err")"; else pass; fi
if [ -n "$(ls -A "$T/work")" ]; then fail "GL failures left files: $(ls -A "$T/work")"; else pass; fi

echo "cli_corpus: $bad malformed and $good good corpus files; $checks checks passed, $failures failed, $skipped skipped"
[ "$failures" -eq 0 ]
