#include "graspecmf/core/output_lock.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <string>

#include "test_support.hpp"

namespace {
namespace fs = std::filesystem;
using graspecmf::OutputLock;
using graspecmf::testing::expect_error;
using graspecmf::testing::ScratchDir;

// A second lock of one output fails with one clear message naming the holder's pid; a lock held by
// one open file is seen by another open of the same path, as by another process.
TEST(OutputLock, ASecondWriterIsRefusedUntilTheFirstLetsGo) {
  const ScratchDir dir;
  const std::string pid = std::to_string(::getpid());
  {
    OutputLock held = OutputLock::folder(dir.path());
    EXPECT_TRUE(fs::exists(dir / ".graspecmf.lock"));
    expect_error([&] { OutputLock::folder(dir.path()); },
                 dir.path().string() + " is in use by another graspecmf process (pid " + pid + ")");
    const OutputLock moved(std::move(held));  // the lock moves with the object
    expect_error([&] { OutputLock::folder(dir.path()); }, "in use");
  }
  EXPECT_FALSE(fs::exists(dir / ".graspecmf.lock"));
  const OutputLock again = OutputLock::folder(dir.path());
  {
    const OutputLock file = OutputLock::file(dir / "labels.h5");
    EXPECT_TRUE(fs::exists(dir / ".labels.h5.lock"));
    expect_error([&] { OutputLock::file(dir / "labels.h5"); }, "labels.h5 is in use");
    const OutputLock other = OutputLock::file(dir / "other.h5");  // another output is free
  }
  EXPECT_FALSE(fs::exists(dir / ".labels.h5.lock"));
  expect_error([&] { OutputLock::file(dir / "missing/labels.h5"); }, "does not exist");
}

// A process killed while holding a lock releases it: the next writer gets it at once.
TEST(OutputLock, AKilledHolderReleasesTheLock) {
  const ScratchDir dir;
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    const OutputLock held = OutputLock::folder(dir.path());
    ::_exit(::kill(::getpid(), SIGKILL));
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status));
  EXPECT_TRUE(fs::exists(dir / ".graspecmf.lock"));  // left behind, but not held
  const OutputLock next = OutputLock::folder(dir.path());
}

}  // namespace
