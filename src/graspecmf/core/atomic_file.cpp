#include "graspecmf/core/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <string>
#include <vector>

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

// Opens path with O_CREAT | mode (O_TRUNC or O_APPEND) and writes bytes, checking every call.
void put_bytes(const fs::path& path, int mode, std::string_view bytes, const fs::path& shown_as) {
  const auto fail = [&](int error) {
    throw Error("cannot write " + shown_as.string() + ": " + std::strerror(error));
  };
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_CLOEXEC | mode, 0644);
  if (fd < 0) fail(errno);
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int error = n < 0 ? errno : ENOSPC;
      ::close(fd);
      fail(error);
    }
    done += static_cast<std::size_t>(n);
  }
  if (::close(fd) != 0) fail(errno);
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

void write_file_atomically(const fs::path& target, std::string_view bytes) {
  write_atomically(target, [&](const fs::path& tmp) { put_bytes(tmp, O_TRUNC, bytes, target); });
}

void append_file_text(const fs::path& path, std::string_view text) {
  put_bytes(path, O_APPEND, text, path);
}

std::size_t remove_temporary_files(const fs::path& folder) {
  std::error_code ec;
  std::vector<fs::path> stale;
  for (auto it = fs::recursive_directory_iterator(folder, ec);
       !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.size() > 1 && name[0] == '.' && name.find(".tmp-") != std::string::npos &&
        it->is_regular_file(ec)) {
      stale.push_back(it->path());
    }
  }
  for (const fs::path& path : stale) {
    if (!fs::remove(path, ec) && ec) {
      throw Error("cannot remove the stale temporary file " + path.string() + ": " + ec.message());
    }
  }
  return stale.size();
}

}  // namespace graspecmf
