#pragma once
// Reading a JSON document (a config, a split file) from a file of bounded size.

#include <cstdint>
#include <filesystem>
#include <nlohmann/json_fwd.hpp>

namespace graspecmf {

// JSON files larger than this are refused before they are read (the parsed document takes about
// ten times the file's size).
inline constexpr std::uintmax_t kMaxJsonFileBytes = std::uintmax_t{64} << 20;  // 64 MiB

// The JSON document in the file; throws Error "<path>: <why>" if the file is missing, larger than
// kMaxJsonFileBytes or not valid JSON.
nlohmann::json read_json_file(const std::filesystem::path& path);

}  // namespace graspecmf
