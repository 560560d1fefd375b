// libFuzzer harness for the mesh reader: the input is read as an STL file, then as an OBJ file
// (Assimp picks the reader by the extension), so that the shipped meshes serve as seeds as they
// are. Bad files must end in InputError.
#include <cstddef>
#include <cstdint>

#include "fuzz_input_file.hpp"
#include "sluice/core/errors.hpp"
#include "sluice/geometry/mesh_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  for (const char* name : {"mesh.stl", "mesh.obj"}) {
    const std::string path = sluice::fuzz::write_input(data, size, name);
    try {
      sluice::read_mesh(path, 1.0, "fuzz.yaml", 1, "bodies[0].mesh");
    } catch (const sluice::InputError&) {
    }
  }
  return 0;
}
