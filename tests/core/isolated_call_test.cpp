#include "graspecmf/core/isolated_call.hpp"

#include <gtest/gtest.h>

#include <csignal>
#include <stdexcept>
#include <thread>

#include "graspecmf/core/error.hpp"

namespace graspecmf {
namespace {

using std::chrono::milliseconds;

TEST(IsolatedCall, ReturnsAndErrorsComplete) {
  int calls = 0;
  EXPECT_TRUE(run_isolated([&] { ++calls; }, milliseconds(10000)).completed);
  EXPECT_EQ(calls, 0);  // the child's effects stay in the child
  EXPECT_TRUE(run_isolated([] { throw Error("refused"); }, milliseconds(10000)).completed);
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

}  // namespace
}  // namespace graspecmf
