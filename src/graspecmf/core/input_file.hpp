#pragma once
// Reading input files: a path's extension in lower case, and a whole file under a size cap that
// bounds the memory a parser can take for it (a text mesh takes a few times its size).

#include <cstdint>
#include <filesystem>
#include <string>

namespace graspecmf {

// Input files (meshes, point clouds) larger than this are refused before they are read.
inline constexpr std::uintmax_t kMaxInputFileBytes = std::uintmax_t{1} << 30;  // 1 GiB

// The path's extension in lower case with its dot (".obj"); empty if it has none.
std::string lower_extension(const std::filesystem::path& path);

// The file's size in bytes; throws Error "<path>: <why>" if the file is missing, not a regular
// file, or larger than max_bytes.
std::uintmax_t check_input_file(const std::filesystem::path& path,
                                std::uintmax_t max_bytes = kMaxInputFileBytes);

// The whole file after check_input_file; throws Error "<path>: <why>" if it cannot be read.
std::string read_input_file(const std::filesystem::path& path,
                            std::uintmax_t max_bytes = kMaxInputFileBytes);

}  // namespace graspecmf
