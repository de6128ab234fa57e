// Runs every flow test with one LibTorch thread (the machines' other core is usually busy, and
// multi-threaded small ops were measured to be much slower then).

#include <ATen/Parallel.h>
#include <gtest/gtest.h>

namespace {

class SingleThread : public ::testing::Environment {
 public:
  void SetUp() override { at::set_num_threads(1); }
};

const auto* const kSingleThread = ::testing::AddGlobalTestEnvironment(new SingleThread);

}  // namespace
