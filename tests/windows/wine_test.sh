#!/usr/bin/env bash
# tests/windows/wine_test.sh WINDOWS_BIN [LINUX_BUILD] — the Windows build
# (scripts/windows.sh: build-windows/bin/*.exe) run under Wine on a virtual X
# server, against the Linux build (default build/, made here if missing):
#   1. every book figure, rendered by its demo's .exe with --png and --json
#      (the hidden-window backend: Wine's OpenGL on Xvfb), against the same
#      figure from the Linux build (make_figures --backend osmesa): PNGs
#      byte-identical except the figures with a wine_bound row in their demo's
#      facts file (demos/*/facts.tsv), within their
#      bounds (pixels that differ, largest channel difference);
#   2. every measurement in those sidecars equal to Linux's within its
#      tolerance of a claim_bound row (default: the digits the demos print);
#   3. --help, an unknown flag, a missing file, a folder, and every malformed
#      file of tests/reliability/corpus: the same exit status and the same
#      output, line for line, as on Linux;
#   4. one window per demo opens, takes its first key, saves with F12
#      (<demo>-1.png and .json, and the command that remakes them) and closes;
#   5. the exercise checker as a child process (CreateProcess):
#      cylinder_seam --seam mine asks exercise_check.exe for its verdict.
# TS_WINE_PARTS (default "figures cli windows child") runs only those parts;
# TS_WINE_FIGURES (a bash glob, default *) only the figures it matches, or
# "per-demo": the first figure each demo lists (the full level's subset:
# every demo's drawing code under Wine at a quarter of the time);
# TS_WINE_WINDOWS (demos' names, default every demo) opens only those demos'
# windows (the window code is the same in every demo).
# Wine's helper processes inherit the output of the program that starts them
# and keep it open: wineserver is started persistent and the prefix booted
# with its output on /dev/null before any test, each run has a time limit,
# and wineserver -k ends them all at the end, however the script ends.
set -u
WIN=$(readlink -f "${1:?usage: wine_test.sh WINDOWS_BIN [LINUX_BUILD]}")
HERE=$(cd "$(dirname "$0")" && pwd)
ROOT=$(cd "$HERE/../.." && pwd)
LINUX=$(readlink -f "${2:-$ROOT/build}")
if [ -z "${DISPLAY:-}" ]; then
  exec xvfb-run -a -s "-screen 0 1600x1200x24" bash "$0" "$@"
fi
export WINEPREFIX=${TS_WINEPREFIX:-${XDG_CACHE_HOME:-$HOME/.cache}/texture-suite-windows/wine-prefix}
export WINEDEBUG=-all
export WINEDLLOVERRIDES="mscoree,mshtml="  # no Mono or Gecko installer dialog
T=$(mktemp -d "${TMPDIR:-/tmp}/ts_wine_test.XXXXXX")
cleanup() { wineserver -k >/dev/null 2>&1; rm -rf "$T"; }
trap cleanup EXIT
failures=0 checks=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
pass() { checks=$((checks + 1)); }
now() { date +%s.%N; }
parts=" ${TS_WINE_PARTS:-figures cli windows child} "
part() { [[ "$parts" == *" $1 "* ]]; }
t0=$(now)

# ---- the Linux build to compare with
if [ ! -x "$LINUX/bin/make_figures" ] || [ ! -x "$LINUX/bin/reliability_tool" ]; then
  echo "== the Linux build ($LINUX) =="
  (cd "$ROOT" && cmake --preset default >/dev/null && nice -n 15 cmake --build --preset default) >"$T/linux_build.log" 2>&1 ||
    { tail -20 "$T/linux_build.log"; echo "FAIL: the Linux build"; exit 1; }
fi
TOOL=$LINUX/bin/reliability_tool

# ---- Wine: one prefix (made once, ~11 s), its server kept running
mkdir -p "$WINEPREFIX"
command -v wine >/dev/null && command -v wineserver >/dev/null ||
  { echo "FAIL: no wine or wineserver command (Debian's package wine; scripts/windows.sh installs it)"; exit 1; }
wineserver -p >/dev/null 2>&1
wine wineboot </dev/null >/dev/null 2>&1
# No debugger on a crash: Wine's would wait for a user until the time limit;
# without it the program ends at once with its fault (a failure here).
wine reg add 'HKLM\Software\Microsoft\Windows NT\CurrentVersion\AeDebug' /v Debugger /t REG_SZ /d '' /f \
  </dev/null >/dev/null 2>&1
