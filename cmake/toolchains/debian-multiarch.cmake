# Shared part of the cross toolchain files: PLANTER_TRIPLE names the target; compilers,
# pkg-config and the emulator are looked up by name, libraries in the multiarch directory of
# that triple. No absolute path is written here.
set(CMAKE_SYSTEM_NAME Linux)
# A missing cross compiler is said with what installs it, not as CMake's bare "not found".
find_program(PLANTER_CROSS_CXX ${PLANTER_TRIPLE}-g++)
if(NOT PLANTER_CROSS_CXX)
  message(FATAL_ERROR "no ${PLANTER_TRIPLE}-g++ on PATH: the cross toolchain for this board is "
    "not installed. scripts/cross-test.sh installs it (Debian's crossbuild-essential-"
    "${PLANTER_DEB_ARCH} and the :${PLANTER_DEB_ARCH} libraries) and builds every board; "
    "docs/boards.md says more.")
endif()
set(CMAKE_C_COMPILER ${PLANTER_TRIPLE}-gcc)
set(CMAKE_CXX_COMPILER ${PLANTER_TRIPLE}-g++)
set(CMAKE_LIBRARY_ARCHITECTURE ${PLANTER_TRIPLE})
# pkg-config for the target (Debian's pkgconf provides <triple>-pkg-config).
set(PKG_CONFIG_EXECUTABLE ${PLANTER_TRIPLE}-pkg-config CACHE FILEPATH "pkg-config for the target")
# Multiarch: the target's libraries and CMake package files live in the triple's lib
# directory (CMAKE_LIBRARY_ARCHITECTURE), headers are shared; programs are the host's.
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
# Unit tests run under qemu-user; the target's dynamic loader and libraries come from the
# multiarch packages (libc6:<arch> and friends), which qemu finds at their usual places.
find_program(PLANTER_QEMU_PATH ${PLANTER_QEMU})
if(PLANTER_QEMU_PATH)
  set(CMAKE_CROSSCOMPILING_EMULATOR ${PLANTER_QEMU_PATH})
endif()
