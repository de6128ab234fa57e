#include "graspecmf/core/isolated_call.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstring>

#include "graspecmf/core/error.hpp"

// Present only in sanitizer builds (the fuzzers): the callback a sanitizer runs before it exits.
extern "C" void __sanitizer_set_death_callback(void (*callback)()) __attribute__((weak));

namespace graspecmf {
namespace {

// Exit statuses of the child: the call completed, or threw something other than Error.
constexpr int kCompleted = 0;
constexpr int kOtherException = 3;
// A refusal's message is cut to this many bytes on its way to the parent.
constexpr std::uint32_t kMaxMessage = 4096;

// Writes all size bytes to fd, or exits the child.
void write_all(int fd, const char* data, std::size_t size) {
  while (size > 0) {
    const ssize_t n = ::write(fd, data, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) ::_exit(kOtherException);
    data += n;
    size -= static_cast<std::size_t>(n);
  }
}

// Tells the parent that a call finished: a 4-byte length, then the Error's message (length 0
// when the call returned).
void report(int fd, const std::string& message) {
  const auto length =
      static_cast<std::uint32_t>(std::min<std::size_t>(message.size(), kMaxMessage));
  write_all(fd, reinterpret_cast<const char*>(&length), sizeof length);
  write_all(fd, message.data(), length);
}

[[noreturn]] void run_child(std::size_t count, const std::function<void(std::size_t)>& step,
                            int progress) {
  // The child dies plainly: the parent's crash handlers (a sanitizer's or libFuzzer's, which would
  // report the child's crash as the parent's) are taken away first.
  for (const int signal : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) std::signal(signal, SIG_DFL);
  if (__sanitizer_set_death_callback != nullptr) __sanitizer_set_death_callback(nullptr);
  const int null = ::open("/dev/null", O_WRONLY);
  if (null >= 0) {
    ::dup2(null, STDOUT_FILENO);
    ::dup2(null, STDERR_FILENO);
  }
  for (std::size_t i = 0; i < count; ++i) {
    std::string message;
    try {
      step(i);
    } catch (const Error& e) {
      message = e.what();  // a clear refusal, passed on to the caller
      if (message.empty()) message = "error";
    } catch (...) {
      ::_exit(kOtherException);
    }
    report(progress, message);  // also tells the parent to restart its clock
  }
  ::_exit(kCompleted);  // no atexit handlers or static destructors of the parent's state
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

IsolatedOutcome run_isolated_steps(std::size_t count, const std::function<void(std::size_t)>& step,
                                   std::chrono::milliseconds step_timeout) {
  // The child writes a record to a pipe after each call and holds the write end until it exits,
  // so the parent wakes the moment a call finishes or the child ends (poll sees the hang-up)
  // instead of polling waitpid on a timer.
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
    run_child(count, step, ends[1]);
  }
  ::close(ends[1]);
  IsolatedOutcome outcome;
  std::string received;  // bytes of records not yet complete
  auto deadline = std::chrono::steady_clock::now() + step_timeout;
  bool ended = false;
  while (!ended) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) break;
    pollfd readable{ends[0], POLLIN, 0};
    if (::poll(&readable, 1, static_cast<int>(std::min<long long>(left.count(), 60000))) <= 0) {
      continue;
    }
    char bytes[4096];
    const ssize_t n = ::read(ends[0], bytes, sizeof bytes);
    if (n > 0) received.append(bytes, static_cast<std::size_t>(n));
    std::uint32_t length = 0;
    while (received.size() >= sizeof length) {
      std::memcpy(&length, received.data(), sizeof length);
      if (received.size() < sizeof length + length) break;
      outcome.refusals.push_back(received.substr(sizeof length, length));
      received.erase(0, sizeof length + length);
      ++outcome.finished;
      deadline = std::chrono::steady_clock::now() + step_timeout;
    }
    ended = n == 0 || (n < 0 && errno != EINTR);
  }
  ::close(ends[0]);
  int status = 0;
  if (!ended) {
    ::kill(child, SIGKILL);
    ::waitpid(child, &status, 0);
    const long long ms = step_timeout.count();
    outcome.failure = "did not finish within " + (ms % 1000 == 0 ? std::to_string(ms / 1000) + " s"
                                                                 : std::to_string(ms) + " ms");
    return outcome;
  }
  while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  outcome.completed =
      WIFEXITED(status) && WEXITSTATUS(status) == kCompleted && outcome.finished == count;
  if (!outcome.completed) outcome.failure = describe(status);
  return outcome;
}

IsolatedOutcome run_isolated(const std::function<void()>& call, std::chrono::milliseconds timeout) {
  return run_isolated_steps(
      1, [&](std::size_t) { call(); }, timeout);
}

}  // namespace graspecmf