t_wine=$(now)
# w SECONDS EXE ARGS...: runs a Windows program from the current folder;
# its stdout and stderr in ./out and ./err with Windows' \r removed.
# Wine now and then ends a run with status 1 and nothing on stderr (twice
# in about 8,000 runs: a figure, and a malformed file that fails with its
# message on every other run; 400 reruns of each under load never did).  The
# programs say why on every failure of their own, so such a run is Wine's:
# it is noted, counted and run once more; a second one in a row stands.
w() {
  local limit=$1 exe=$2
  shift 2
  timeout "$limit" wine "$WIN/$exe.exe" "$@" </dev/null >out.raw 2>err.raw
  local rc=$?
  if [ "$rc" -ne 0 ] && [ "$rc" -ne 124 ] && [ ! -s err.raw ]; then
    echo "  $exe $*: Wine ended it with status $rc and nothing on stderr; run once more"
    echo >>"$T/silent_reruns"
    timeout "$limit" wine "$WIN/$exe.exe" "$@" </dev/null >out.raw 2>err.raw
    rc=$?
  fi
  tr -d '\r' <out.raw >out
  tr -d '\r' <err.raw >err
  return $rc
}

# Wine on Xvfb now and then ends a run that has written its output with a
# page fault (the same address each time; no run faulted twice in a row;
# in demos' windows too: 3 of 50 window runs on 2026-12-07, each passing
# when run again), and once, with another Xvfb job
# beside it, could not make GLFW's helper window ("Failed to create helper
# window: Resource data not found").  faulted ERR: whether a run's stderr
# says so; the parts run such a run once more, and a second fault fails.
wine_fault='Unhandled|Failed to create helper window'
faulted() { grep -Eq "$wine_fault" "$1"; }

# ---- 1 and 2: every figure, PNG and measurements
if part figures; then
echo "== figures: Linux (OSMesa) =="
only=()
if [ "${TS_WINE_FIGURES:-}" = per-demo ]; then
  only=(--only "$("$LINUX/bin/make_figures" --list | awk '!seen[$NF]++ { print $1 }' | paste -sd, -)")
elif [ -n "${TS_WINE_FIGURES:-}" ]; then
  ids=$("$LINUX/bin/make_figures" --list | awk '{print $1}' | while read -r id; do
          # shellcheck disable=SC2053
          [[ "$id" == $TS_WINE_FIGURES ]] && echo "$id"; done | paste -sd, -)
  only=(--only "$ids")
fi
"$LINUX/bin/make_figures" --backend osmesa --out "$T/linux" "${only[@]}" >"$T/linux.log" 2>&1 ||
  { tail -5 "$T/linux.log"; fail "make_figures on Linux"; }
t_linux=$(now)
declare -A maxpx maxdiff tol
while read -r name px diff _; do
  case "$name" in ''|\#*) continue ;; esac
  maxpx[$name]=$px maxdiff[$name]=$diff
