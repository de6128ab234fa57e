#include "graspecmf/core/json_file.hpp"

#include <nlohmann/json.hpp>
#include <string>

#include "graspecmf/core/error.hpp"
#include "graspecmf/core/input_file.hpp"

namespace graspecmf {

nlohmann::json read_json_file(const std::filesystem::path& path) {
  const std::string text = read_input_file(path, kMaxJsonFileBytes);
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    throw Error(path.string() + ": not valid JSON (" + e.what() + ")");
  }
}

}  // namespace graspecmf
