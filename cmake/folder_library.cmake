# sluice_folder_library(FOLDER [SOURCES ...] [DEPENDS lower folders ...] [LIBRARIES ...]):
# the library target sluice_FOLDER for src/sluice/FOLDER (a folder below another, such as
# fluid/wcsph, is a library of its own: target sluice_fluid_wcsph). Dependencies run one way: a
# folder may include its own headers and those of the folders it depends on, directly or through
# them; configuring fails on any other `#include "sluice/..."` (in .hpp, .cpp, .cu and .cuh
# files, indented or not), naming the file and line, so an include that runs upward or sideways
# (one model's folder into another's) never builds.
function(sluice_folder_library folder)
  cmake_parse_arguments(arg "" "" "SOURCES;DEPENDS;LIBRARIES" ${ARGN})
  set(allowed ${folder})
  foreach(dependency IN LISTS arg_DEPENDS)
    get_property(below GLOBAL PROPERTY sluice_reaches_${dependency})
    if(NOT below)
      message(FATAL_ERROR "sluice: folder '${folder}' depends on '${dependency}', which is not "
                          "declared before it")
    endif()
    list(APPEND allowed ${below})
  endforeach()
  list(REMOVE_DUPLICATES allowed)
  set_property(GLOBAL PROPERTY sluice_reaches_${folder} ${allowed})

  set(here "${PROJECT_SOURCE_DIR}/src/sluice/${folder}")
  file(GLOB files CONFIGURE_DEPENDS "${here}/*.hpp" "${here}/*.cpp" "${here}/*.cu" "${here}/*.cuh")
  foreach(file IN LISTS files)
    file(STRINGS "${file}" includes REGEX "^[ \t]*#[ \t]*include[ \t]*\"sluice/")
    foreach(line IN LISTS includes)
      # The folder of the included header: "fluid/wcsph" for "sluice/fluid/wcsph/tait.hpp".
      string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*\"sluice/(([a-z_]+/)*)[a-z_0-9.]+\".*"
                           "\\1" included "${line}")
      string(REGEX REPLACE "/$" "" included "${included}")
      if(NOT included IN_LIST allowed)
        list(JOIN allowed ", " reach)
        file(STRINGS "${file}" all_lines)
        list(FIND all_lines "${line}" index)
        math(EXPR number "${index} + 1")
        file(RELATIVE_PATH shown "${PROJECT_SOURCE_DIR}" "${file}")
        message(FATAL_ERROR "sluice: ${shown}:${number}: '${folder}' may not include "
                            "'${included}' (it reaches: ${reach}); move the shared type down "
                            "or the code up (docs/architecture.md)")
      endif()
    endforeach()
  endforeach()

  string(REPLACE "/" "_" target "sluice_${folder}")
  list(TRANSFORM arg_DEPENDS REPLACE "/" "_" OUTPUT_VARIABLE dependency_targets)
  list(TRANSFORM dependency_targets PREPEND sluice_)
  if(arg_SOURCES)
    list(TRANSFORM arg_SOURCES PREPEND "${PROJECT_SOURCE_DIR}/src/sluice/${folder}/")
    add_library(${target} STATIC ${arg_SOURCES})
    target_include_directories(${target} PUBLIC "${PROJECT_SOURCE_DIR}/src")
    target_link_libraries(${target} PUBLIC ${dependency_targets} sluice_warnings ${arg_LIBRARIES})
    # A folder of a few sources gains less than its precompiled header costs.
    list(LENGTH arg_SOURCES source_count)
    if(source_count GREATER_EQUAL 4)
      sluice_precompile_headers(${target})
    endif()
  else()
    add_library(${target} INTERFACE)
    target_include_directories(${target} INTERFACE "${PROJECT_SOURCE_DIR}/src")
    target_link_libraries(${target} INTERFACE ${dependency_targets} sluice_warnings
                                              ${arg_LIBRARIES})
  endif()
endfunction()