done < <(bash "$HERE/../../scripts/facts.sh" wine_bound || echo "FAILED 0 0")
[ -z "${maxpx[FAILED]:-}" ] || fail "scripts/facts.sh wine_bound: the demos' facts files do not read"
tolerance() {  # the tolerance of measurement $1: the first claim_bound pattern it matches
  local name=$1 pat t
  while read -r pat t _; do
    case "$pat" in ''|\#*) continue ;; esac
    # shellcheck disable=SC2053
    if [[ "$name" == $pat ]]; then echo "$t"; return; fi
  done < <(bash "$HERE/../../scripts/facts.sh" claim_bound)
  echo 0.00005
}
echo "== figures: Windows (the demos' .exe under Wine, --backend auto) =="
mkdir -p "$T/win"
same=0 bounded=0 figures=0 numbers=0 faults=0
for json in "$T/linux"/*.json; do
  id=$(basename "$json" .json)
  [ -f "$T/linux/$id.png" ] || continue
  figures=$((figures + 1))
  # The figure's command as the sidecar records it: build/bin/<demo> --png ... flags.
  cmd=$(sed -n 's/^  "command": "\(.*\)",$/\1/p' "$json")
  eval "set -- $cmd"
  demo=$(basename "$1")
  shift
  args=()
  while [ $# -gt 0 ]; do
    case "$1" in
      --png) args+=(--png "$id.png"); shift 2 ;;
      --json) args+=(--json "$id.json"); shift 2 ;;
      *) args+=("$1"); shift ;;
    esac
  done
  (cd "$T/win" && w 120 "$demo" "${args[@]}")
  rc=$?
  # A Wine fault (faulted, above) is counted and run once more; a second
  # fails.  (A silent status 1 is w's to run again.)
  if faulted "$T/win/err"; then
    faults=$((faults + 1))
    echo "  $id: Wine reported a fault (exit status $rc): $(grep -Em1 "$wine_fault" "$T/win/err" || echo 'nothing on stderr'); run once more"
    rm -f "$T/win/$id.png" "$T/win/$id.json"
    (cd "$T/win" && w 120 "$demo" "${args[@]}")
    rc=$?
    if faulted "$T/win/err"; then
      fail "$id: Wine reported a fault twice (exit status $rc): $(grep -Em1 "$wine_fault" "$T/win/err" || echo 'nothing on stderr')"
      continue
    fi
  fi
  if [ "$rc" -ne 0 ]; then fail "$id: $demo.exe exit status $rc: $(head -c 400 "$T/win/err")"; continue; fi
  if [ ! -f "$T/win/$id.png" ]; then fail "$id: no PNG"; continue; fi
  if cmp -s "$T/linux/$id.png" "$T/win/$id.png"; then same=$((same + 1)); pass
  else
    read -r px diff < <("$TOOL" diff "$T/linux/$id.png" "$T/win/$id.png") || { fail "$id: cannot compare"; continue; }
    if [ -z "${maxpx[$id]:-}" ]; then fail "$id: Linux and Windows differ ($px pixels, up to $diff) and it has no wine_bound row in its demo's facts.tsv"
    elif [ "$px" -gt "${maxpx[$id]}" ] || [ "$diff" -gt "${maxdiff[$id]}" ]; then
      fail "$id: Linux and Windows differ in $px pixels by up to $diff, over the stated ${maxpx[$id]} pixels / ${maxdiff[$id]}"
    else bounded=$((bounded + 1)); pass; echo "  $id: $px pixels differ, by up to $diff (bound ${maxpx[$id]} / ${maxdiff[$id]})"; fi
  fi
  "$TOOL" measurements "$json" | sort >"$T/m_linux"
  "$TOOL" measurements "$T/win/$id.json" | sort >"$T/m_win"
  if ! cmp -s <(cut -f1 "$T/m_linux") <(cut -f1 "$T/m_win"); then
    fail "$id: Windows measures other quantities than Linux: $(diff <(cut -f1 "$T/m_linux") <(cut -f1 "$T/m_win") | head -4 | tr '\n' ' ')"
    continue
  fi
  while IFS=$'\t' read -r name a b; do
    t=$(tolerance "$name")
    numbers=$((numbers + 1))
    if awk -v a="$a" -v b="$b" -v t="$t" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d <= t) }'; then pass
    else fail "$id: $name is $b on Windows, $a on Linux (tolerance $t)"; fi
  done < <(join -t $'\t' "$T/m_linux" "$T/m_win")
done
t_figs=$(now)
echo "figures: $figures rendered on Windows: $same byte-identical to Linux, $bounded within their wine_bound rows; $numbers measurements compared; $faults runs rerun after a Wine fault"
fi
t_figs=${t_figs:-$(now)} t_linux=${t_linux:-$t_figs}

# ---- 3: the command line's errors, as on Linux
if part cli; then
echo "== command line: exit status and messages =="
mkdir -p "$T/cli" && cd "$T/cli"
corpus=$ROOT/tests/reliability/corpus
# same NAME ARGS...: quad_distortion on Linux and on Windows, from an empty
# folder: the same exit status, stdout and stderr (the program's name as it
# prints it, "quad_distortion", is the same on both).
same_as_linux() {
  local name=$1
  shift
  rm -f ./*.png
  timeout 60 "$LINUX/bin/quad_distortion" "$@" </dev/null >lout 2>lerr
  local lrc=$?
  rm -f ./*.png
  w 60 quad_distortion "$@"
  local rc=$?
  if [ "$rc" -ne "$lrc" ]; then fail "$name: exit status $rc on Windows, $lrc on Linux: $(cat err)"
  elif ! cmp -s lerr err; then fail "$name: stderr differs: Linux '$(head -c 300 lerr)', Windows '$(head -c 300 err)'"
  elif ! cmp -s lout out; then fail "$name: stdout differs: $(diff lout out | head -6 | tr '\n' ' ')"
  else pass; fi
}
same_as_linux "--help" --help
same_as_linux "an unknown flag" --no-such-flag
same_as_linux "a missing file" --texture missing.png --png out.png
same_as_linux "a folder" --texture "$corpus" --png out.png
same_as_linux "a bad size" --size 0x7 --png out.png
bad=0
while IFS=$'\t' read -r name kind _; do
  [ "$kind" = error ] || continue
  cp "$corpus/$name" "./$name"
  same_as_linux "malformed $name" --texture "$name" --png out.png
  rm -f "./$name"
  bad=$((bad + 1))
done <"$corpus/MANIFEST"
echo "command line: --help, 4 errors and $bad malformed files compared"
fi
t_cli=$(now)

# ---- 4: one window per demo: a key, F12, closed
if part windows; then
echo "== windows: one per demo =="
for exe in "$WIN"/*.exe; do
  demo=$(basename "$exe" .exe)
  case "$demo" in make_figures|make_textures|exercise_*) continue ;; esac
  [ -x "$LINUX/bin/$demo" ] || continue
  if [ -n "${TS_WINE_WINDOWS:-}" ] && [[ " $TS_WINE_WINDOWS " != *" $demo "* ]]; then continue; fi
  # The demo's first letter key, from its --help ("  --option ...  key x  ..." lines).
  key=$("$LINUX/bin/$demo" --help | sed -n 's/^  --.* key \([a-zA-Z0-9]\)[ /].*/\1/p' | head -1)
  [ -n "$key" ] || key=h
  d="$T/window/$demo" && mkdir -p "$d" && cd "$d"
  w 120 "$demo" --size 640x480 --frames 3 --keys "$key"$'\x02' --screenshot window.png
  rc=$?
  if faulted err; then
    echo "  $demo window: Wine reported a fault (exit status $rc): $(grep -Em1 "$wine_fault" err); run once more"
    echo >>"$T/window_fault_reruns"
    rm -f "$d"/*
    w 120 "$demo" --size 640x480 --frames 3 --keys "$key"$'\x02' --screenshot window.png
    rc=$?
    if faulted err; then fail "$demo window: Wine reported a fault twice (exit status $rc): $(grep -Em1 "$wine_fault" err)"; continue; fi
  fi
  if [ "$rc" -ne 0 ]; then fail "$demo window: exit status $rc: $(head -c 300 err)"; continue; fi
  if [ ! -s window.png ] || [ ! -s "$demo-1.png" ] || [ ! -s "$demo-1.json" ]; then
    fail "$demo window: missing window.png or F12's $demo-1.png/.json: $(ls | tr '\n' ' ')"; continue
  fi
  if ! grep -q "^  $demo.exe --png $demo-1.png" out; then fail "$demo window: no command that remakes F12's picture: $(tail -3 out)"; continue; fi
  # The key changed the state: the remaking command carries more than the default's flags.
  "$LINUX/bin/$demo" --png default.png --json default.json --size 640x480 --quiet >/dev/null 2>&1
  if cmp -s <(sed -n 's/^  "state": \(.*\),$/\1/p' default.json) <(sed -n 's/^  "state": \(.*\),$/\1/p' "$demo-1.json"); then
    fail "$demo window: the key '$key' did not change the state F12 saved"; continue
  fi
  pass
done
fi
t_win=$(now)

# ---- 5: a child process: the exercise checker
if ! part child; then :
elif [ -x "$WIN/exercise_check.exe" ]; then
  echo "== child process: cylinder_seam --seam mine runs exercise_check.exe =="
  d="$T/child" && mkdir -p "$d" && cd "$d"
  w 300 cylinder_seam --seam mine --png seam.png
  rc=$?
  timeout 300 "$LINUX/bin/cylinder_seam" --seam mine --png lseam.png </dev/null >lout 2>lerr
  lrc=$?
  if [ "$rc" -ne "$lrc" ]; then fail "cylinder_seam --seam mine: exit status $rc on Windows, $lrc on Linux: $(head -c 300 err)"
  elif grep -q "no exercise checker" out err; then fail "cylinder_seam --seam mine: the checker did not run: $(cat err)"
  elif ! cmp -s <(grep -i "vi1_back_seam" lout lerr | sed 's/^l//') <(grep -i "vi1_back_seam" out err); then
    fail "cylinder_seam --seam mine: the checker's verdict differs: Linux $(grep -i vi1_back_seam lout lerr | head -2) / Windows $(grep -i vi1_back_seam out err | head -2)"
  else pass; fi
else
  fail "no exercise_check.exe in $WIN"
fi
t_end=$(now)

awk -v a="$t0" -v b="$t_wine" -v c="$t_linux" -v d="$t_figs" -v e="$t_cli" -v f="$t_win" -v g="$t_end" 'BEGIN {
  printf "times: Wine start %.1f s, Linux figures %.1f s, Windows figures %.1f s, command line %.1f s, windows %.1f s, child %.1f s\n",
    b - a, c - b, d - c, e - d, f - e, g - f }'
silent=0 && [ -f "$T/silent_reruns" ] && silent=$(wc -l <"$T/silent_reruns")
windowFaults=0 && [ -f "$T/window_fault_reruns" ] && windowFaults=$(wc -l <"$T/window_fault_reruns")
echo "wine_test: $checks checks passed, $failures failed; $silent runs rerun after Wine ended them silently, $windowFaults windows after a fault"
[ "$failures" -eq 0 ]
