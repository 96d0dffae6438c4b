# Layers the build enforces. Each target sees, besides the libraries it links, only its own
# folders: planter_layer(<target> <folder>...) links those folders into a tree of the target's
# own under the build directory and exports that tree alone (PUBLIC for a library, PRIVATE for
# a program). A header of a layer the target does not link is then not found at all, so a
# wrong-way include (config including sim, firmware including config) fails the build.
# Includes keep their project-relative form ("sim/runner/scenario.h").
function(planter_layer target)
  set(tree ${PROJECT_BINARY_DIR}/layers/${target})
  foreach(folder IN LISTS ARGN)
    get_filename_component(parent ${tree}/${folder} DIRECTORY)
    file(MAKE_DIRECTORY ${parent})
    if(NOT EXISTS ${tree}/${folder})
      file(CREATE_LINK ${PROJECT_SOURCE_DIR}/${folder} ${tree}/${folder} SYMBOLIC)
    endif()
  endforeach()
  get_target_property(type ${target} TYPE)
  if(type STREQUAL "INTERFACE_LIBRARY")
    target_include_directories(${target} INTERFACE ${tree})
  elseif(type STREQUAL "EXECUTABLE")
    target_include_directories(${target} PRIVATE ${tree})
  else()
    target_include_directories(${target} PUBLIC ${tree})
  endif()
endfunction()
