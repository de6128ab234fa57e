#pragma once
// Running the built graspecmf command in tests: exit code, stdout and stderr of one invocation.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <string>
#include <vector>

#include "test_support.hpp"

namespace graspecmf::testing {

struct CliRun {
  int exit_code;
  std::string out;  // stdout
  std::string err;  // stderr
};

// Runs `graspecmf ARGS` with its output captured in files under dir; prefix goes before the
// program (e.g. a resource limit).
inline CliRun run(const std::string& args, const ScratchDir& dir, const std::string& prefix = "") {
  const std::filesystem::path out = dir / "stdout.txt", err = dir / "stderr.txt";
  const std::string command =
      prefix + std::string(GRASPECMF_EXE) + " " + args + " >" + out.string() + " 2>" + err.string();
  const int status = std::system(command.c_str());
  CliRun result{WIFEXITED(status) ? WEXITSTATUS(status) : -1, read_file(out), read_file(err)};
  std::filesystem::remove(out);
  std::filesystem::remove(err);
  return result;
}

// Runs `graspecmf ARGS` as on a full disk: every write that would make a file (its captured
// stdout and stderr included) larger than max_bytes fails with EFBIG (RLIMIT_FSIZE, SIGXFSZ
// ignored).
inline CliRun run_on_full_disk(const std::string& args, const ScratchDir& dir, long max_bytes) {
  return run(args, dir, "trap '' XFSZ; exec prlimit --fsize=" + std::to_string(max_bytes) + " ");
}

// The temporary files that atomic writes leave behind, anywhere under folder.
inline std::vector<std::filesystem::path> temporary_files(const std::filesystem::path& folder) {
  std::vector<std::filesystem::path> found;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(folder)) {
    if (entry.path().filename().string().find(".tmp-") != std::string::npos) {
      found.push_back(entry.path());
    }
  }
  return found;
}

// A failed run prints exactly one line on stderr, starting with "error:".
inline void expect_one_error_line(const CliRun& r, const std::string& fragment) {
  EXPECT_NE(r.exit_code, 0);
  EXPECT_EQ(r.err.rfind("error: ", 0), 0u) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find(fragment), std::string::npos) << r.err;
}

// A failed long job: progress lines may come first, then exactly one error line, the last one.
inline void expect_error_after_progress(const CliRun& r, const std::string& fragment) {
  EXPECT_NE(r.exit_code, 0);
  std::size_t at = r.err.rfind("error: ", 0) == 0 ? 0 : r.err.find("\nerror: ");
  ASSERT_NE(at, std::string::npos) << r.err;
  if (at != 0) ++at;
  EXPECT_EQ(r.err.find('\n', at), r.err.size() - 1) << r.err;  // the first error line is the last
  EXPECT_NE(r.err.find(fragment, at), std::string::npos) << r.err;
}

}  // namespace graspecmf::testing
