#!/usr/bin/env bash
# tests/cli/texture_test.sh BIN_DIR CORPUS — `--texture FILE` in every demo
# that maps a picture, as a student meets it:
#   * --help shows `--texture FILE` and names the formats (PNG, JPEG, BMP);
#     no file option shows TEXT;
#   * a small PNG, a JPEG and a 32-bit BMP with alpha each render (exit 0)
#     and change the picture (the PNG differs from the default render's);
#   * a bad file (not an image, a truncated JPEG, a huge JPEG header, a
#     32-bit BMP with bad masks): exit 2, one line on stderr naming the file,
#     nothing on stdout, no output file.
set -u
BIN=$(readlink -f "${1:?usage: texture_test.sh BIN_DIR CORPUS}")
CORPUS=$(readlink -f "${2:?usage: texture_test.sh BIN_DIR CORPUS}")
BACKEND=${TS_TEST_BACKEND:-osmesa}
T=$(mktemp -d "${TMPDIR:-/tmp}/ts_texture_test.XXXXXX")
trap 'rm -rf "$T"' EXIT
mkdir "$T/work"
failures=0 checks=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
pass() { checks=$((checks + 1)); }

# Each demo with flags that keep its render small and quick.
declare -A FLAGS=(
  [quad_distortion]=""
  [perspective_correction]=""
  [cylinder_seam]=""
  [sphere_projections]=""
  [torus]=""
  [mipmap_popping]=""
  [parallax_aniso]="--view single --res 80 --rays 2"
  [multitexture]="--view lightmap"
  [octant_mapping]="--view overview"
)
GOOD=(good_rgba8_37x23.png good_jpeg_blocks_32x24.jpg good_bmp32_alpha_5x3.bmp)
BAD=("text.jpg:not a PNG, JPEG or BMP" "jpeg_cut_in_half.jpg:Premature end" "jpeg_huge_65000x65000.jpg:over the limit"
     "bmp32_masks_overlap.bmp:overlap")
printf 'not a picture\n' >"$T/text.jpg"

for demo in quad_distortion perspective_correction cylinder_seam sphere_projections torus mipmap_popping parallax_aniso multitexture octant_mapping; do
  exe="$BIN/$demo"
  [ -x "$exe" ] || { fail "$demo: no program $exe"; continue; }
  read -r -a extra <<<"${FLAGS[$demo]}"
  help=$("$exe" --help 2>&1)
  line=$(grep -E '^ +--texture FILE ' <<<"$help")
  if [ -z "$line" ]; then fail "$demo --help: no '--texture FILE' line"
  elif ! grep -q "PNG, JPEG or 24/32-bit BMP" <<<"$line"; then fail "$demo --help: --texture does not name the formats: $line"
  else pass; fi
  if grep -qE -- '--(texture|csv|.*file.*) TEXT' <<<"$help"; then fail "$demo --help: a file option shows TEXT"; else pass; fi

  run() {  # run OUT [args...]: render into OUT, 256x160
    local out=$1; shift
    (cd "$T/work" && timeout 120 "$exe" --backend "$BACKEND" --size 256x160 --quiet "${extra[@]}" --png "$out" "$@" \
       >"$T/out" 2>"$T/err")
  }
  run "$T/default.png"; rc=$?
  [ "$rc" -eq 0 ] || { fail "$demo: the default render exits $rc: $(cat "$T/err")"; continue; }
  for g in "${GOOD[@]}"; do
    rm -f "$T/good.png"
    run "$T/good.png" --texture "$CORPUS/$g"; rc=$?
    if [ "$rc" -ne 0 ] || [ ! -s "$T/good.png" ]; then fail "$demo --texture $g: exit $rc: $(cat "$T/err")"
    elif cmp -s "$T/default.png" "$T/good.png"; then fail "$demo --texture $g: the picture did not change"
    else pass; fi
  done
  for b in "${BAD[@]}"; do
    name=${b%%:*} phrase=${b#*:}
    file="$CORPUS/$name"
    [ "$name" = text.jpg ] && file="$T/text.jpg"
    run out.png --texture "$file"; rc=$?
    if [ "$rc" -ne 2 ]; then fail "$demo --texture $name: exit $rc, want 2: $(cat "$T/err")"
    elif [ "$(wc -l <"$T/err")" -ne 1 ]; then fail "$demo --texture $name: $(wc -l <"$T/err") lines on stderr, want 1"
    elif ! grep -qF -- "$file" "$T/err" || ! grep -qF -- "$phrase" "$T/err"; then
      fail "$demo --texture $name: the line lacks the file or '$phrase': $(cat "$T/err")"
    elif [ -s "$T/out" ]; then fail "$demo --texture $name: wrote to stdout"
    elif [ -n "$(ls -A "$T/work")" ]; then fail "$demo --texture $name: left $(ls -A "$T/work")"; rm -rf "$T/work"/*
    else pass; fi
  done
done
# octant_mapping with a bundled image (textures/, Rogers' "scanned" pattern) and a path that is not there.
exe="$BIN/octant_mapping"
if [ -x "$exe" ]; then
  bundled="$PWD/textures/labelled_grid_512_8.png"
  (cd "$T/work" && timeout 120 "$exe" --backend "$BACKEND" --size 256x160 --quiet --png "$T/bundled.png" \
     --texture "$bundled" >"$T/out" 2>"$T/err"); rc=$?
  if [ "$rc" -ne 0 ] || [ ! -s "$T/bundled.png" ]; then fail "octant_mapping --texture $bundled: exit $rc: $(cat "$T/err")"
  else pass; fi
  (cd "$T/work" && timeout 120 "$exe" --backend "$BACKEND" --size 256x160 --quiet --png "$T/missing.png" \
     --texture "$T/no_such_file.png" >"$T/out" 2>"$T/err"); rc=$?
  if [ "$rc" -ne 2 ] || [ "$(wc -l <"$T/err")" -ne 1 ] || ! grep -qF "no_such_file.png" "$T/err" || [ -e "$T/missing.png" ]
  then fail "octant_mapping --texture (missing file): exit $rc, stderr: $(cat "$T/err")"
  else pass; fi
fi
echo "texture_test: $checks checks passed, $failures failed"
[ "$failures" -eq 0 ]
