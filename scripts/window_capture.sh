#!/usr/bin/env bash
# scripts/window_capture.sh DEMO WxH [OUT] — what a student sees in a demo's
# first seconds: spawns build/bin/DEMO at WxH under Xvfb and takes the
# screen (`import -window root`) about every 0.2 s for 3 s, as
# OUT/cap_NN_<seconds since the spawn>.png, with the window's frame log
# (TS_TEST_FRAME_LOG: "stage" when a first, coarse stage came, "result" when
# the numbers did) as OUT/frames.log.  Needs xvfb-run and ImageMagick.
#   scripts/window_capture.sh filter_zoo 1280x720 /tmp/cap
set -euo pipefail
cd "$(dirname "$0")/.."
demo=$1 size=$2 out=${3:-/tmp/window_capture/${1}_$2}
mkdir -p "$out"
if [ -z "${DISPLAY:-}" ]; then
  exec xvfb-run -a -s "-screen 0 1280x1024x24" "$0" "$demo" "$size" "$(realpath "$out")"
fi
TS_TEST_FRAME_LOG="$out/frames.log" "build/bin/$demo" --size "$size" --quiet >/dev/null 2>&1 &
pid=$!
t0=$(date +%s%N)
for i in $(seq -w 0 15); do
  sleep 0.2
  ms=$((($(date +%s%N) - t0) / 1000000))
  import -window root "$out/cap_${i}_$(printf '%d.%03d' $((ms / 1000)) $((ms % 1000)))s.png" 2>/dev/null || true
done
kill "$pid" 2>/dev/null || true
wait "$pid" 2>/dev/null || true
awk 'NR == 1 {t0 = $2} $1 == "stage" || $1 == "result" {printf "%s %.2f s after the first frame\n", $1, $2 - t0}' \
  "$out/frames.log"
echo "captures in $out"
