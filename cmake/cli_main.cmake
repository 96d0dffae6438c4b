# The programs' mains, where the command line is declared with CLI11 (a header-only library):
# its inline code is most of their compile time. Under the sanitizers at -O1, UBSan's checks
# on every instantiation made a main take 26-30 s to compile against 7 s at -O0 (five mains, a
# minute and a half of the sanitizer build on two cores). What a main runs is argv parsing and
# calls into the libraries, which keep -O1; so the mains alone are built at -O0 there.
find_package(CLI11 REQUIRED)
function(planter_cli_main target source)
  target_link_libraries(${target} PRIVATE CLI11::CLI11)
  if(PLANTER_SANITIZE)
    set_source_files_properties(${source} PROPERTIES COMPILE_OPTIONS -O0)
  endif()
endfunction()
