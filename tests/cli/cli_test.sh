#!/usr/bin/env bash
# tests/cli/cli_test.sh DEMO MAKE_FIGURES — the command-line contract of a
# demo (quad_distortion) and of make_figures, as a user meets it:
#   * bad input: exit status 2, exactly one line on stderr, no output file,
#     and quickly (every run is wrapped in `timeout 60`);
#   * --help lists every option and key; no display without --png is a
#     one-line hint at --png;
#   * a good --png run writes a PNG (and with --json a JSON sidecar);
#   * make_figures lists its figures, is byte-for-byte reproducible, and
#     rejects an unknown --only.
set -u
DEMO=$(readlink -f "${1:?usage: cli_test.sh DEMO MAKE_FIGURES}")
FIGS=$(readlink -f "${2:?usage: cli_test.sh DEMO MAKE_FIGURES}")
for exe in "$DEMO" "$FIGS"; do
  [ -x "$exe" ] || { echo "FAIL: $exe is not an executable"; exit 1; }
done
export TS_TEST_BACKEND=${TS_TEST_BACKEND:-osmesa}
BACKEND=$TS_TEST_BACKEND

T=$(mktemp -d "${TMPDIR:-/tmp}/ts_cli_test.XXXXXX")
trap 'rm -rf "$T"' EXIT
failures=0
checks=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
pass() { checks=$((checks + 1)); }

# run NAME CMD...: runs CMD with a 60 s limit; sets $rc, $out, $err.
run() {
  local name=$1; shift
  timeout 60 "$@" >"$T/out.$name" 2>"$T/err.$name"
  rc=$?
  out="$T/out.$name"
  err="$T/err.$name"
  if [ "$rc" -eq 124 ]; then fail "$name: timed out after 60 s"; fi
}

# Files in the scratch folder besides the captured stdout/stderr.
outputs() { (cd "$T/inputs" && find . -mindepth 1 | sort); }

# expect_usage_error NAME ARGS...: the demo, run in the scratch folder, must
# exit 2 with one line on stderr, nothing on stdout, and leave the folder as
# it was.
expect_usage_error() {
  local name=$1; shift
  local before after
  before=$(outputs)
  run "$name" bash -c 'cd "$0" && exec "$@"' "$T/inputs" "$DEMO" "$@"
  after=$(outputs)
  local lines
  lines=$(wc -l <"$err")
  if [ "$rc" -ne 2 ]; then fail "$name: exit status $rc, want 2 (stderr: $(cat "$err"))";
  elif [ "$lines" -ne 1 ]; then fail "$name: $lines lines on stderr, want 1:"; cat "$err";
  elif [ -s "$out" ]; then fail "$name: wrote to stdout: $(cat "$out")"
  elif [ "$before" != "$after" ]; then fail "$name: created files: $(diff <(echo "$before") <(echo "$after") | grep '^>')";
  else pass; fi
}

mkdir -p "$T/inputs/adir" "$T/inputs/adir.texels"
printf 'this is not a PNG\n' >"$T/inputs/text.png"
PNG_ARGS=(--backend "$BACKEND" --png out.png)

# ---------------------------------------------------------------- bad input
expect_usage_error unknown_flag "${PNG_ARGS[@]}" --nosuch
expect_usage_error unknown_value "${PNG_ARGS[@]}" --diagonal sideways
expect_usage_error positional "${PNG_ARGS[@]}" stray
for size in 0x10 -5x5 20000x10 abc 12x x12; do
  expect_usage_error "size_$size" "${PNG_ARGS[@]}" --size "$size"
done
expect_usage_error size_missing_value --png out.png --size
expect_usage_error png_missing_dir --backend "$BACKEND" --png nosuch/out.png
expect_usage_error png_trailing_slash --backend "$BACKEND" --png adir/
expect_usage_error png_is_a_dir --backend "$BACKEND" --png adir
expect_usage_error png_named_jpg --backend "$BACKEND" --png out.jpg
expect_usage_error json_missing_dir "${PNG_ARGS[@]}" --json nosuch/out.json
expect_usage_error json_without_png --json out.json
expect_usage_error listing_missing_dir --backend "$BACKEND" --gl-listing nosuch/gl.txt
expect_usage_error listing_is_a_dir --backend "$BACKEND" --gl-listing adir
expect_usage_error listing_in_a_window --backend window --gl-listing gl.txt
expect_usage_error export_missing_dir --backend "$BACKEND" --export-c nosuch/fig.c
expect_usage_error export_is_a_dir --backend "$BACKEND" --export-c adir
expect_usage_error export_texels_is_a_dir --backend "$BACKEND" --png out.png --export-c adir.c  # adir.texels beside it
expect_usage_error export_with_png_missing_dir "${PNG_ARGS[@]}" --export-c nosuch/fig.c
expect_usage_error export_in_a_window --backend window --export-c fig.c
expect_usage_error texture_missing "${PNG_ARGS[@]}" --texture missing.png
expect_usage_error texture_not_png "${PNG_ARGS[@]}" --texture text.png
expect_usage_error corners_garbage "${PNG_ARGS[@]}" --corners garbage
expect_usage_error corners_three "${PNG_ARGS[@]}" --corners "0,0 1,0 1,1"
expect_usage_error corners_collinear "${PNG_ARGS[@]}" --corners "0,0 0.5,0 1,0 0,1"
expect_usage_error corners_huge "${PNG_ARGS[@]}" --corners "0,0 1e9,0 1,1 0,1"
expect_usage_error checks_range "${PNG_ARGS[@]}" --checks 1
expect_usage_error backend_nonsense --backend nonsense --png out.png
expect_usage_error backend_window_png --backend window --png out.png
expect_usage_error frames_zero --frames 0

