#pragma once
// The objects an interrupted evaluation has finished, kept beside its report so that the same
// evaluation, rerun, continues where it stopped. Torch-free.

#include <filesystem>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "graspecmf/eval/report.hpp"

namespace graspecmf::eval {

// Writes `done` atomically to path with the evaluation's identity (what must match for a resume).
void write_partial_report(const std::filesystem::path& path, const nlohmann::json& identity,
                          const std::vector<ObjectResult>& done);

// The objects of the partial report at path if it exists and has this identity; none otherwise,
// and then `note` says why it is not resumed (left empty when there is no file). Throws Error if
// the path is not a readable regular file.
std::vector<ObjectResult> read_partial_report(const std::filesystem::path& path,
                                              const nlohmann::json& identity, std::string& note);

}  // namespace graspecmf::eval
