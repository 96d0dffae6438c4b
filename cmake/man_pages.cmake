# Man pages for the programs, made by help2man from their own --help and --version, so the page
# and the program cannot disagree. Without help2man (or on a cross build with no emulator to run
# the program) there are none, and the build says so once.
find_program(PLANTER_HELP2MAN help2man)
if(NOT PLANTER_HELP2MAN)
  message(STATUS "help2man not found: no man pages (scripts/setup.sh installs it)")
endif()
# planter_man_page(<program target> "<one line: what it is>")
function(planter_man_page target what)
  # Not from the sanitizer or fuzzing builds: no package is made of them, and a leak report at
  # exit would fail the page.
  if(NOT PLANTER_HELP2MAN OR PLANTER_SANITIZE OR PLANTER_FUZZ)
    return()
  endif()
  set(run $<TARGET_FILE:${target}>)
  if(CMAKE_CROSSCOMPILING)
    if(NOT CMAKE_CROSSCOMPILING_EMULATOR)
      return()
    endif()
    # help2man runs the program as one word: a wrapper gives it the emulator, and the console's
    # private sysroot libraries where the build links them (console/CMakeLists.txt).
    set(libs "")
    if(PLANTER_CONSOLE_SYSROOT)
      set(libs "${PLANTER_CONSOLE_SYSROOT}/usr/lib/${PLANTER_TRIPLE}:${PLANTER_CONSOLE_SYSROOT}/lib/${PLANTER_TRIPLE}")
    endif()
    set(wrapper ${CMAKE_CURRENT_BINARY_DIR}/${target}-under-emulator)
    file(GENERATE OUTPUT ${wrapper}
         CONTENT "#!/bin/sh\nLD_LIBRARY_PATH='${libs}' exec ${CMAKE_CROSSCOMPILING_EMULATOR} $<TARGET_FILE:${target}> \"$@\"\n"
         FILE_PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE GROUP_READ GROUP_EXECUTE
                          WORLD_READ WORLD_EXECUTE)
    set(run ${wrapper})
  endif()
  set(page ${CMAKE_CURRENT_BINARY_DIR}/${target}.1)
  set(include ${CMAKE_CURRENT_BINARY_DIR}/${target}.h2m)
  add_custom_command(
    OUTPUT ${page}.gz
    # Each subcommand's options, from its own --help (cmake/man_subcommands.sh).
    COMMAND sh ${PROJECT_SOURCE_DIR}/cmake/man_subcommands.sh ${run} ${include} ${target}
    # stdout only: a program that cannot start prints its error on stderr, and help2man then
    # fails the build instead of making a page of the error. The footer's version is the
    # release's alone: the build's git id ran into the date at 80 columns.
    COMMAND ${PLANTER_HELP2MAN} --no-info --section=1 --include=${include}
            "--version-string=${PROJECT_VERSION}" "--name=${what}" --output=${page} ${run}
    COMMAND gzip -n -9 -f ${page}
    DEPENDS ${target} ${run} ${PROJECT_SOURCE_DIR}/cmake/man_subcommands.sh
    COMMENT "man page for ${target} (help2man)"
    VERBATIM)
  add_custom_target(${target}-man ALL DEPENDS ${page}.gz)
endfunction()