# ---------------------------------------------------------------- --help
run help "$DEMO" --help
if [ "$rc" -ne 0 ]; then fail "--help: exit status $rc"; else pass; fi
for word in --diagonal --interp --edges --view --filter --checks --texture --corners \
            --png --json --size --backend --frames --screenshot --keys --quiet \
            "d: diagonal" "i: interp" "e: edges" "v: view" "f: filter" "+/-: checks" "esc/q: quit"; do
  if grep -qF -- "$word" "$out"; then pass; else fail "--help does not mention '$word'"; fi
done
if [ -s "$err" ]; then fail "--help wrote to stderr: $(cat "$err")"; else pass; fi

# ------------------------------------------------- no display, no --png
run nodisplay env -u DISPLAY -u WAYLAND_DISPLAY "$DEMO" --diagonal bl-tr
if [ "$rc" -ne 2 ]; then fail "no display: exit status $rc, want 2"; else pass; fi
if [ "$(wc -l <"$err")" -ne 1 ] || ! grep -q -- "--png" "$err"; then
  fail "no display: want one stderr line mentioning --png, got:"; cat "$err"
else pass; fi

# ---------------------------------------------------------------- good runs
run good "$DEMO" --backend "$BACKEND" --png "$T/good.png" --json "$T/good.json" --size 320x200 --view compare
if [ "$rc" -ne 0 ]; then fail "good run: exit status $rc: $(cat "$err")"; else pass; fi
if [ "$(head -c 8 "$T/good.png" 2>/dev/null | od -An -tx1 | tr -d ' \n')" = "89504e470d0a1a0a" ]; then pass
else fail "good run: $T/good.png does not start with the PNG signature"; fi
# IHDR width and height (big-endian at bytes 16..23): 320 x 200.
if [ "$(head -c 24 "$T/good.png" | tail -c 8 | od -An -tx1 | tr -d ' \n')" = "00000140000000c8" ]; then pass
else fail "good run: PNG is not 320x200"; fi
if command -v python3 >/dev/null; then
  if python3 -m json.tool "$T/good.json" >/dev/null; then pass; else fail "good run: invalid JSON sidecar"; fi
fi
if grep -q '"panels"' "$T/good.json" && grep -q '"kink_deg\[affine_tl_br\]"' "$T/good.json"; then pass
else fail "good run: sidecar lacks panels or the kink measurement"; fi
if grep -q 'kink_deg\[affine_tl_br\]' "$out"; then pass; else fail "good run: measurement not printed"; fi
if ls "$T" | grep -q '\.tmp-'; then fail "good run: temporary files left: $(ls "$T")"; else pass; fi
# The sidecar's "command" (shell-quoted) reproduces the same PNG bytes.
cmd=$(sed -n 's/^  "command": "\(.*\)",$/\1/p' "$T/good.json" | sed 's/\\"/"/g')
case "$cmd" in
  build/bin/quad_distortion\ *)
    cp "$T/good.png" "$T/good.first.png"
    run replay bash -c "exec \"\$0\" --backend $BACKEND --quiet ${cmd#build/bin/quad_distortion }" "$DEMO"
    if [ "$rc" -ne 0 ]; then fail "sidecar command failed ($rc): $cmd: $(cat "$err")"
    elif cmp -s "$T/good.first.png" "$T/good.png"; then pass
    else fail "sidecar command made a different PNG: $cmd"; fi ;;
  *) fail "sidecar has no usable command: '$cmd'" ;;
esac
# --quiet prints nothing.
run quiet "$DEMO" --backend "$BACKEND" --png "$T/quiet.png" --size 64x64 --quiet
if [ "$rc" -ne 0 ] || [ -s "$out" ]; then fail "--quiet: status $rc, stdout: $(cat "$out")"; else pass; fi

