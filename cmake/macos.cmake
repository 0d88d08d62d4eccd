# Cross toolchain for the macOS library, one architecture a build: zig's clang and linker from
# PyPI's ziglang (scripts/macos_slices.sh makes the wrappers and sets EL_ZIG_TARGET, e.g.
# aarch64-macos.11.0: Blender 4.2 supports macOS 11.2 and later). Nothing built here runs here.
set(CMAKE_SYSTEM_NAME Darwin)
set(CMAKE_SYSTEM_PROCESSOR ${EL_MACOS_ARCH})
set(CMAKE_C_COMPILER ${EL_ZIG_WRAPPERS}/zcc)
set(CMAKE_CXX_COMPILER ${EL_ZIG_WRAPPERS}/zcxx)
set(CMAKE_AR ${EL_ZIG_WRAPPERS}/zar)
set(CMAKE_RANLIB ${EL_ZIG_WRAPPERS}/zranlib)
set(CMAKE_OSX_SYSROOT "")
set(CMAKE_OSX_DEPLOYMENT_TARGET "")
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE BOTH)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE BOTH)
