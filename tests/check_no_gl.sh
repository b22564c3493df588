#!/usr/bin/env bash
# tests/check_no_gl.sh PROGRAM — fails (and so fails the build, as a
# POST_BUILD step of ts_add_core_test) if PROGRAM needs a window-system or GL
# library: the GL-free core and the CPU reference must stay GL-free.
set -u
needed=$(readelf -d "${1:?usage: check_no_gl.sh PROGRAM}" 2>/dev/null | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p')
[ -n "$needed" ] || { echo "check_no_gl: cannot read the dynamic section of $1" >&2; exit 1; }
bad=$(echo "$needed" | grep -E '^lib(glfw|X11|xcb|GL|GLX|EGL|OSMesa|gbm|drm)' || true)
if [ -n "$bad" ]; then
  echo "check_no_gl: $(basename "$1") links $(echo $bad | tr '\n' ' '): a GL-free program must link tscore only" >&2
  exit 1
fi
