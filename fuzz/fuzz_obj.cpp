// Fuzzes geometry::read_mesh on .obj files (tinyobjloader plus graspecmf's line checks).
#include "fuzz_input_file.hpp"
#include "graspecmf/geometry/mesh_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return graspecmf::fuzz::read_input_as_file(
      data, size, ".obj", [](const auto& path) { graspecmf::geometry::read_mesh(path); });
}