# ---------------------------------------------------------------- make_figures
run list "$FIGS" --list
if [ "$rc" -ne 0 ]; then fail "make_figures --list: exit status $rc"; else pass; fi
for id in vi1_quad_distortion vi1_quad_variants; do
  if grep -q "^$id " "$out"; then pass; else fail "make_figures --list lacks $id"; fi
done

# Twice into the same folder (the sidecars quote the --out path in their
# commands), keeping the first run's files aside: byte-identical.  This demo's
# figures only (--only takes a demo name): every figure and the gallery, run to
# run and across backends, is tests/reliability/figures_repro.sh, which runs
# once; this script also runs on softpipe, where the parallax figures' twelve
# full-frame GLSL passes alone take minutes.
mkdir -p "$T/figs" "$T/figs.first" "$T/figs.other"
run figs1 "$FIGS" --backend "$BACKEND" --out "$T/figs" --only quad_distortion
if [ "$rc" -ne 0 ]; then fail "make_figures --out: exit status $rc: $(cat "$err")"; else pass; fi
cp -p "$T/figs"/* "$T/figs.first/" 2>/dev/null
# The second run exports the figures as C programs too (--export-c: what
# export_c builds and runs; here the export code runs under the ASan preset).
run figs2 "$FIGS" --backend "$BACKEND" --out "$T/figs" --only quad_distortion --export-c
if [ "$rc" -ne 0 ]; then fail "make_figures --out (again): exit status $rc: $(cat "$err")"; else pass; fi
for f in vi1_quad_distortion.c vi1_quad_variants.c; do
  if [ -s "$T/figs/$f" ]; then pass; else fail "make_figures --export-c did not write $f"; fi
done
for f in vi1_quad_distortion.png vi1_quad_distortion.json vi1_quad_distortion.gl.txt vi1_quad_variants.png \
         vi1_quad_variants.json vi1_quad_variants.gl.txt; do
  if [ ! -s "$T/figs.first/$f" ]; then fail "make_figures did not write $f"; continue; fi
  if cmp -s "$T/figs.first/$f" "$T/figs/$f"; then pass; else fail "make_figures: $f differs between two runs"; fi
done
# Every figure has its PNG and sidecar, and no temporary file is left behind.
if ls "$T/figs" | grep -q '\.tmp-'; then fail "make_figures left temporary files: $(ls "$T/figs")"; else pass; fi
for png in "$T/figs"/*.png; do
  if [ -s "${png%.png}.json" ]; then pass; else fail "make_figures: $(basename "$png") has no sidecar"; fi
done
# Into another folder: the same pictures (the PNGs hold no path).
run figs3 "$FIGS" --backend "$BACKEND" --out "$T/figs.other" --only vi1_quad_variants
if [ "$rc" -ne 0 ]; then fail "make_figures --only vi1_quad_variants: exit status $rc"; else pass; fi
if cmp -s "$T/figs/vi1_quad_variants.png" "$T/figs.other/vi1_quad_variants.png"; then pass
else fail "make_figures: vi1_quad_variants.png differs between output folders"; fi
if [ "$(ls "$T/figs.other")" = "$(printf 'vi1_quad_variants.gl.txt\nvi1_quad_variants.json\nvi1_quad_variants.png')" ]; then pass
else fail "make_figures --only wrote: $(ls "$T/figs.other")"; fi

run only_nosuch "$FIGS" --backend "$BACKEND" --out "$T/figs.none" --only nosuch
if [ "$rc" -eq 0 ]; then fail "make_figures --only nosuch: exit status 0"; else pass; fi
if [ "$(wc -l <"$err")" -ne 1 ]; then fail "make_figures --only nosuch: want one stderr line, got:"; cat "$err"; else pass; fi
if [ -e "$T/figs.none" ]; then fail "make_figures --only nosuch created its --out folder"; else pass; fi
run figs_bad_arg "$FIGS" --nosuch
if [ "$rc" -eq 0 ] || [ "$(wc -l <"$err")" -ne 1 ]; then fail "make_figures --nosuch: status $rc, stderr: $(cat "$err")"; else pass; fi

# The smallest sizes are sizes too: jitter's accumulation-buffer probe used
# 4x4 pixels whatever the target (exit 1 at --size 3x3).
JITTER="$(dirname "$DEMO")/jitter"
if [ -x "$JITTER" ]; then
  run jitter3 "$JITTER" --backend "$BACKEND" --png "$T/j3.png" --size 3x3 --quiet
  if [ "$rc" -ne 0 ] || [ ! -s "$T/j3.png" ] || [ -s "$T/err.jitter3" ]; then
    fail "jitter --size 3x3: exit $rc, stderr: $(cat "$T/err.jitter3")"; else pass; fi
fi

echo "$checks checks passed, $failures failed"
[ "$failures" -eq 0 ]
