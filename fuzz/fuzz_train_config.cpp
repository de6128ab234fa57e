// Fuzzes models::read_train_config on training config JSON (nlohmann parse, from_json, validate).
#include "fuzz_input_file.hpp"
#include "graspecmf/models/train_config.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return graspecmf::fuzz::read_input_as_file(
      data, size, ".json", [](const auto& path) { graspecmf::models::read_train_config(path); });
}
