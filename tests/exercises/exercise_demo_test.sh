#!/bin/bash
# tests/exercises/exercise_demo_test.sh BINDIR — a demo opened with a
# student's code (cylinder_seam --seam mine, torus --mapping mine):
#   it draws with the student's values, which it asks of exercise_check
#   (--eval), and shows the exercise's checks, each pass or FAIL, as its
#   measurements (the side panel lists them);
#   with the stubs as handed out it says "not done yet" and draws no cylinder;
#   with the suite's solutions every check passes, with a wrong one the
#   failing checks are the checker's own lines;
#   in a real window (Xvfb, xdotool keys) the key that selects "mine" brings
#   the checks, and code that loops forever leaves the window responsive.
# TS_EXERCISE_IMPL=solutions|wrong stands in for a student's finished code.
set -u
bin=$1
out=$(mktemp -d)
trap 'rm -rf "$out"; [ -n "${xpid:-}" ] && kill -- -"$xpid" 2>/dev/null' EXIT
fails=0
expect() { if [ "$2" = 0 ]; then echo "ok: $1"; else echo "FAILED: $1"; fails=$((fails + 1)); fi; }
has() { grep -qF -- "$2" <<<"$1"; echo $?; }
value() { awk -v n="$2" '$1 == n { print $2; exit }' <<<"$1"; }

# --png: the stubs, the solutions, a wrong solution.
r=$("$bin/cylinder_seam" --seam mine --png "$out/stub.png" 2>&1); code=$?
expect "stub: exit 0 (got $code), a picture" $([ $code = 0 ] && [ -s "$out/stub.png" ]; echo $?)
expect "stub: not done yet" "$(has "$r" "vi1_back_seam: FAIL: not done yet (write it in exercises/vi1_back_seam.cpp)")"
expect "stub: no checks made" $([ "$(value "$r" exercise_checks_total)" = 0.0000 ]; echo $?)
r=$(TS_EXERCISE_IMPL=solutions "$bin/cylinder_seam" --seam mine --slices 6 --png "$out/sol.png" 2>&1)
expect "solution: 6 of 6 checks pass" $([ "$(value "$r" exercise_checks_passed)" = 6.0000 ] && [ "$(value "$r" exercise_checks_total)" = 6.0000 ]; echo $?)
expect "solution: drawn with its s, the seam patch is the back one (3 of 6)" $([ "$(value "$r" seam_patch)" = 3.0000 ]; echo $?)
expect "solution: the seam patch shows one slice forwards" $([ "$(value "$r" "seam_patch_direction[right]")" = 1.0000 ]; echo $?)
r=$(TS_EXERCISE_IMPL=wrong "$bin/cylinder_seam" --seam mine --png "$out/wrong.png" 2>&1)
expect "wrong (the book's front seam): the checker's line, FAIL" "$(has "$r" "6 slices: the texture's edges meet in the patch at theta = 0.0 deg, expected 180: FAIL")"
expect "wrong: 4 of 6 pass" $([ "$(value "$r" exercise_checks_passed)" = 4.0000 ]; echo $?)
expect "wrong: drawn with its s, the seam patch is the front one" $([ "$(value "$r" seam_patch)" = 0.0000 ]; echo $?)
r=$(TS_EXERCISE_IMPL=solutions "$bin/torus" --mapping mine --png "$out/torus.png" 2>&1)
expect "torus solution: 2 of 2 pass" $([ "$(value "$r" exercise_checks_passed)" = 2.0000 ] && [ "$(value "$r" exercise_checks_total)" = 2.0000 ]; echo $?)
expect "torus solution: drawn with its (s, t), the centre found at R + r" $(awk '$1 == "centre_3d_z[mine]" { exit !($2 > 1.39 && $2 < 1.41) }' <<<"$r"; echo $?)
r=$(TS_EXERCISE_IMPL=wrong "$bin/torus" --mapping mine --png "$out/torus_wrong.png" 2>&1)
expect "torus wrong (t unchanged): not seen from the front, FAIL" "$(has "$r" "is seen in the render from the front: no, expected yes: FAIL")"
r=$("$bin/torus" --mapping mine --png "$out/torus_stub.png" 2>&1)
expect "torus stub: not done yet" "$(has "$r" "vi2_torus_front: FAIL: not done yet")"

