#pragma once
// Train/validation/test splits of a dataset's objects: drawn deterministically from a seed, or read
// from / written to a JSON split file {"train": [...], "val": [...], "test": [...]} of object
// names.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace graspecmf::data {

// The split file's name in a dataset folder, beside grasps/.
inline constexpr const char* kSplitFileName = "splits.json";

struct DatasetSplit {
  std::vector<std::string> train, val, test;

  // The names of one part: "train", "val" or "test"; throws Error for another name.
  const std::vector<std::string>& part(const std::string& name) const;
};

struct SplitFractions {
  double val = 0.1;
  double test = 0.1;  // the rest is train
};

// Sorts the names, shuffles them with the seed and cuts val = round(f_val·n), test =
// round(f_test·n), train = the rest. Throws Error if a fraction is outside [0, 1] or they sum to
// more than 1.
DatasetSplit random_split(std::vector<std::string> names, const SplitFractions& fractions,
                          std::uint64_t seed);
// Reads a JSON split file; throws Error if it is missing, malformed or lists a name twice.
DatasetSplit read_split_file(const std::filesystem::path& path);
// Writes a JSON split file atomically.
void write_split_file(const DatasetSplit& split, const std::filesystem::path& path);

}  // namespace graspecmf::data
