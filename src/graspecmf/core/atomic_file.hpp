#pragma once
// Checked file output. Atomic writes: a writer fills a temporary file beside the target, which is
// renamed over the target only when the writer returns; on any failure the target is left exactly
// as it was and the temporary file is removed. Every write and close is checked.

#include <filesystem>
#include <functional>
#include <string_view>

namespace graspecmf {

// Calls write(tmp) with a fresh temporary path in target's folder, then renames tmp to target.
// If write throws, tmp is removed and the exception propagates. Throws Error if the folder is
// missing or not writable.
void write_atomically(const std::filesystem::path& target,
                      const std::function<void(const std::filesystem::path& tmp)>& write);

// Writes bytes (text or binary) to target atomically, every write and the close checked; throws
// Error "cannot write <target>: <system reason>" (e.g. "No space left on device").
void write_file_atomically(const std::filesystem::path& target, std::string_view bytes);

// Appends text to path (created if missing), every write and the close checked; throws Error
// "cannot write <path>: <system reason>". A failed append may leave part of text in the file.
void append_file_text(const std::filesystem::path& path, std::string_view text);

// Removes the temporary files that write_atomically leaves when its process is killed, in folder
// and below (for a resumed job); returns how many were removed.
std::size_t remove_temporary_files(const std::filesystem::path& folder);

}  // namespace graspecmf
