#!/usr/bin/env bash
# The Windows package, made on Debian 12 (as root) with MinGW-w64:
#
#   bash scripts/windows.sh          install what is missing, cross-build the
#                                    dependencies (once: cached), every demo and
#                                    make_figures as static .exe files, and
#                                    write dist/texture-demos-windows-x64.zip
#   bash scripts/windows.sh --test   the same, then run the programs under Wine
#                                    on a virtual X server and compare them
#                                    with the Linux build (tests/windows/)
#
# The dependencies come from Debian's source packages (glfw3, libpng1.6,
# libjpeg-turbo, imgui; zlib prebuilt from libz-mingw-w64-dev; GLM,
# nlohmann-json and stb are headers, taken from the Debian packages).  Each is
# built into ${XDG_CACHE_HOME:-~/.cache}/texture-suite-windows/<package>-<version>/,
# outside the checkout, so a second run (or a second checkout) rebuilds none
# of them; a new Debian version of a package gets a folder of its own.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
mode=build
case "${1:-}" in
  --test) mode=test ;;
  "") ;;
  *) echo "usage: bash scripts/windows.sh [--test]" >&2; exit 2 ;;
esac
jobs=${TS_JOBS:-$(nproc)}
t_start=$(date +%s)

# ---- Debian packages
# wine: the launchers (wine, wineserver) in /usr/bin, which wine64 alone,
# installed without its recommends, does not put there.
packages=(mingw-w64 wine64 wine libz-mingw-w64-dev dpkg-dev cmake make pkg-config zip unzip
          libglm-dev nlohmann-json3-dev libstb-dev xvfb xauth fonts-dejavu-extra)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
