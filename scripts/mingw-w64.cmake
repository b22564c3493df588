# scripts/mingw-w64.cmake — CMake toolchain for the Windows build, made on
# Debian with MinGW-w64 (scripts/windows.sh passes it; the README's Windows
# section says how).
#
# The -posix compilers: the win32-thread ones have no std::mutex/std::thread,
# which the measurement worker needs.  Every program is linked statically
# (libstdc++, libgcc, winpthread, GLFW, libpng, libjpeg, zlib), so a student's
# machine needs no DLL beside the .exe: OpenGL itself comes from the Windows
# driver (opengl32.dll), which GLFW opens at run time.
set(CMAKE_SYSTEM_NAME Windows)
set(CMAKE_SYSTEM_PROCESSOR x86_64)
set(CMAKE_C_COMPILER x86_64-w64-mingw32-gcc-posix)
set(CMAKE_CXX_COMPILER x86_64-w64-mingw32-g++-posix)
set(CMAKE_RC_COMPILER x86_64-w64-mingw32-windres)

# The cross-built dependencies: scripts/windows.sh puts their install
# prefixes in TS_WINDOWS_PREFIXES (read from the environment, so that
# try_compile's nested projects see them too).
string(REPLACE " " ";" ts_prefixes "$ENV{TS_WINDOWS_PREFIXES}")
set(CMAKE_FIND_ROOT_PATH /usr/x86_64-w64-mingw32 ${ts_prefixes})
set(CMAKE_PREFIX_PATH ${ts_prefixes})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
set(CMAKE_EXE_LINKER_FLAGS_INIT "-static -static-libgcc -static-libstdc++")
