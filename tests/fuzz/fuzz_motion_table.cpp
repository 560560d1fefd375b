// libFuzzer harness for the motion-table reader (a prescribed motion's CSV poses). Bad tables
// must end in InputError.
#include <cstddef>
#include <cstdint>
#include <memory>

#include "fuzz_input_file.hpp"
#include "sluice/core/errors.hpp"
#include "sluice/io/body_reader.hpp"
#include "sluice/io/yaml_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const auto source =
      std::make_shared<const sluice::io::YamlSource>(sluice::io::YamlSource{"fuzz.yaml", 3, {}});
  static const YAML::Node node = YAML::Load("{type: table, file: poses.csv}");
  const std::string path = sluice::fuzz::write_input(data, size, "poses.csv");
  const sluice::io::MapReader owner(source, node, "bodies[0].prescribed", 1);
  try {
    sluice::io::read_pose_table(path, owner, "file");
  } catch (const sluice::InputError&) {
  }
  return 0;
}
