// Fuzzes data::read_acronym_file on ACRONYM grasp files (HDF5 through libhdf5's C++ API).
#include "fuzz_input_file.hpp"
#include "graspecmf/data/acronym_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return graspecmf::fuzz::read_input_as_file(
      data, size, ".h5", [](const auto& path) { graspecmf::data::read_acronym_file(path); });
}
