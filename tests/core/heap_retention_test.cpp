#include "graspecmf/core/heap_retention.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>

#ifdef __GLIBC__
#include <malloc.h>
#endif

namespace graspecmf {
namespace {

#ifdef __GLIBC__
// The number of blocks malloc has served with their own mmap.
std::size_t mapped_blocks() {
  return mallinfo2().hblks;
}

// Allocates and touches `bytes`; returns how many more mmap'd blocks exist while it is held.
std::size_t extra_mapped_blocks(std::size_t bytes) {
  const std::size_t before = mapped_blocks();
  char* volatile block = static_cast<char*>(std::malloc(bytes));
  std::memset(block, 1, bytes);
  const std::size_t during = mapped_blocks();
  std::free(block);
  return during - before;
}
#endif

TEST(HeapRetention, KeepsLargeBlocksInTheHeapUnlessTheEnvironmentSaysOtherwise) {
#ifndef __GLIBC__
  GTEST_SKIP() << "malloc tuning applies to glibc only";
#else
  ASSERT_EQ(std::getenv("GLIBC_TUNABLES"), nullptr);
  setenv("MALLOC_TRIM_THRESHOLD_", "131072", 1);
  EXPECT_FALSE(retain_freed_memory());  // the user's own setting wins
  unsetenv("MALLOC_TRIM_THRESHOLD_");

  // By default a 24 MB block gets its own mapping, given back to the kernel when freed (glibc
  // then raises its threshold to 24 MB, so the check below uses a larger block).
  EXPECT_EQ(extra_mapped_blocks(24 << 20), 1u);
  ASSERT_TRUE(retain_freed_memory());
  EXPECT_EQ(extra_mapped_blocks(30 << 20), 0u);
  EXPECT_GE(mallinfo2().fordblks, std::size_t{30} << 20);  // freed but kept in the heap
  EXPECT_EQ(extra_mapped_blocks(kHeapBlockLimit + (1 << 20)), 1u);
#endif
}

}  // namespace
}  // namespace graspecmf
