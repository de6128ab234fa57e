// Fuzzes geometry::read_point_cloud on .npy files (graspecmf's NumPy header and data reader).
#include "fuzz_input_file.hpp"
#include "graspecmf/geometry/point_cloud_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return graspecmf::fuzz::read_input_as_file(
      data, size, ".npy", [](const auto& path) { graspecmf::geometry::read_point_cloud(path); });
}
