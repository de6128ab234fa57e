#pragma once
// Advisory locks (flock) that keep two processes from writing one output of a long job at once.
// A lock is a file that exists only while it is held; a process killed with it held releases it.

#include <filesystem>

namespace graspecmf {

class OutputLock {
 public:
  // Locks the folder (which must exist) through FOLDER/.graspecmf.lock; throws Error
  // "<folder> is in use by another graspecmf process (pid P)" when another process holds it.
  static OutputLock folder(const std::filesystem::path& folder);
  // Locks the output file target through .NAME.lock beside it; throws Error as folder() does, or
  // if target's folder does not exist.
  static OutputLock file(const std::filesystem::path& target);

  OutputLock(OutputLock&& other) noexcept;
  OutputLock& operator=(OutputLock&&) = delete;
  OutputLock(const OutputLock&) = delete;
  OutputLock& operator=(const OutputLock&) = delete;
  // Removes the lock file and releases the lock.
  ~OutputLock();

 private:
  OutputLock(const std::filesystem::path& lock_file, const std::filesystem::path& output);
  std::filesystem::path lock_file_;
  int fd_ = -1;
};

}  // namespace graspecmf
