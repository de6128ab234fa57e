#pragma once
// Shared by the fuzz targets: graspecmf's readers take a path, so each input is written to one
// temporary file per process (named by pid, with the extension that selects the parser) and the
// reader is called on it. graspecmf::Error is the expected outcome for bad input and is swallowed;
// any other exception escapes and libFuzzer reports it as a crash (a finding).

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <system_error>

#include "graspecmf/core/error.hpp"

namespace graspecmf::fuzz {

// $TMPDIR if set, else /dev/shm (memory) if present, else /tmp.
inline std::filesystem::path scratch_directory() {
  const char* tmpdir = std::getenv("TMPDIR");
  if (tmpdir != nullptr && *tmpdir != '\0') return tmpdir;
  std::error_code ec;
  if (std::filesystem::is_directory("/dev/shm", ec)) return "/dev/shm";
  return "/tmp";
}

class InputFile {
 public:
  explicit InputFile(const std::string& extension)
      : path_(scratch_directory() / ("graspecmf-fuzz-" + std::to_string(::getpid()) + extension)) {}
  ~InputFile() {
    std::error_code ec;
    std::filesystem::remove(path_, ec);
  }
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;

  // Replaces the file's contents with the input; aborts if it cannot (not a parser finding).
  const std::filesystem::path& write(const std::uint8_t* data, std::size_t size) const {
    std::FILE* file = std::fopen(path_.c_str(), "wb");
    const bool ok = file != nullptr && (size == 0 || std::fwrite(data, 1, size, file) == size);
    if (file == nullptr || std::fclose(file) != 0 || !ok) {
      std::perror(path_.c_str());
      std::abort();
    }
    return path_;
  }

 private:
  std::filesystem::path path_;
};

// Writes the input to this process's file with the given extension and calls read(path).
template <typename Read>
int read_input_as_file(const std::uint8_t* data, std::size_t size, const char* extension,
                       Read read) {
  static const InputFile file(extension);
  const std::filesystem::path& path = file.write(data, size);
  try {
    read(path);
  } catch (const graspecmf::Error&) {
    // The reader refused the input with its one-line error: the expected outcome.
  }
  return 0;
}

}  // namespace graspecmf::fuzz
