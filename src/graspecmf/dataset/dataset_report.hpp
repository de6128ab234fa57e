#pragma once
// A dataset folder at a glance, for `graspecmf inspect DIR`: each object's success fraction and
// their distribution, how many objects the paper's ≥ 100-successes filter keeps, the split sizes,
// and the labelling time make-dataset logged.

#include <cstddef>
#include <filesystem>
#include <optional>
#include <vector>

#include "graspecmf/data/dataset.hpp"
#include "graspecmf/data/splits.hpp"

namespace graspecmf::dataset {

struct DatasetReport {
  std::vector<data::ObjectEntry> objects;       // every readable object, in name order
  std::vector<data::SkippedObject> unreadable;  // grasp files or meshes that could not be read
  std::size_t min_successful = 100;
  std::size_t usable = 0;                   // objects with ≥ min_successful successful grasps
  std::optional<data::DatasetSplit> split;  // splits.json, when present
  std::size_t labelled_objects = 0;         // log.jsonl lines of objects made (not resumed)
  double labelling_seconds = 0.0;           // their summed wall time
};

// Scans root/grasps/*.h5 keeping every readable object, and reads splits.json and log.jsonl when
// present. Throws Error if root/grasps is missing or empty, or a present splits.json or log.jsonl
// is malformed.
DatasetReport report_dataset(const std::filesystem::path& root, std::size_t min_successful = 100);

// The q-quantile of the values (0 ≤ q ≤ 1; linear interpolation between order statistics).
// Throws Error if values is empty or q is out of range.
double quantile(std::vector<double> values, double q);

}  // namespace graspecmf::dataset
