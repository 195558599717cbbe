// The allocator of the project's programs (src/allocator): requests that cannot be
// met end in std::bad_alloc (which readers of damaged files turn into a clear error),
// never in an aborted process, and ordinary ones come from mimalloc when it is linked.
#include <gtest/gtest.h>

#include <cstddef>
#include <cstdlib>
#include <memory>
#include <new>
#include <vector>

#ifdef FREESPACE_WITH_MIMALLOC
#include <mimalloc.h>
#include <sys/mman.h>
#endif

TEST(ProgramAllocator, ARequestBeyondThePhysicalMemoryThrowsBadAlloc) {
  // 16 TiB: more memory than a machine this runs on has, less than the address space
  // (an allocator that only reserves address space could grant it).
  const std::size_t beyondMemory = std::size_t(1) << 44;
  std::vector<char> buffer;
  EXPECT_THROW(buffer.reserve(beyondMemory), std::bad_alloc);
  void* block = nullptr;
  EXPECT_THROW(block = ::operator new(beyondMemory), std::bad_alloc);
  ::operator delete(block);
  char* nothing = new (std::nothrow) char[beyondMemory];
  EXPECT_EQ(nothing, nullptr);
  delete[] nothing;
}

TEST(ProgramAllocator, OrdinaryRequestsAreMet) {
  std::vector<std::unique_ptr<double[]>> blocks;
  for (std::size_t size = 1; size <= (std::size_t(1) << 24); size *= 4) {
    blocks.push_back(std::make_unique<double[]>(size));
    blocks.back()[size - 1] = 1.0;
#ifdef FREESPACE_WITH_MIMALLOC
    EXPECT_TRUE(mi_is_in_heap_region(blocks.back().get())) << size;
#endif
  }
  EXPECT_EQ(blocks.size(), 13u);
}

#if defined(FREESPACE_WITH_MIMALLOC) && defined(MADV_HUGEPAGE) && MI_MALLOC_VERSION >= 209 && MI_MALLOC_VERSION < 300
TEST(ProgramAllocator, FreedMemoryIsKeptUnlessTheEnvironmentSaysOtherwise) {
  // Giving freed pages back to the system splits huge pages (src/allocator).
  if (std::getenv("MIMALLOC_ALLOW_DECOMMIT") != nullptr) GTEST_SKIP() << "MIMALLOC_ALLOW_DECOMMIT is set";
  EXPECT_FALSE(mi_option_is_enabled(mi_option_allow_decommit));
}
#endif
