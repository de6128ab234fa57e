#include "graspecmf/core/isolated_call.hpp"

#include <gtest/gtest.h>

#include <csignal>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "graspecmf/core/error.hpp"

namespace graspecmf {
namespace {

using std::chrono::milliseconds;

TEST(IsolatedCall, ReturnsAndErrorsComplete) {
  int calls = 0;
  EXPECT_TRUE(run_isolated([&] { ++calls; }, milliseconds(10000)).completed);
  EXPECT_EQ(calls, 0);  // the child's effects stay in the child
  const IsolatedOutcome refused = run_isolated([] { throw Error("refused"); }, milliseconds(10000));
  EXPECT_TRUE(refused.completed);
  EXPECT_EQ(refused.refusals, std::vector<std::string>{"refused"});
}

// Each finished call's Error message comes back (cut to 4096 bytes), empty for a call that
// returned, also from a child that crashes later.
TEST(IsolatedCall, RefusalsComeBackWithTheirMessages) {
  const std::string long_message(10000, 'x');
  const IsolatedOutcome outcome = run_isolated_steps(
      5,
      [&](std::size_t i) {
        if (i == 1) throw Error("bad file 1");
        if (i == 2) throw Error(long_message);
        if (i == 4) std::raise(SIGSEGV);
      },
      milliseconds(10000));
  EXPECT_FALSE(outcome.completed);
  ASSERT_EQ(outcome.finished, 4U);
  EXPECT_EQ(outcome.refusals,
            (std::vector<std::string>{"", "bad file 1", long_message.substr(0, 4096), ""}));
}

TEST(IsolatedCall, CrashesAbortsAndHangsAreReportedNotSuffered) {
  const IsolatedOutcome crash = run_isolated([] { std::raise(SIGSEGV); }, milliseconds(10000));
  EXPECT_FALSE(crash.completed);
  EXPECT_EQ(crash.failure.rfind("crashed (signal 11", 0), 0U) << crash.failure;
  const IsolatedOutcome abort = run_isolated([] { std::abort(); }, milliseconds(10000));
  EXPECT_EQ(abort.failure.rfind("crashed (signal 6", 0), 0U) << abort.failure;
  const IsolatedOutcome other =
      run_isolated([] { throw std::runtime_error("?"); }, milliseconds(10000));
  EXPECT_EQ(other.failure, "failed with an unexpected exception");
  const IsolatedOutcome hang = run_isolated(
      [] { std::this_thread::sleep_for(std::chrono::seconds(30)); }, milliseconds(300));
  EXPECT_FALSE(hang.completed);
  EXPECT_EQ(hang.failure, "did not finish within 300 ms");
}

// Many calls share one child; each has its own time limit, and the outcome says which call the
// child ended in.
TEST(IsolatedCall, StepsShareOneChildAndReportWhereItEnded) {
  const IsolatedOutcome slow = run_isolated_steps(
      4, [](std::size_t) { std::this_thread::sleep_for(milliseconds(150)); }, milliseconds(400));
  EXPECT_TRUE(slow.completed) << slow.failure;  // 600 ms in all, under 400 ms each
  EXPECT_EQ(slow.finished, 4U);
  EXPECT_EQ(slow.refusals, std::vector<std::string>(4));
  const IsolatedOutcome crash = run_isolated_steps(
      5,
      [](std::size_t i) {
        if (i == 2) std::raise(SIGSEGV);
      },
      milliseconds(10000));
  EXPECT_FALSE(crash.completed);
  EXPECT_EQ(crash.finished, 2U);
  EXPECT_EQ(crash.failure.rfind("crashed (signal 11", 0), 0U) << crash.failure;
  const IsolatedOutcome hang = run_isolated_steps(
      3,
      [](std::size_t i) {
        if (i == 1) std::this_thread::sleep_for(std::chrono::seconds(30));
      },
      milliseconds(300));
  EXPECT_EQ(hang.finished, 1U);
  EXPECT_EQ(hang.failure, "did not finish within 300 ms");
  EXPECT_TRUE(run_isolated_steps(
                  0, [](std::size_t) { std::abort(); }, milliseconds(1000))
                  .completed);
}

}  // namespace
}  // namespace graspecmf
