#pragma once
// The model that ships with graspecmf (models/mugs/ in the source tree,
// share/graspecmf/models/mugs/ when installed), used when the command line or the Python module
// is given no model.

#include <filesystem>
#include <string>
#include <vector>

namespace graspecmf::models {

// The bundled model's name (its folder under models/).
inline constexpr const char* kBundledModel = "mugs";

// The folders searched for the bundled model, in order: $GRASPECMF_MODELS/mugs when that variable
// is set; share/graspecmf/models/mugs under each of the four nearest ancestors of the file that
// holds this code (the graspecmf binary in bin/, or the Python module in lib/python3/…); the
// source tree this code was built from (models/mugs).
std::vector<std::filesystem::path> bundled_model_candidates();
// The first candidate folder that holds config.json and model.pt. Throws Error naming every folder
// searched when none does.
std::filesystem::path bundled_model_dir();
// `model` when it is not empty, else bundled_model_dir().
std::filesystem::path model_or_bundled(const std::string& model);

}  // namespace graspecmf::models
