// Which sluice this is, for `sluice --version`, run statistics and checkpoints. The definitions
// are generated at build time (cmake/write_build_info.cmake).
#pragma once

#include <string_view>

namespace sluice {

// The release, as CMakeLists.txt's project() names it ("0.1.0"): checkpoints of another
// release are refused.
std::string_view sluice_version();
// `git describe --always --dirty` of the source tree the build was made from ("07b69f2f1c3a",
// "07b69f2f1c3a-dirty" with uncommitted changes), or "unknown" outside a git checkout.
std::string_view source_revision();

}  // namespace sluice