# `apt-get source` needs deb-src entries: one file mirroring Debian's deb
# entries (deb822 or one-line form), added once.
need_update=0
if ! grep -rqsE '^(Types:.*deb-src|deb-src )' /etc/apt/sources.list /etc/apt/sources.list.d/; then
  if [ "$(id -u)" -ne 0 ]; then echo "windows: run as root (adds a deb-src entry, installs packages)" >&2; exit 1; fi
  for f in /etc/apt/sources.list.d/*.sources; do
    [ -e "$f" ] && grep -q '^Types: deb$' "$f" && sed 's/^Types: deb$/Types: deb-src/' "$f"
  done > /etc/apt/sources.list.d/texture-suite-deb-src.sources
  [ -s /etc/apt/sources.list.d/texture-suite-deb-src.sources ] || rm -f /etc/apt/sources.list.d/texture-suite-deb-src.sources
  if [ -f /etc/apt/sources.list ]; then
    grep -E '^deb ' /etc/apt/sources.list | sed 's/^deb /deb-src /' > /etc/apt/sources.list.d/texture-suite-deb-src.list || true
    [ -s /etc/apt/sources.list.d/texture-suite-deb-src.list ] || rm -f /etc/apt/sources.list.d/texture-suite-deb-src.list
  fi
  need_update=1
fi
if [ ${#missing[@]} -gt 0 ] || [ "$need_update" = 1 ]; then
  if [ "$(id -u)" -ne 0 ]; then echo "windows: need root to install: ${missing[*]}" >&2; exit 1; fi
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  if [ ${#missing[@]} -gt 0 ]; then
    echo "windows: installing ${missing[*]}" >&2
    apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
  fi
fi

# ---- the dependencies, cross-built once per Debian version
cache=${XDG_CACHE_HOME:-$HOME/.cache}/texture-suite-windows
mkdir -p "$cache"
toolchain=$root/scripts/mingw-w64.cmake
srcversions() {  # the versions Debian lists, highest first
  apt-cache showsrc "$1" 2>/dev/null | sed -n 's/^Version: //p' | sort -rV | uniq
}
prefixes=()
# dep PACKAGE RECIPE: runs RECIPE SRC PREFIX on the source of the highest
# version that downloads (an index can list a version its mirror no longer
# holds), unless a version's <package>-<version>/.built is there already;
# adds the prefix either way.
dep() {
  local pkg=$1 recipe=$2 ver dir="" versions
  versions=$(srcversions "$pkg")
  [ -n "$versions" ] || { echo "windows: no Debian source package '$pkg' (is a deb-src entry there?)" >&2; exit 1; }
  for ver in $versions; do
    if [ -f "$cache/$pkg-${ver//:/_}/.built" ]; then dir=$cache/$pkg-${ver//:/_}; break; fi
  done
  if [ -z "$dir" ]; then
    for ver in $versions; do
      dir=$cache/$pkg-${ver//:/_}
      rm -rf "$dir" && mkdir -p "$dir/src"
      if (cd "$dir/src" && apt-get source -qq "$pkg=$ver" >/dev/null 2>&1); then break; fi
      rm -rf "$dir"
      dir=""
    done
    [ -n "$dir" ] || { echo "windows: no version of the source package $pkg downloads" >&2; exit 1; }
    echo "windows: cross-building $pkg $ver into $dir" >&2
    local src t0
    t0=$(date +%s)
    src=$(find "$dir/src" -mindepth 1 -maxdepth 1 -type d | head -1)
    (TS_WINDOWS_PREFIXES="${prefixes[*]}" "$recipe" "$src" "$dir/prefix") > "$dir/build.log" 2>&1 ||
      { echo "windows: building $pkg failed; the log: $dir/build.log" >&2; tail -20 "$dir/build.log" >&2; exit 1; }
    rm -rf "$dir/src" "$dir/build"
    touch "$dir/.built"
    echo "windows: $pkg built in $(( $(date +%s) - t0 )) s" >&2
  fi
  prefixes+=("$dir/prefix")
}
cmake_dep() {  # SRC PREFIX CMAKE-ARGS...: a static library with its own CMake build
  local src=$1 prefix=$2
  shift 2
  cmake -S "$src" -B "$(dirname "$prefix")/build" -DCMAKE_TOOLCHAIN_FILE="$toolchain" -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_INSTALL_PREFIX="$prefix" -DBUILD_SHARED_LIBS=OFF "$@"
  nice -n 15 cmake --build "$(dirname "$prefix")/build" -j"$jobs"
  cmake --install "$(dirname "$prefix")/build"
}
build_glfw() {
  cmake_dep "$1" "$2" -DGLFW_BUILD_EXAMPLES=OFF -DGLFW_BUILD_TESTS=OFF -DGLFW_BUILD_DOCS=OFF
}
build_png() {
  cmake_dep "$1" "$2" -DPNG_SHARED=OFF -DPNG_STATIC=ON -DPNG_TESTS=OFF -DPNG_EXECUTABLES=OFF -DSKIP_INSTALL_PROGRAMS=ON
}
build_jpeg() {
  # No SIMD: it needs nasm, and the suite decodes a few small files.
  cmake_dep "$1" "$2" -DENABLE_SHARED=OFF -DENABLE_STATIC=ON -DWITH_TURBOJPEG=OFF -DWITH_SIMD=OFF
}
build_imgui() {
  # imgui has no build system of its own: the core and the GLFW backend, made
  # as Debian's package makes them, with stb's rect_pack and truetype from
  # the stb package (not imgui's copies), so that the labels' font, which the
  # suite rasterises with them, comes out in the same pixels as on Linux.
  local src=$1 prefix=$2 glfw b
  glfw=$(echo "$TS_WINDOWS_PREFIXES" | tr ' ' '\n' | grep '/glfw3-')/include
  b=$(dirname "$prefix")/build
  mkdir -p "$prefix/lib/pkgconfig" "$prefix/include/imgui/backends" "$b"
  local flags=(-O2 -std=c++17 "-I$src" "-I$glfw" "-I$headers/include"
               -DIMGUI_DISABLE_STB_RECT_PACK_IMPLEMENTATION '-DIMGUI_STB_RECT_PACK_FILENAME=<stb/stb_rect_pack.h>'
               -DIMGUI_DISABLE_STB_TRUETYPE_IMPLEMENTATION '-DIMGUI_STB_TRUETYPE_FILENAME=<stb/stb_truetype.h>')
  printf '#define STB_RECT_PACK_IMPLEMENTATION\n#include <stb/stb_rect_pack.h>\n#define STB_TRUETYPE_IMPLEMENTATION\n#include <stb/stb_truetype.h>\n' > "$b/stb_impl.c"
  local objs=("$b/stb_impl.o")
  nice -n 15 x86_64-w64-mingw32-gcc-posix -O2 "-I$headers/include" -c "$b/stb_impl.c" -o "$b/stb_impl.o"
  for f in imgui imgui_draw imgui_tables imgui_widgets imgui_demo backends/imgui_impl_glfw; do
    [ -f "$src/$f.cpp" ] || continue
    nice -n 15 x86_64-w64-mingw32-g++-posix "${flags[@]}" -c "$src/$f.cpp" -o "$b/$(basename "$f").o"
    objs+=("$b/$(basename "$f").o")
  done
  x86_64-w64-mingw32-ar rcs "$prefix/lib/libimgui.a" "${objs[@]}"
  cp "$src"/*.h "$prefix/include/imgui/"
  cp "$src"/backends/imgui_impl_glfw.h "$prefix/include/imgui/backends/"
  cat > "$prefix/lib/pkgconfig/imgui.pc" <<EOF
prefix=$prefix
libdir=\${prefix}/lib
includedir=\${prefix}/include/imgui
Name: imgui
Description: Dear ImGui, cross-built for Windows
Version: $(sed -n 's/^#define IMGUI_VERSION *"\(.*\)"/\1/p' "$src/imgui.h")
Libs: -L\${libdir} -limgui
Cflags: -I\${includedir} -I$headers/include
EOF
}

# Header-only libraries: Debian's Linux headers serve the cross build too,
# copied (not /usr/include itself, whose C library headers are Linux's).
hver=$(dpkg-query -W -f='${Version}' libglm-dev)_$(dpkg-query -W -f='${Version}' nlohmann-json3-dev)_$(dpkg-query -W -f='${Version}' libstb-dev)
headers=$cache/headers-${hver//:/_}/prefix
if [ ! -f "$headers/../.built" ]; then
  rm -rf "$(dirname "$headers")" && mkdir -p "$headers/include" "$headers/share/cmake"
  cp -r /usr/include/glm /usr/include/nlohmann /usr/include/stb "$headers/include/"
  cp -r /usr/share/cmake/glm /usr/share/cmake/nlohmann_json "$headers/share/cmake/"
  touch "$headers/../.built"
fi
prefixes+=("$headers")
dep glfw3 build_glfw
dep libpng1.6 build_png
dep libjpeg-turbo build_jpeg
dep imgui build_imgui
export TS_WINDOWS_PREFIXES="${prefixes[*]}"
export PKG_CONFIG_LIBDIR=$(printf '%s/lib/pkgconfig:' "${prefixes[@]}")
t_deps=$(date +%s)

# ---- the suite, cross-built
bw=${TS_WINDOWS_BUILD:-$root/build-windows}
cmake -S "$root" -B "$bw" -DCMAKE_TOOLCHAIN_FILE="$toolchain" -DCMAKE_BUILD_TYPE=Release \
  -DTS_BUILD_TESTS=OFF -DTS_BUILD_BENCHMARKS=OFF ${TS_WINDOWS_CMAKE_ARGS:-} >/dev/null
nice -n 15 cmake --build "$bw" -j"$jobs"
t_build=$(date +%s)

# ---- the zip: the programs, the textures, a README for the student
stage=$bw/package/texture-demos
rm -rf "$bw/package" && mkdir -p "$stage/textures"
for exe in "$bw"/bin/*.exe; do
  case "$(basename "$exe")" in
    make_textures.exe|exercise_*.exe|*_test.exe) ;;  # tools of the repository, not of the course
    *) x86_64-w64-mingw32-strip -o "$stage/$(basename "$exe")" "$exe" ;;  # no symbols: a smaller download
  esac
done
cp "$root"/textures/*.png "$stage/textures/"
# Windows' Notepad reads CRLF files best.
sed 's/$/\r/' "$root/scripts/windows_readme.txt" > "$stage/README.txt"
# The suite's licence, and the labels' font's: every program embeds DejaVu
# Sans Condensed, whose licence asks for its notice in every copy.
sed 's/$/\r/' "$root/LICENSE" > "$stage/LICENSE.txt"
sed 's/$/\r/' /usr/share/doc/fonts-dejavu-extra/copyright > "$stage/FONT-LICENCE.txt"
mkdir -p "$root/dist"
rm -f "$root/dist/texture-demos-windows-x64.zip"
(cd "$bw/package" && zip -qr -X "$root/dist/texture-demos-windows-x64.zip" texture-demos)
echo "windows: dist/texture-demos-windows-x64.zip ($(du -k "$root/dist/texture-demos-windows-x64.zip" | cut -f1) KiB," \
     "$(ls "$stage"/*.exe | wc -l) programs); dependencies $((t_deps - t_start)) s, build $((t_build - t_deps)) s"

if [ "$mode" = test ]; then
  bash "$root/tests/windows/wine_test.sh" "$bw/bin"
fi
echo "windows: done in $(( $(date +%s) - t_start )) s"
