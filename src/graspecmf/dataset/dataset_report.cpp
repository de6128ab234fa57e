#include "graspecmf/dataset/dataset_report.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "graspecmf/core/error.hpp"
#include "graspecmf/dataset/make_dataset.hpp"

namespace graspecmf::dataset {

namespace fs = std::filesystem;

DatasetReport report_dataset(const fs::path& root, std::size_t min_successful) {
  data::DatasetOptions options;
  options.min_successful = 0;  // keep every readable object; the filter is counted below
  const data::AcronymDataset dataset = data::AcronymDataset::open(root, options);
  DatasetReport report;
  report.objects = dataset.objects();
  report.unreadable = dataset.skipped();
  report.min_successful = min_successful;
  for (const data::ObjectEntry& e : report.objects)
    report.usable += e.num_successful >= min_successful;
  const fs::path split_file = root / data::kSplitFileName;
  if (fs::exists(split_file)) report.split = data::read_split_file(split_file);
  const fs::path log = root / kTimingLogName;
  std::ifstream in(log);
  std::string line;
  for (std::size_t number = 1; std::getline(in, line); ++number) {
    try {
      const nlohmann::json entry = nlohmann::json::parse(line);
      if (entry.at("resumed").get<bool>()) continue;
      ++report.labelled_objects;
      report.labelling_seconds += entry.at("seconds").get<double>();
    } catch (const nlohmann::json::exception& e) {
      throw Error(log.string() + ":" + std::to_string(number) + ": not a make-dataset log line (" +
                  e.what() + ")");
    }
  }
  return report;
}

double quantile(std::vector<double> values, double q) {
  if (values.empty()) throw Error("quantile of no values");
  if (!(q >= 0.0 && q <= 1.0)) throw Error("quantile: q must lie in [0, 1]");
  std::sort(values.begin(), values.end());
  const double position = q * static_cast<double>(values.size() - 1);
  const auto below = static_cast<std::size_t>(std::floor(position));
  const std::size_t above = std::min(below + 1, values.size() - 1);
  const double t = position - static_cast<double>(below);
  return values[below] + t * (values[above] - values[below]);
}

}  // namespace graspecmf::dataset
