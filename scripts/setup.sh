#!/usr/bin/env bash
# Installs what the suite needs from Debian's packages, and nothing when it is
# all there already.  Run as root (CI does) or with sudo available.
set -euo pipefail

packages=(
  g++ make cmake pkg-config git          # toolchain
  libgl-dev libegl-dev                   # GL and EGL headers (no GL library is linked)
  libosmesa6 libosmesa6-dev              # OSMesa, the default offscreen backend (dlopen'ed)
  libegl1 libegl-mesa0 libgl1-mesa-dri   # EGL surfaceless backend and Mesa's llvmpipe/softpipe
  libgl1 libglx-mesa0                    # GLX for the window backend (GLFW dlopens libGL.so.1)
  libglfw3-dev libglm-dev libpng-dev libjpeg62-turbo-dev libimgui-dev libstb-dev
  nlohmann-json3-dev                     # JSON: the sidecars are written and read with it
  googletest libgtest-dev libbenchmark-dev
  xvfb xauth                             # window tests under a virtual X server
  xdotool imagemagick                    # window tests: real X key events, and the screen read back (import)
  clang libclang-rt-14-dev               # libFuzzer and its sanitizer runtimes (fuzz preset)
  valgrind zlib1g-dev                    # memcheck over a figure run; zlib for the corpus generator
  clang-format                           # the style check (tests/format_check.sh)
  fonts-dejavu-extra                     # the labels' font, compiled in (DejaVu Sans Condensed)
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "setup: installing ${missing[*]}" >&2
SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then SUDO=sudo; else
    echo "setup: need root to install: ${missing[*]}" >&2
    exit 1
  fi
fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