# The values the demos draw with: exercise_check --eval, isolated like a check.
r=$(printf '0\n90\n' | "$bin/exercise_check" --eval cylinderS --solutions); code=$?
expect "eval: s(0), s(90) of the back seam are 0.5, 0.75 (exit $code)" $([ $code = 0 ] && [ "$(head -2 <<<"$r" | tr -d ' ' | tr '\n' ,)" = "0.5,0.75," ]; echo $?)
r=$(printf '0\n' | "$bin/exercise_check" --eval cylinderS --impl hang --time-limit 2); code=$?
expect "eval: a loop is one line (exit 1, got $code)" $([ $code = 1 ] && [ "$r" = "vi1_back_seam: FAIL: your code did not finish within 2 s (an endless loop?)" ]; echo $?)
r=$(printf '0 0\n' | "$bin/exercise_check" --eval torusST --impl crash); code=$?
expect "eval: a crash is one line (exit 1, got $code)" $([ $code = 1 ] && [ "$(wc -l <<<"$r")" = 1 ]; echo $?)
err=$(printf '0 1 2\n' | "$bin/exercise_check" --eval torusST 2>&1 >/dev/null); code=$?
expect "eval: bad input, exit 2 (got $code), one line" $([ $code = 2 ] && [ "$(wc -l <<<"$err")" = 1 ]; echo $?)

# A real window: b (seam) front -> back -> mine, typed with xdotool.  Waits
# on the window's printed measurements, never on a clock (the hang guard
# aside).
if ! command -v xvfb-run >/dev/null || ! command -v xdotool >/dev/null; then
  echo "SKIPPED the window part: no xvfb-run or xdotool"
else
  log=$out/window.log
  # wait_for PATTERN: until the window's output holds it (300 s: a hang).
  wait_for() {
    for _ in $(seq 3000); do grep -qF -- "$1" "$log" && return 0; sleep 0.1; done
    echo "window: no '$1' in 300 s"; return 1
  }
  setsid env TS_EXERCISE_IMPL=wrong xvfb-run -a -s "-screen 0 1280x720x24" sh -c \
    'echo "$DISPLAY $XAUTHORITY $$" > "$0.env"; exec "$@"' "$out/x" "$bin/cylinder_seam" >"$log" 2>&1 &
  xpid=$!
  wait_for "seam_patch_span_s" && for _ in $(seq 300); do [ -s "$out/x.env" ] && break; sleep 0.1; done
  read -r disp xauth pid <"$out/x.env"
  export DISPLAY=$disp XAUTHORITY=$xauth
  w=$(xdotool search --sync --onlyvisible --pid "$pid" | head -1)
  xdotool key --window "$w" b && wait_for " seam=back" && xdotool key --window "$w" b
  wait_for "exercise_verdict"; r=$(cat "$log")
  expect "window: b twice selects mine, the checks arrive" "$(has "$r" " seam=mine")"
  expect "window: the checker's failing line" "$(has "$r" "the texture's edges meet in the patch at theta = 0.0 deg, expected 180: FAIL")"
  command -v import >/dev/null && import -window root "$out/window.png" 2>/dev/null && cp "$out/window.png" "${TS_EXERCISE_SHOT:-/dev/null}" 2>/dev/null
  xdotool key --window "$w" q
  for _ in $(seq 3000); do kill -0 "$xpid" 2>/dev/null || break; sleep 0.1; done
  ! kill -0 "$xpid" 2>/dev/null; expect "window: q ends it" $?
  xpid=
fi

echo "$fails failed"
[ $fails = 0 ]
