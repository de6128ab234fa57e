#pragma once
// The model that ships with graspecmf (models/mugs/ in the source tree,
// share/graspecmf/models/mugs/ when installed), used when a command is given no --model.

#include <filesystem>
#include <string>
#include <vector>

namespace graspecmf::apps {

// The bundled model's name (its folder under models/).
inline constexpr const char* kBundledModel = "mugs";

// The folders searched for the bundled model, in order: $GRASPECMF_MODELS/mugs when that variable
// is set, then beside the running binary (../share/graspecmf/models/mugs for an installed binary),
// then the source tree this binary was built from (models/mugs).
std::vector<std::filesystem::path> bundled_model_candidates();
// The first candidate folder that holds config.json and model.pt. Throws Error naming every folder
// searched when none does.
std::filesystem::path bundled_model_dir();
// `model` when it is not empty, else bundled_model_dir().
std::filesystem::path model_or_bundled(const std::string& model);

}  // namespace graspecmf::apps
