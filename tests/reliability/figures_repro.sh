#!/usr/bin/env bash
# tests/reliability/figures_repro.sh MAKE_FIGURES RELIABILITY_TOOL FIRST_RUN [--backends]
# — figures are reproducible and written atomically.  FIRST_RUN is the folder
# the figures_render fixture wrote (make_figures --backend osmesa --out
# FIRST_RUN --export-c: the one regeneration the quick level's figure tests
# share).
#   1. a second run into another folder gives byte-identical PNGs, GL
#      listings (and sidecars, once the folder name in their commands is
#      replaced);
#   3. runs killed (SIGKILL) while a file is being written leave no partial
#      PNG and no temporary file: every *.png present decodes completely.
# With --backends (the full level), instead:
#   2. OSMesa and EGL give byte-identical PNGs except the figures listed in
#      a backend_bound row in their demo's facts file (demos/*/facts.tsv),
#      whose differences stay within the stated bounds (pixels that differ,
#      largest channel difference).
# With --hidden (the quick level), the same for the hidden-window backend (a
# hidden GLFW window and a framebuffer object: Windows' offscreen backend)
# against OSMesa, within the hidden_bound rows, on the first figure each demo
# lists (every demo's drawing code through the backend at a quarter of the
# cost of all figures; TS_HIDDEN_FIGURES=all renders every one); it needs a
# display, so without one it runs under xvfb-run (77: skipped, without
# xvfb-run).
set -u
FIGS=$(readlink -f "${1:?usage: figures_repro.sh MAKE_FIGURES RELIABILITY_TOOL FIRST_RUN [--backends|--hidden]}")
TOOL=$(readlink -f "${2:?usage: figures_repro.sh MAKE_FIGURES RELIABILITY_TOOL FIRST_RUN [--backends|--hidden]}")
A=$(readlink -f "${3:?usage: figures_repro.sh MAKE_FIGURES RELIABILITY_TOOL FIRST_RUN [--backends|--hidden]}")
part=${4:-}
HERE=$(cd "$(dirname "$0")" && pwd)
T=$(mktemp -d "${TMPDIR:-/tmp}/ts_figures_repro.XXXXXX")
trap 'rm -rf "$T"' EXIT
failures=0 checks=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
pass() { checks=$((checks + 1)); }
[ -n "$(ls "$A"/*.png 2>/dev/null)" ] || { echo "FAIL: no figures in $A (the figures_render fixture)"; exit 1; }

figs() { "$FIGS" --out "$@" >"$T/log" 2>&1 || fail "make_figures --out $*: $(tail -3 "$T/log")"; }

