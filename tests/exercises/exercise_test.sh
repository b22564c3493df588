#!/bin/bash
# tests/exercises/exercise_test.sh CHECKER — the exercises' checker checked:
#   the suite's solutions pass every check (exit 0);
#   the stubs as handed out fail each exercise with "not done yet" (exit 1);
#   a deliberately wrong solution fails each exercise with its own message;
#   code that crashes, loops or returns NaN fails in one line, and the next
#   exercise is still checked;
#   bad usage: one line on stderr, exit 2.
set -u
checker=$1
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
fails=0
expect() {  # expect WHAT CONDITION-RESULT
  if [ "$2" = 0 ]; then echo "ok: $1"; else echo "FAILED: $1"; fails=$((fails + 1)); fi
}
has() { grep -qF -- "$2" <<<"$1"; echo $?; }
names="vi1_back_seam vi2_torus_front lab1_blit mirror_wrap scanline lab2_cube lab3_planar_wrap sphere_map bump_gradient"
stubs="vi1_back_seam vi2_torus_front lab1_blit mirror_wrap lab2_cube lab3_planar_wrap sphere_map bump_gradient"  # scanline's stub is seed 002's algorithm, not empty

r=$("$checker" --all --solutions --out "$out"); code=$?
expect "the solutions pass (exit 0, got $code)" $([ $code = 0 ]; echo $?)
for n in $names; do expect "solution $n: PASS" "$(has "$r" "$n: PASS")"; done
expect "the solutions' pictures are written" $([ -s "$out/vi1_back_seam.png" ] && [ -s "$out/lab1_blit.png" ]; echo $?)

r=$("$checker" --all --out "$out"); code=$?
expect "the stubs fail (exit 1, got $code)" $([ $code = 1 ]; echo $?)
for n in $stubs; do expect "stub $n: not done yet" "$(has "$r" "$n: FAIL: not done yet")"; done
expect "scanline's stub (seed 002 as printed) fails with its pixel counts" "$(has "$r" "seed 002's triangle (8,4) (56,20) (20,60): ")"
expect "scanline's stub fails on the shared edge" "$(has "$r" "two triangles sharing the edge (56,8)-(8,56): 1128 pixels missing")"
expect "scanline's stub: FAIL" "$(has "$r" "| scanline | FAIL |")"

r=$("$checker" --all --wrong --out "$out"); code=$?
expect "the wrong solutions fail (exit 1, got $code)" $([ $code = 1 ]; echo $?)
expect "wrong vi1 (the book's front seam): edges meet at theta = 0" "$(has "$r" "the texture's edges meet in the patch at theta = 0.0 deg, expected 180: FAIL")"
expect "wrong vi2 (t unchanged): the centre is not seen from the front" "$(has "$r" "is seen in the render from the front: no, expected yes: FAIL")"
expect "wrong lab1 (pixel corners): pixels differ from GL_NEAREST" "$(has "$r" "300x200: 45920 pixels differ from GL_NEAREST's, expected 0: FAIL")"
expect "wrong mirror (seed 002 as printed): differs at the integers" "$(has "$r" "8 texels, the 7 integers s = -3..3: 7 texels differ from GL_MIRRORED_REPEAT's, expected 0: FAIL")"
expect "wrong mirror agrees between integers" "$(has "$r" "8 texels, 1008 coordinates from -3 to 3 between integers: 0 texels differ")"
expect "wrong scanline (no fill rule): the shared edge covered twice" "$(has "$r" "two triangles sharing the edge (56,8)-(8,56): 0 pixels missing, 0 extra, 0 with other (s,t), 48 covered twice; expected 0: FAIL")"
expect "wrong cube (one projection along Z): -Z mirrored" "$(has "$r" "(mirrored left-right), expected")"
expect "wrong cube: +Z is right" "$(has "$r" "face +Z: (s,t) near its corners (0.04,0.04) (0.96,0.04) (0.96,0.96) (0.04,0.96), expected")"
expect "wrong planar wrap (seed 002's Z as printed): Z differs, X and Y agree" "$(has "$r" "along Z: 1000 of 1000 points differ")"
expect "wrong planar wrap: X agrees" "$(has "$r" "along X: 0 of 1000 points differ")"
expect "wrong planar wrap: the sphere along Z is off GL_OBJECT_LINEAR texgen's" "$(has "$r" "along Z: the sphere's 11481 pixels, 11360 with another texel")"
expect "wrong sphere map (seed 002's, from the normal): off GL's" "$(has "$r" "1000 of 1000 points more than 1.5 texels of 2048 from GL_SPHERE_MAP's")"
expect "wrong bump (raw differences on the unit normal): 10.83 deg" "$(has "$r" "over 1024 texels: 10.83 deg (largest 23.30), expected at most 1: FAIL")"
for n in $names; do expect "wrong $n: FAIL" "$(has "$r" "| $n | FAIL")"; done

r=$("$checker" --all --impl crash --out "$out"); code=$?
expect "crashing code fails (exit 1, got $code)" $([ $code = 1 ]; echo $?)
# (signal 11 here; under a sanitizer, which catches the signal, an exit status)
for n in $names; do expect "crash $n: one line" "$(has "$r" "$n: FAIL: your code crashed (")"; done

r=$("$checker" vi1_back_seam mirror_wrap --impl hang --time-limit 2 --out "$out"); code=$?
expect "looping code fails (exit 1, got $code)" $([ $code = 1 ]; echo $?)
for n in vi1_back_seam mirror_wrap; do expect "hang $n: one line" "$(has "$r" "$n: FAIL: your code did not finish within 2 s")"; done

r=$("$checker" --all --impl nan --out "$out"); code=$?
expect "NaN fails (exit 1, got $code)" $([ $code = 1 ]; echo $?)
expect "nan vi1: named" "$(has "$r" "vi1_back_seam: FAIL: cylinderS(")"
expect "nan vi2: named" "$(has "$r" "vi2_torus_front: FAIL: torusST(")"
expect "out of range mirror: named" "$(has "$r" "mirror_wrap: FAIL: mirrorTexel(")"
expect "nan scanline: named" "$(has "$r" "scanline: FAIL: plot's s returned NaN")"
for n in lab2_cube lab3_planar_wrap sphere_map bump_gradient; do expect "nan $n: named" "$(has "$r" "$n: FAIL: ")"; done

err=$("$checker" no_such_exercise 2>&1 >/dev/null); code=$?
expect "an unknown exercise: exit 2 (got $code), one line" $([ $code = 2 ] && [ "$(wc -l <<<"$err")" = 1 ]; echo $?)
err=$("$checker" 2>&1 >/dev/null); code=$?
expect "no exercise named: exit 2 (got $code)" $([ $code = 2 ]; echo $?)

echo "$fails failed"
[ $fails = 0 ]
