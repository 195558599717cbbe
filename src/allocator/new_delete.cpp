// The global operator new and delete of the project's programs, on mimalloc.
//
// Linking mimalloc replaces malloc and free in the whole process; its own operator
// new, however, aborts the process when a request cannot be met, and it reserves
// address space for any request however large. A damaged input can ask for a huge
// buffer (a length read from a corrupted file), and that must end in
// std::bad_alloc, which the readers turn into a clear error, never in a crash or in
// the machine running out of memory. These replacements refuse a request larger
// than the machine's physical memory (as the system's allocator does under Linux's
// default overcommit rule), allocate the rest with mimalloc, and throw as the
// standard says. mimalloc is also given address space advised for huge pages.
#include <mimalloc.h>
#include <sys/mman.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <new>

namespace {

/// The physical memory's size, or the largest size_t when it is unknown.
std::size_t physicalMemory() {
  const long pages = sysconf(_SC_PHYS_PAGES), pageSize = sysconf(_SC_PAGE_SIZE);
  return pages > 0 && pageSize > 0 ? static_cast<std::size_t>(pages) * static_cast<std::size_t>(pageSize)
                                   : static_cast<std::size_t>(-1);
}

#if defined(MADV_HUGEPAGE) && MI_MALLOC_VERSION >= 209 && MI_MALLOC_VERSION < 300

/// mimalloc 2's segments: 32 MiB, aligned to their size.
constexpr std::uintptr_t kSegmentSize = std::uintptr_t{32} << 20;

/// mimalloc places a reservation of at most 1 GiB at addresses of its own choosing,
/// where it finds a block's segment again (mi_is_in_heap_region); a larger one lands
/// anywhere.
constexpr std::size_t kArenaSize = std::size_t{1} << 30;
constexpr std::size_t kMostArenas = 16;

/// Whether the process's address space is unlimited (no RLIMIT_AS): reserving some
/// of it then takes nothing from other requests.
bool unlimitedAddressSpace() {
  rlimit limit{};
  return getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur == RLIM_INFINITY;
}

/// A build touches hundreds of MB once, and with the system's 4 KiB pages every
/// first touch is a page fault (58,000 in one build of house_mixed_32). The segment
/// mimalloc took when the process started, which holds most of a small build, is
/// advised for transparent huge pages (2 MiB each) where its 2 MiB pieces are still
/// untouched; and mimalloc is given arenas of 1 GiB, a quarter of the physical memory
/// in all (at most 16), reserved without being committed (it commits a segment when
/// it takes one) and advised alike, which it fills before it asks the system for
/// more. Where the system refuses a reservation or the advice, or the address space
/// is limited, or the memory size is unknown, mimalloc allocates as before.
void useHugePages() {
  void* early = mi_malloc(1);
  madvise(reinterpret_cast<void*>(reinterpret_cast<std::uintptr_t>(early) & ~(kSegmentSize - 1)), kSegmentSize,
          MADV_HUGEPAGE);
  mi_free(early);
  const std::size_t memory = physicalMemory();
  if (memory == static_cast<std::size_t>(-1) || !unlimitedAddressSpace()) return;
  const std::size_t count = std::min(memory / 4 / kArenaSize, kMostArenas);
  for (std::size_t k = 0; k < count; ++k) {
    mi_arena_id_t arena = 0;
    const bool commit = false, allowLarge = false, exclusive = false;
    if (mi_reserve_os_memory_ex(kArenaSize, commit, allowLarge, exclusive, &arena) != 0) return;
    std::size_t size = 0;
    void* start = mi_arena_area(arena, &size);
    if (start == nullptr || madvise(start, size, MADV_HUGEPAGE) != 0) return;
  }
}

/// mimalloc gives the pages of a freed span back to the system (decommits them) a
/// few milliseconds after the span is freed. A build frees and allocates again all
/// the time, and each give-back splits a huge page, whose 4 KiB pieces then fault and
/// are zeroed again on the next touch: house_mixed_160 committed 1.6 GiB for a peak
/// of 0.95 GiB, with 22,000 page faults (1,400 without the give-back) and about 13% of
/// its time in the kernel. Freed memory is therefore kept for the process's later
/// allocations, unless the user's environment says otherwise
/// (MIMALLOC_ALLOW_DECOMMIT). It is set before the first segment of ours is taken.
void keepFreedMemory() {
  if (std::getenv("MIMALLOC_ALLOW_DECOMMIT") == nullptr) mi_option_disable(mi_option_allow_decommit);
}

/// Sets the huge pages up when the program starts.
const struct HugePageSetup {
  HugePageSetup() {
    keepFreedMemory();
    useHugePages();
  }
} hugePageSetup;

#endif

bool beyondMemory(std::size_t size) {
  static const std::size_t limit = physicalMemory();
  return size > limit;
}

void* allocate(std::size_t size) noexcept { return beyondMemory(size) ? nullptr : mi_new_nothrow(size); }

void* allocate(std::size_t size, std::align_val_t alignment) noexcept {
  return beyondMemory(size) ? nullptr : mi_new_aligned_nothrow(size, static_cast<std::size_t>(alignment));
}

void* orBadAlloc(void* memory) {
  if (memory == nullptr) throw std::bad_alloc();
  return memory;
}

}  // namespace

void* operator new(std::size_t size) { return orBadAlloc(allocate(size)); }
void* operator new[](std::size_t size) { return orBadAlloc(allocate(size)); }
void* operator new(std::size_t size, std::align_val_t alignment) { return orBadAlloc(allocate(size, alignment)); }
void* operator new[](std::size_t size, std::align_val_t alignment) { return orBadAlloc(allocate(size, alignment)); }
void* operator new(std::size_t size, const std::nothrow_t&) noexcept { return allocate(size); }
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept { return allocate(size); }
void* operator new(std::size_t size, std::align_val_t alignment, const std::nothrow_t&) noexcept {
  return allocate(size, alignment);
}
void* operator new[](std::size_t size, std::align_val_t alignment, const std::nothrow_t&) noexcept {
  return allocate(size, alignment);
}

// mimalloc frees any of its blocks whatever the size or alignment it was asked for.
void operator delete(void* memory) noexcept { mi_free(memory); }
void operator delete[](void* memory) noexcept { mi_free(memory); }
void operator delete(void* memory, std::size_t) noexcept { mi_free(memory); }
void operator delete[](void* memory, std::size_t) noexcept { mi_free(memory); }
void operator delete(void* memory, std::align_val_t) noexcept { mi_free(memory); }
void operator delete[](void* memory, std::align_val_t) noexcept { mi_free(memory); }
void operator delete(void* memory, std::size_t, std::align_val_t) noexcept { mi_free(memory); }
void operator delete[](void* memory, std::size_t, std::align_val_t) noexcept { mi_free(memory); }
void operator delete(void* memory, const std::nothrow_t&) noexcept { mi_free(memory); }
void operator delete[](void* memory, const std::nothrow_t&) noexcept { mi_free(memory); }
void operator delete(void* memory, std::align_val_t, const std::nothrow_t&) noexcept { mi_free(memory); }
void operator delete[](void* memory, std::align_val_t, const std::nothrow_t&) noexcept { mi_free(memory); }
