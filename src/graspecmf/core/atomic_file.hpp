#pragma once
// Atomic file output: a writer fills a temporary file beside the target, which is renamed over the
// target only when the writer returns; on any failure the target is left exactly as it was.

#include <filesystem>
#include <functional>
#include <string_view>

namespace graspecmf {

// Calls write(tmp) with a fresh temporary path in target's folder, then renames tmp to target.
// If write throws, tmp is removed and the exception propagates. Throws Error if the folder is
// missing or not writable.
void write_atomically(const std::filesystem::path& target,
                      const std::function<void(const std::filesystem::path& tmp)>& write);

// Writes text to target atomically.
void write_text_atomically(const std::filesystem::path& target, std::string_view text);

}  // namespace graspecmf
