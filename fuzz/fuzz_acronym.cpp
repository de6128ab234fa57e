// Fuzzes data::read_acronym_file on ACRONYM grasp files (HDF5 through libhdf5's C++ API). libhdf5
// runs first in a child process (core/isolated_call.hpp), whose crashes and hangs become Errors;
// its time limit here (10 s) stays under scripts/fuzz's per-input timeout (20 s).
#include <chrono>

#include "fuzz_input_file.hpp"
#include "graspecmf/data/acronym_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return graspecmf::fuzz::read_input_as_file(data, size, ".h5", [](const auto& path) {
    graspecmf::data::read_acronym_file(path, std::chrono::seconds(10));
  });
}
