#include "graspecmf/core/isolated_call.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstring>

#include "graspecmf/core/error.hpp"

// Present only in sanitizer builds (the fuzzers): the callback a sanitizer runs before it exits.
extern "C" void __sanitizer_set_death_callback(void (*callback)()) __attribute__((weak));

namespace graspecmf {
namespace {

// Exit statuses of the child: the call completed, or threw something other than Error.
constexpr int kCompleted = 0;
constexpr int kOtherException = 3;

[[noreturn]] void run_child(const std::function<void()>& call) {
  // The child dies plainly: the parent's crash handlers (a sanitizer's or libFuzzer's, which would
  // report the child's crash as the parent's) are taken away first.
  for (const int signal : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) std::signal(signal, SIG_DFL);
  if (__sanitizer_set_death_callback != nullptr) __sanitizer_set_death_callback(nullptr);
  const int null = ::open("/dev/null", O_WRONLY);
  if (null >= 0) {
    ::dup2(null, STDOUT_FILENO);
    ::dup2(null, STDERR_FILENO);
  }
  int status = kCompleted;
  try {
    call();
  } catch (const Error&) {
    // A clear refusal: the caller's own call will throw it again.
  } catch (...) {
    status = kOtherException;
  }
  ::_exit(status);  // no atexit handlers or static destructors of the parent's state
}

std::string describe(int status) {
  if (WIFSIGNALED(status)) {
    const int signal = WTERMSIG(status);
    return "crashed (signal " + std::to_string(signal) + ", " + ::strsignal(signal) + ")";
  }
  if (WIFEXITED(status) && WEXITSTATUS(status) == kOtherException) {
    return "failed with an unexpected exception";
  }
  return "exited with status " + std::to_string(WEXITSTATUS(status));
}

}  // namespace

IsolatedOutcome run_isolated(const std::function<void()>& call, std::chrono::milliseconds timeout) {
  // The child holds the write end of a pipe until it exits, so the parent wakes the moment it
  // does (poll sees the hang-up) instead of polling waitpid on a timer.
  int ends[2];
  if (::pipe(ends) != 0) {
    throw Error(std::string("cannot start a child process (") + std::strerror(errno) + ")");
  }
  const pid_t child = ::fork();
  if (child < 0) {
    const int error = errno;
    ::close(ends[0]);
    ::close(ends[1]);
    throw Error(std::string("cannot start a child process (") + std::strerror(error) + ")");
  }
  if (child == 0) {
    ::close(ends[0]);
    run_child(call);
  }
  ::close(ends[1]);
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  bool finished = false;
  while (!finished) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) break;
    pollfd hang_up{ends[0], POLLIN, 0};
    const int ready =
        ::poll(&hang_up, 1, static_cast<int>(std::min<long long>(left.count(), 60000)));
    finished = ready > 0;
  }
  ::close(ends[0]);
  int status = 0;
  if (!finished) {
    ::kill(child, SIGKILL);
    ::waitpid(child, &status, 0);
    const long long ms = timeout.count();
    return {false, "did not finish within " + (ms % 1000 == 0 ? std::to_string(ms / 1000) + " s"
                                                              : std::to_string(ms) + " ms")};
  }
  while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  if (WIFEXITED(status) && WEXITSTATUS(status) == kCompleted) return {true, {}};
  return {false, describe(status)};
}

}  // namespace graspecmf
