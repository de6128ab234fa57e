#pragma once
// Refusing an output that would overwrite an input, as cp refuses to copy a file onto itself.

#include <filesystem>
#include <string>
#include <vector>

namespace graspecmf {

// True if a and b name the same file or folder (through links, "..", relative paths), or would
// once a is created; false if either is empty.
bool same_path(const std::filesystem::path& a, const std::filesystem::path& b);

// True if path is folder itself or lies inside it (resolved as in same_path).
bool inside_folder(const std::filesystem::path& path, const std::filesystem::path& folder);

// Throws Error "<option> <out> is also the input <input>; choose another output" if out names
// any of inputs, or lies inside one of the folders in input_folders. Empty paths are ignored.
void require_distinct_output(const std::string& option, const std::filesystem::path& out,
                             const std::vector<std::filesystem::path>& inputs,
                             const std::vector<std::filesystem::path>& input_folders = {});

}  // namespace graspecmf
