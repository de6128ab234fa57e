#include "graspecmf/models/bundled_model.hpp"

#include <dlfcn.h>

#include <cstdlib>
#include <system_error>

#include "graspecmf/core/error.hpp"

namespace graspecmf::models {
namespace fs = std::filesystem;

std::vector<fs::path> bundled_model_candidates() {
  std::vector<fs::path> folders;
  if (const char* root = std::getenv("GRASPECMF_MODELS"); root != nullptr && *root != '\0') {
    folders.push_back(fs::path(root) / kBundledModel);
  }
  // The executable or shared object this function was linked into.
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&bundled_model_candidates), &info) != 0 &&
      info.dli_fname != nullptr) {
    std::error_code ec;
    fs::path folder = fs::weakly_canonical(fs::absolute(info.dli_fname, ec), ec).parent_path();
    for (int up = 0; up < 4 && folder.has_relative_path(); ++up) {
      folder = folder.parent_path();
      folders.push_back(folder / "share" / "graspecmf" / "models" / kBundledModel);
    }
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
              "); give a model folder, or set GRASPECMF_MODELS to the folder that holds " +
              kBundledModel + "/");
}

fs::path model_or_bundled(const std::string& model) {
  return model.empty() ? bundled_model_dir() : fs::path(model);
}

}  // namespace graspecmf::models