if [ "$part" != --backends ] && [ "$part" != --hidden ]; then
# ---------------------------------------------------- 1. run to run
figs "$T/b" --backend osmesa
n=0
for f in "$A"/*.png; do
  n=$((n + 1))
  name=$(basename "$f")
  if cmp -s "$f" "$T/b/$name"; then pass; else fail "$name differs between two OSMesa runs"; fi
  json=${name%.png}.json
  if cmp -s <(sed "s|$A|OUT|g" "$A/$json") <(sed "s|$T/b|OUT|g" "$T/b/$json"); then pass
  else fail "$json differs between two runs (beyond the --out folder)"; fi
  listing=${name%.png}.gl.txt
  if [ ! -f "$A/$listing" ]; then fail "$listing was not written"
  elif cmp -s "$A/$listing" "$T/b/$listing"; then pass
  else fail "$listing differs between two runs"; fi
done
[ "$n" -gt 0 ] || fail "make_figures wrote no PNG"
echo "run to run: $n figures byte-identical"
fi

if [ "$part" = --backends ] || [ "$part" = --hidden ]; then
# ---------------------------------------------------- 2. OSMesa vs EGL, or vs a hidden window
if [ "$part" = --hidden ]; then
  other=hidden kind=hidden_bound label="the hidden window"
  if [ -z "${DISPLAY:-}" ]; then
    command -v xvfb-run >/dev/null || { echo "SKIPPED: no display and no xvfb-run"; exit 77; }
    figs() { xvfb-run -a -s "-screen 0 640x480x24" "$FIGS" --out "$@" >"$T/log" 2>&1 || fail "make_figures --out $*: $(tail -3 "$T/log")"; }
  fi
else
  other=egl kind=backend_bound label=EGL
fi
only=() compared=("$A"/*.png)
if [ "$part" = --hidden ] && [ "${TS_HIDDEN_FIGURES:-}" != all ]; then
  ids=$("$FIGS" --list | awk '!seen[$NF]++ { print $1 }')
  only=(--only "$(echo "$ids" | paste -sd, -)")
  compared=()
  for id in $ids; do compared+=("$A/$id.png"); done
fi
figs "$T/e" --backend "$other" "${only[@]}"
declare -A maxpx maxdiff
while read -r name px diff _; do
  case "$name" in ''|\#*) continue ;; esac
  maxpx[$name]=$px maxdiff[$name]=$diff
done < <(bash "$HERE/../../scripts/facts.sh" "$kind" || echo "FAILED 0 0")
[ -z "${maxpx[FAILED]:-}" ] || fail "scripts/facts.sh $kind: the demos' facts files do not read"
same=0 bounded=0
for f in "${compared[@]}"; do
  name=$(basename "$f" .png)
  if cmp -s "$f" "$T/e/$name.png"; then same=$((same + 1)); pass; continue; fi
  read -r px diff < <("$TOOL" diff "$f" "$T/e/$name.png") || { fail "$name: cannot compare"; continue; }
  if [ -z "${maxpx[$name]:-}" ]; then fail "$name: OSMesa and $label differ ($px pixels, up to $diff) and it has no $kind row in its demo's facts.tsv"
  elif [ "$px" -gt "${maxpx[$name]}" ] || [ "$diff" -gt "${maxdiff[$name]}" ]; then
    fail "$name: OSMesa and $label differ in $px pixels by up to $diff, over the stated ${maxpx[$name]} pixels / ${maxdiff[$name]}"
  else bounded=$((bounded + 1)); pass; echo "  $name: $px pixels differ, by up to $diff (bound ${maxpx[$name]} / ${maxdiff[$name]})"; fi
done
echo "OSMesa vs $label: $same figures byte-identical, $bounded within their stated bounds"
echo "figures_repro $part: $checks checks passed, $failures failed"
[ "$failures" -eq 0 ]
exit
fi

# ---------------------------------------------------- 3. killed mid-write
# TS_TEST_WRITE_PAUSE_MS makes every write pause half-way, while the data is
# in the unnamed (O_TMPFILE) file; we wait until the process holds such a
# file open in the output folder, then SIGKILL it.  --jobs 1: the figures in
# that one process (by default the demos are rendered in children of it,
# each writing the same way), so the process watched is the one writing.
for round in 1 2 3; do
  out="$T/k$round"
  mkdir -p "$out"
  TS_TEST_WRITE_PAUSE_MS=400 "$FIGS" --jobs 1 --backend osmesa --out "$out" >/dev/null 2>&1 &
  pid=$!
  caught=0
  # Skip $round writes first, so the kill lands on different files.  Waits
  # on the event (a write in progress), for as long as the process runs: no
  # count of polls that a busy machine could exhaust.  After a catch, waits
  # for that file to be written (its unnamed file gone) before looking again.
  while kill -0 "$pid" 2>/dev/null; do
    if ls -l /proc/$pid/fd 2>/dev/null | grep -q "$out/.*(deleted)\|$out/#"; then
      caught=$((caught + 1))
      [ "$caught" -ge "$round" ] && break
      while kill -0 "$pid" 2>/dev/null && ls -l /proc/$pid/fd 2>/dev/null | grep -q "$out/.*(deleted)\|$out/#"; do
        sleep 0.02
      done
    else
      sleep 0.02
    fi
  done
  kill -KILL "$pid" 2>/dev/null
  wait "$pid" 2>/dev/null
  if [ "$caught" -lt "$round" ]; then fail "round $round: never saw a write in progress"; continue; fi
  pngs=("$out"/*.png)
  if [ -e "${pngs[0]}" ]; then
    if "$TOOL" check "${pngs[@]}"; then pass; else fail "round $round: a partial PNG was left"; fi
  fi
  # Finished files of any kind may stay (a listing or a CSV written before
  # the kill is whole: the writes are atomic); a temporary file may not.
  left=$(ls -A "$out" | grep -v '\.png$\|\.json$\|\.gl\.txt$\|\.csv$' || true)
  if [ -n "$left" ]; then fail "round $round: left behind: $left"; else pass; fi
  echo "killed mid-write (round $round): ${#pngs[@]} complete PNGs present, nothing partial"
done

echo "figures_repro: $checks checks passed, $failures failed"
[ "$failures" -eq 0 ]
