#pragma once
// Running a call in a forked child process, so that a crash, an abort or a hang inside a
// third-party library (libhdf5 on a damaged file) cannot take the caller down with it.

#include <chrono>
#include <functional>
#include <string>

namespace graspecmf {

struct IsolatedOutcome {
  bool completed = false;  // the call returned or threw graspecmf::Error
  std::string failure;     // otherwise: "crashed (signal 11)", "exited with status 1", ...
};

// Calls `call` in a forked child with standard output and error sent to /dev/null, and waits for
// it at most `timeout` (then kills it). The child's effects stay in the child: only whether the
// call completed comes back. POSIX only; the caller must not hold locks the call needs in other
// threads. Throws Error if the child cannot be started.
IsolatedOutcome run_isolated(const std::function<void()>& call, std::chrono::milliseconds timeout);

}  // namespace graspecmf
