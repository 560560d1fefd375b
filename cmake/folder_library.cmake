# sluice_folder_library(FOLDER [SOURCES ...] [DEPENDS lower folders ...] [LIBRARIES ...]):
# the library target sluice_FOLDER for src/sluice/FOLDER. Dependencies run one way: a folder
# may include its own headers and those of the folders it depends on, directly or through
# them; configuring fails on any other `#include "sluice/..."`, naming the file and line, so
# an include that runs upward never builds.
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

  file(GLOB_RECURSE files CONFIGURE_DEPENDS "${PROJECT_SOURCE_DIR}/src/sluice/${folder}/*.hpp"
       "${PROJECT_SOURCE_DIR}/src/sluice/${folder}/*.cpp")
  foreach(file IN LISTS files)
    file(STRINGS "${file}" includes REGEX "^#include \"sluice/")
    foreach(line IN LISTS includes)
      string(REGEX REPLACE "^#include \"sluice/([a-z_]+)/.*" "\\1" included "${line}")
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

  set(target sluice_${folder})
  list(TRANSFORM arg_DEPENDS PREPEND sluice_ OUTPUT_VARIABLE dependency_targets)
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
