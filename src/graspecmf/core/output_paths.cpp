#include "graspecmf/core/output_paths.hpp"

#include "graspecmf/core/error.hpp"

namespace graspecmf {
namespace fs = std::filesystem;

namespace {

// The absolute, link-free form of path as far as it exists, with the rest appended lexically.
fs::path resolved(const fs::path& path) {
  std::error_code ec;
  const fs::path result = fs::weakly_canonical(fs::absolute(path, ec), ec);
  return ec ? fs::absolute(path).lexically_normal() : result;
}

}  // namespace

bool same_path(const fs::path& a, const fs::path& b) {
  if (a.empty() || b.empty()) return false;
  std::error_code ec;
  if (fs::exists(a, ec) && fs::exists(b, ec)) return fs::equivalent(a, b, ec);
  return resolved(a) == resolved(b);
}

bool inside_folder(const fs::path& path, const fs::path& folder) {
  if (path.empty() || folder.empty()) return false;
  const fs::path p = resolved(path), f = resolved(folder);
  auto pi = p.begin();
  for (auto fi = f.begin(); fi != f.end(); ++fi, ++pi) {
    if (fi->empty()) continue;  // a trailing separator
    if (pi == p.end() || *pi != *fi) return false;
  }
  return true;
}

void require_distinct_output(const std::string& option, const fs::path& out,
                             const std::vector<fs::path>& inputs,
                             const std::vector<fs::path>& input_folders) {
  const auto refuse = [&](const fs::path& input) {
    throw Error(option + " " + out.string() + " is also the input " + input.string() +
                "; choose another output");
  };
  for (const fs::path& input : inputs) {
    if (same_path(out, input)) refuse(input);
  }
  for (const fs::path& folder : input_folders) {
    if (inside_folder(out, folder)) refuse(folder);
  }
}

}  // namespace graspecmf
