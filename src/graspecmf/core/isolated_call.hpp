#pragma once
// Running a call in a forked child process, so that a crash, an abort or a hang inside a
// third-party library (libhdf5 on a damaged file) cannot take the caller down with it.

#include <chrono>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace graspecmf {

struct IsolatedOutcome {
  bool completed = false;    // every call returned or threw graspecmf::Error
  std::size_t finished = 0;  // calls that returned or threw Error before the child ended
  std::string failure;       // otherwise: "crashed (signal 11)", "exited with status 1", ...
  // One entry per finished call: the message of the Error it threw, or empty if it returned.
  std::vector<std::string> refusals;
};

// Calls step(0), …, step(count - 1) in one forked child with standard output and error sent to
// /dev/null, allowing each call at most step_timeout (then the child is killed). The child's
// effects stay in the child: only how many calls finished, and the messages of those that threw
// Error, come back, so when the child ends during call k, finished is k. POSIX only; the caller
// must not hold locks the calls need in other threads. Throws Error if the child cannot be started.
IsolatedOutcome run_isolated_steps(std::size_t count, const std::function<void(std::size_t)>& step,
                                   std::chrono::milliseconds step_timeout);

// run_isolated_steps for the one call `call`.
IsolatedOutcome run_isolated(const std::function<void()>& call, std::chrono::milliseconds timeout);

}  // namespace graspecmf
