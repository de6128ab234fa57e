#include "graspecmf/core/output_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

#include "graspecmf/core/error.hpp"

namespace graspecmf {
namespace fs = std::filesystem;
namespace {

// The process id written in a held lock file, or "?" if it cannot be read.
std::string holder(int fd) {
  char text[32] = {};
  const ssize_t n = ::pread(fd, text, sizeof text - 1, 0);
  return n > 0 ? std::string(text, static_cast<std::size_t>(n)) : std::string("?");
}

}  // namespace

OutputLock OutputLock::folder(const fs::path& folder) {
  return OutputLock(folder / ".graspecmf.lock", folder);
}

OutputLock OutputLock::file(const fs::path& target) {
  const fs::path parent = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  if (!fs::is_directory(parent)) {
    throw Error(target.string() + ": its folder " + parent.string() + " does not exist");
  }
  return OutputLock(parent / ("." + target.filename().string() + ".lock"), target);
}

OutputLock::OutputLock(const fs::path& lock_file, const fs::path& output) : lock_file_(lock_file) {
  // A holder removes the file before releasing it, so a lock taken on a file that is no longer at
  // the path is stale: try again on the new file.
  for (;;) {
    const int fd = ::open(lock_file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0) {
      throw Error(output.string() + ": cannot create the lock file " + lock_file.string() + " (" +
                  std::strerror(errno) + ")");
    }
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
      const int reason = errno;
      const std::string pid = holder(fd);
      ::close(fd);
      if (reason == EWOULDBLOCK) {
        throw Error(output.string() + " is in use by another graspecmf process (pid " + pid +
                    "); wait for it to finish or stop it");
      }
      throw Error(output.string() + ": cannot lock " + lock_file.string() + " (" +
                  std::strerror(reason) + ")");
    }
    struct stat held {};
    struct stat named {};
    if (::fstat(fd, &held) == 0 && ::stat(lock_file.c_str(), &named) == 0 &&
        held.st_ino == named.st_ino && held.st_dev == named.st_dev) {
      const std::string pid = std::to_string(::getpid());
      const bool noted = ::ftruncate(fd, 0) == 0 && ::pwrite(fd, pid.data(), pid.size(), 0) ==
                                                        static_cast<ssize_t>(pid.size());
      static_cast<void>(noted);  // the pid only names the holder in another process's message
      fd_ = fd;
      return;
    }
    ::close(fd);
  }
}

OutputLock::OutputLock(OutputLock&& other) noexcept
    : lock_file_(std::move(other.lock_file_)), fd_(other.fd_) {
  other.fd_ = -1;
}

OutputLock::~OutputLock() {
  if (fd_ < 0) return;
  ::unlink(lock_file_.c_str());
  ::close(fd_);
}

}  // namespace graspecmf
