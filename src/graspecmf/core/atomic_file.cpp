#include "graspecmf/core/atomic_file.hpp"

#include <unistd.h>

#include <atomic>
#include <fstream>
#include <string>

#include "graspecmf/core/error.hpp"

namespace graspecmf {
namespace fs = std::filesystem;

namespace {

fs::path temporary_path_for(const fs::path& target) {
  static std::atomic<unsigned> counter{0};
  const std::string name = "." + target.filename().string() + ".tmp-" + std::to_string(::getpid()) +
                           "-" + std::to_string(counter++);
  return target.parent_path() / name;
}

}  // namespace

void write_atomically(const fs::path& target, const std::function<void(const fs::path&)>& write) {
  const fs::path folder = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) {
    throw Error("cannot write " + target.string() + ": folder " + folder.string() +
                " does not exist");
  }
  if (::access(folder.c_str(), W_OK) != 0) {
    throw Error("cannot write " + target.string() + ": folder " + folder.string() +
                " is not writable");
  }
  const fs::path tmp = temporary_path_for(target);
  try {
    write(tmp);
    fs::rename(tmp, target);
  } catch (const fs::filesystem_error& e) {
    fs::remove(tmp, ec);
    throw Error("cannot write " + target.string() + ": " + e.code().message());
  } catch (...) {
    fs::remove(tmp, ec);
    throw;
  }
}

void write_text_atomically(const fs::path& target, std::string_view text) {
  write_atomically(target, [&](const fs::path& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
    out.flush();
    if (!out) throw Error("cannot write " + target.string() + ": write failed");
  });
}

}  // namespace graspecmf
