# Cross toolchain for 64-bit Arm boards (Raspberry Pi 4 class), Debian's way: the compilers
# from crossbuild-essential-arm64, the libraries from multiarch packages (libgpiod-dev:arm64,
# ...). Only the triple is named here; everything is found on PATH and in Debian's
# multiarch directories. Tests run under qemu-user.
set(PLANTER_TRIPLE aarch64-linux-gnu)
set(CMAKE_SYSTEM_PROCESSOR aarch64)
set(PLANTER_QEMU qemu-aarch64)
set(PLANTER_DEB_ARCH arm64)
include(${CMAKE_CURRENT_LIST_DIR}/debian-multiarch.cmake)
