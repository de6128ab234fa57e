// Fuzzes geometry::read_point_cloud on .ply files (read_ply_header, graspecmf's vertex reader).
#include "fuzz_input_file.hpp"
#include "graspecmf/geometry/point_cloud_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return graspecmf::fuzz::read_input_as_file(
      data, size, ".ply", [](const auto& path) { graspecmf::geometry::read_point_cloud(path); });
}
