// Fuzzes check_zip_archive, the integrity check every checkpoint and weights file passes before
// LibTorch's reader sees it (ZIP directory parsing, ZIP64 records, zlib inflate, CRC-32).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "graspecmf/core/error.hpp"
#include "graspecmf/core/zip_archive.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    graspecmf::check_zip_archive({reinterpret_cast<const char*>(data), size}, "input");
  } catch (const graspecmf::Error&) {
    // A clear refusal is the expected outcome for damaged input.
  }
  return 0;
}
