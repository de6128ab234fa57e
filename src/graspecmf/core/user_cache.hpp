#pragma once
// Where graspecmf keeps its per-user caches.

#include <cstdlib>
#include <filesystem>
#include <string>

namespace graspecmf {

// $XDG_CACHE_HOME/graspecmf/<name>, else $HOME/.cache/graspecmf/<name>, else
// <temporary folder>/graspecmf/<name>. The folder is not created.
inline std::filesystem::path user_cache_dir(const std::string& name) {
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg != nullptr && *xdg != '\0') {
    return std::filesystem::path(xdg) / "graspecmf" / name;
  }
  if (const char* home = std::getenv("HOME"); home != nullptr && *home != '\0') {
    return std::filesystem::path(home) / ".cache" / "graspecmf" / name;
  }
  return std::filesystem::temp_directory_path() / "graspecmf" / name;
}

}  // namespace graspecmf
