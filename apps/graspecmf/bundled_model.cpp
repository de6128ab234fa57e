#include "bundled_model.hpp"

#include <cstdlib>
#include <system_error>

#include "graspecmf/core/error.hpp"

namespace graspecmf::apps {
namespace fs = std::filesystem;

std::vector<fs::path> bundled_model_candidates() {
  std::vector<fs::path> folders;
  if (const char* root = std::getenv("GRASPECMF_MODELS"); root != nullptr && *root != '\0') {
    folders.push_back(fs::path(root) / kBundledModel);
  }
  std::error_code ec;
  const fs::path binary = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    folders.push_back(binary.parent_path().parent_path() / "share" / "graspecmf" / "models" /
                      kBundledModel);
  }
  folders.push_back(fs::path(GRASPECMF_SOURCE_DIR) / "models" / kBundledModel);
  return folders;
}

fs::path bundled_model_dir() {
  const std::vector<fs::path> folders = bundled_model_candidates();
  std::string searched;
  for (const fs::path& folder : folders) {
    if (fs::exists(folder / "config.json") && fs::exists(folder / "model.pt")) return folder;
    searched += (searched.empty() ? "" : ", ") + folder.string();
  }
  throw Error("the bundled model is missing (looked in " + searched +
              "); give --model RUN, or set GRASPECMF_MODELS to the folder that holds " +
              kBundledModel + "/");
}

fs::path model_or_bundled(const std::string& model) {
  return model.empty() ? bundled_model_dir() : fs::path(model);
}

}  // namespace graspecmf::apps
