# What goes onto the controller: planterd, planter-can, the systemd unit, the board files and
# their calibrations under /etc/planter/boards (this build's board and calibration as
# /etc/planter/board.toml and calibration.toml), the machine files under
# /etc/planter/machines, and a default config that holds the drives until commissioning has
# passed. `cpack` makes one .deb per target.
include(GNUInstallDirs)
install(TARGETS planterd planter-can RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# Their man pages (cmake/man_pages.cmake), where help2man could make them.
foreach(program planterd planter-can)
  if(TARGET ${program}-man)
    install(FILES ${CMAKE_BINARY_DIR}/apps/${program}/${program}.1.gz
            DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
  endif()
endforeach()
install(FILES ${PROJECT_SOURCE_DIR}/apps/planterd/planterd.service DESTINATION /lib/systemd/system)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/boards/ DESTINATION /etc/planter/boards
        FILES_MATCHING PATTERN "board.toml" PATTERN "calibration.toml")
install(DIRECTORY ${PROJECT_SOURCE_DIR}/machines/ DESTINATION /etc/planter/machines
        FILES_MATCHING PATTERN "*.toml")
set(planter_default_board ${PLANTER_BOARD})
if(NOT planter_default_board)
  set(planter_default_board host-sim)
endif()
install(FILES ${PROJECT_SOURCE_DIR}/boards/${planter_default_board}/board.toml
        ${PROJECT_SOURCE_DIR}/boards/${planter_default_board}/calibration.toml
        DESTINATION /etc/planter)
install(FILES ${PROJECT_SOURCE_DIR}/packaging/default-planterd DESTINATION /etc/default
        RENAME planterd)
install(FILES ${PROJECT_SOURCE_DIR}/README.md ${PROJECT_SOURCE_DIR}/packaging/copyright
        DESTINATION ${CMAKE_INSTALL_DOCDIR})


set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME planter)
set(CPACK_PACKAGE_VERSION ${planter_version})
set(CPACK_PACKAGE_CONTACT "planter maintainers <planter@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "scallion transplanter controller (planterd) and CAN commissioning tool (planter-can)")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION misc)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "can-utils")
# A board's console links the cpp-httplib of a private sysroot (console/CMakeLists.txt), which
# dpkg-shlibdeps cannot trace to an installed package: scripts/cross-test.sh names its package.
set(PLANTER_CONSOLE_DEPENDS "" CACHE STRING "cross builds: the Depends of the sysroot's cpp-httplib")
if(PLANTER_CONSOLE_DEPENDS AND PLANTER_CONSOLE_SYSROOT_LIBS AND TARGET planter_console)
  set(CPACK_DEBIAN_PACKAGE_DEPENDS "${PLANTER_CONSOLE_DEPENDS}")
  set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS_PRIVATE_DIRS ${PLANTER_CONSOLE_SYSROOT_LIBS})
endif()
if(PLANTER_DEB_ARCH)  # set by a cross toolchain file
  set(CPACK_DEBIAN_PACKAGE_ARCHITECTURE ${PLANTER_DEB_ARCH})
else()
  execute_process(COMMAND dpkg --print-architecture OUTPUT_VARIABLE CPACK_DEBIAN_PACKAGE_ARCHITECTURE
                  OUTPUT_STRIP_TRAILING_WHITESPACE)
endif()
# Files under /etc are the admin's: dpkg keeps their edits on upgrade.
file(GLOB planter_board_dirs RELATIVE ${PROJECT_SOURCE_DIR}/boards ${PROJECT_SOURCE_DIR}/boards/*)
set(planter_conffiles
    "/etc/planter/board.toml\n/etc/planter/calibration.toml\n/etc/default/planterd\n")
foreach(b ${planter_board_dirs})
  foreach(f board.toml calibration.toml)
    if(EXISTS ${PROJECT_SOURCE_DIR}/boards/${b}/${f})
      string(APPEND planter_conffiles "/etc/planter/boards/${b}/${f}\n")
    endif()
  endforeach()
endforeach()
file(GLOB planter_machines RELATIVE ${PROJECT_SOURCE_DIR}/machines ${PROJECT_SOURCE_DIR}/machines/*.toml)
foreach(m ${planter_machines})
  string(APPEND planter_conffiles "/etc/planter/machines/${m}\n")
endforeach()
file(WRITE ${CMAKE_BINARY_DIR}/debian/conffiles "${planter_conffiles}")
set(CPACK_DEBIAN_PACKAGE_CONTROL_EXTRA
    ${CMAKE_BINARY_DIR}/debian/conffiles ${PROJECT_SOURCE_DIR}/packaging/debian/postinst
    ${PROJECT_SOURCE_DIR}/packaging/debian/prerm ${PROJECT_SOURCE_DIR}/packaging/debian/postrm)
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)
include(CPack)
