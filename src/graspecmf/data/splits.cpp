#include "graspecmf/data/splits.hpp"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <set>

#include "graspecmf/core/atomic_file.hpp"
#include "graspecmf/core/error.hpp"
#include "graspecmf/core/json_file.hpp"
#include "graspecmf/core/random.hpp"

namespace graspecmf::data {
namespace fs = std::filesystem;

namespace {

using PartMember = std::vector<std::string> DatasetSplit::*;
constexpr std::pair<const char*, PartMember> kParts[] = {
    {"train", &DatasetSplit::train}, {"val", &DatasetSplit::val}, {"test", &DatasetSplit::test}};

}  // namespace

const std::vector<std::string>& DatasetSplit::part(const std::string& name) const {
  for (const auto& [part_name, member] : kParts) {
    if (name == part_name) return this->*member;
  }
  throw Error("unknown split '" + name + "' (expected train, val or test)");
}

DatasetSplit random_split(std::vector<std::string> names, const SplitFractions& fractions,
                          std::uint64_t seed) {
  const auto valid = [](double f) { return f >= 0.0 && f <= 1.0; };
  if (!valid(fractions.val) || !valid(fractions.test) || fractions.val + fractions.test > 1.0) {
    throw Error("split fractions must lie in [0, 1] and val + test must not exceed 1");
  }
  std::sort(names.begin(), names.end());
  Rng rng(seed);
  rng.shuffle(names);
  const double n = static_cast<double>(names.size());
  const auto num_val = static_cast<std::ptrdiff_t>(std::lround(fractions.val * n));
  const auto num_test = std::min(static_cast<std::ptrdiff_t>(std::lround(fractions.test * n)),
                                 static_cast<std::ptrdiff_t>(names.size()) - num_val);
  DatasetSplit split;
  split.val.assign(names.begin(), names.begin() + num_val);
  split.test.assign(names.begin() + num_val, names.begin() + num_val + num_test);
  split.train.assign(names.begin() + num_val + num_test, names.end());
  return split;
}

DatasetSplit read_split_file(const fs::path& path) {
  const nlohmann::json json = read_json_file(path);
  DatasetSplit split;
  std::set<std::string> seen;
  for (const auto& [part, member] : kParts) {
    if (!json.is_object() || !json.contains(part) || !json[part].is_array()) {
      throw Error(path.string() + ": split file needs a list \"" + std::string(part) + "\"");
    }
    std::vector<std::string>& names = split.*member;
    for (const auto& entry : json[part]) {
      if (!entry.is_string()) throw Error(path.string() + ": object names must be strings");
      const std::string name = entry.get<std::string>();
      if (!seen.insert(name).second) {
        throw Error(path.string() + ": object '" + name + "' is listed twice");
      }
      names.push_back(name);
    }
  }
  return split;
}

void write_split_file(const DatasetSplit& split, const fs::path& path) {
  nlohmann::json json;
  for (const auto& [part, member] : kParts) json[part] = split.*member;
  write_file_atomically(path, json.dump(2) + "\n");
}

}  // namespace graspecmf::data
