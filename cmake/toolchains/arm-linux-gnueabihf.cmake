# Cross toolchain for 32-bit Arm boards with hard float (BeagleBone class), Debian's way:
# crossbuild-essential-armhf and multiarch :armhf libraries. Tests run under qemu-user.
set(PLANTER_TRIPLE arm-linux-gnueabihf)
set(CMAKE_SYSTEM_PROCESSOR arm)
set(PLANTER_QEMU qemu-arm)
set(PLANTER_DEB_ARCH armhf)
include(${CMAKE_CURRENT_LIST_DIR}/debian-multiarch.cmake)
