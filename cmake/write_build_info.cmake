# Script mode (cmake -P), run at every build: writes OUTPUT, a source that says which sluice
# this is (VERSION and the source tree's revision), rewriting it only where its text changes so
# that an unchanged revision relinks nothing.
#   cmake -DSOURCE_DIR=... -DOUTPUT=... -DVERSION=... -P write_build_info.cmake
set(revision "unknown")
find_program(git_program git)
if(git_program AND EXISTS "${SOURCE_DIR}/.git")
  execute_process(COMMAND "${git_program}" describe --always --dirty --abbrev=12
                  WORKING_DIRECTORY "${SOURCE_DIR}" OUTPUT_VARIABLE described
                  RESULT_VARIABLE failed OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  if(NOT failed AND described)
    # Only characters that need no quoting in C++, JSON or a file name.
    string(REGEX REPLACE "[^A-Za-z0-9._+-]" "_" revision "${described}")
  endif()
endif()
set(text "// Written by cmake/write_build_info.cmake at build time; do not edit.
#include \"sluice/core/build_info.hpp\"

namespace sluice {
std::string_view sluice_version() { return \"${VERSION}\"; }
std::string_view source_revision() { return \"${revision}\"; }
}  // namespace sluice
")
set(old "")
if(EXISTS "${OUTPUT}")
  file(READ "${OUTPUT}" old)
endif()
if(NOT old STREQUAL text)
  file(WRITE "${OUTPUT}" "${text}")
endif()
