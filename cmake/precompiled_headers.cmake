# sluice_precompile_headers(TARGET [HEADER ...]): parses the third-party and standard headers
# that most of sluice's sources include once per target instead of once per source file.
# Eigen, fmt and GoogleTest took about 3.5 s of a test source's 5 s front end (docs/testing.md).
# Off in the fuzz preset, so that one build still checks that every source includes what it
# uses.
option(SLUICE_PRECOMPILE_HEADERS "Precompile the headers most sources include" ON)
function(sluice_precompile_headers target)
  if(NOT SLUICE_PRECOMPILE_HEADERS)
    return()
  endif()
  target_precompile_headers(
    ${target} PRIVATE <Eigen/Core> <Eigen/Geometry> <fmt/format.h> <algorithm> <array> <cmath>
    <cstdint> <functional> <limits> <map> <memory> <optional> <stdexcept> <string> <utility>
    <vector> ${ARGN})
endfunction()
