#include "graspecmf/eval/partial_report.hpp"

#include <nlohmann/json.hpp>

#include "graspecmf/core/atomic_file.hpp"
#include "graspecmf/core/error.hpp"
#include "graspecmf/core/input_file.hpp"

namespace graspecmf::eval {
using nlohmann::json;

void write_partial_report(const std::filesystem::path& path, const json& identity,
                          const std::vector<ObjectResult>& done) {
  json objects = json::array();
  for (const ObjectResult& o : done) objects.push_back(to_json(o));
  write_file_atomically(path, json{{"identity", identity}, {"objects", objects}}.dump() + "\n");
}

std::vector<ObjectResult> read_partial_report(const std::filesystem::path& path,
                                              const json& identity, std::string& note) {
  note.clear();
  if (!std::filesystem::exists(path)) return {};
  const json saved = json::parse(read_input_file(path), nullptr, /*allow_exceptions=*/false);
  const std::string name = path.string();
  if (!saved.is_object() || !saved.contains("objects") || !saved["objects"].is_array()) {
    note = name + " is not a partial evaluation report; starting afresh";
    return {};
  }
  if (saved.value("identity", json()) != identity) {
    note = name + " is from an evaluation with other settings; starting afresh";
    return {};
  }
  std::vector<ObjectResult> done;
  try {
    for (const json& entry : saved["objects"]) done.push_back(object_result_from_json(entry));
  } catch (const Error& e) {
    note = name + ": " + e.what() + "; starting afresh";
    return {};
  }
  return done;
}

}  // namespace graspecmf::eval
