#include "graspecmf/core/heap_retention.hpp"

#include <cstdlib>
#include <cstring>

#ifdef __GLIBC__
#include <malloc.h>
#endif

namespace graspecmf {

bool retain_freed_memory() {
#ifdef __GLIBC__
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  if ((tunables != nullptr && std::strstr(tunables, "malloc") != nullptr) ||
      std::getenv("MALLOC_MMAP_THRESHOLD_") != nullptr ||
      std::getenv("MALLOC_TRIM_THRESHOLD_") != nullptr) {
    return false;
  }
  // Setting either threshold also turns off glibc's own raising of the mmap threshold, so both
  // are set together; setting only the trim threshold made training steps 5× slower here.
  return mallopt(M_MMAP_THRESHOLD, static_cast<int>(kHeapBlockLimit)) == 1 &&
         mallopt(M_TRIM_THRESHOLD, static_cast<int>(kRetainedFreeMemory)) == 1;
#else
  return false;
#endif
}

}  // namespace graspecmf
