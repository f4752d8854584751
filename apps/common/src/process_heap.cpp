// Page faults are most of what a course render's start-up costs beyond its instructions: about 9 us each on the
// machines measured (2026-11), and a 1280 x 960 run took 9,800 of them -- the mesh's arrays, the kd-tree build's
// per-node blocks, the image. glibc maps blocks from 128 kB up afresh and returns freed memory to the kernel, so the
// build paid for the same pages again node after node; and the kernel's transparent huge pages, which would take one
// fault per 2 MB instead of per 4 kB, are here only given to memory that asks for them (madvise).
#include <rtlab/app/process_heap.hpp>

#if defined(__GLIBC__) && defined(__linux__) && !defined(__SANITIZE_ADDRESS__)
#define RTLAB_TUNE_HEAP 1
#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#endif

namespace rtlab::app {

void prepare_heap() {
#if RTLAB_TUNE_HEAP
    mallopt(M_MMAP_THRESHOLD, 32 << 20);
    mallopt(M_TRIM_THRESHOLD, 256 << 20);
    // Grow the heap by 64 MB at once (a block larger than any free one, with that much padding), advise the
    // grown part into huge pages and keep it (the trim threshold above). When the heap cannot grow, the block is
    // mapped elsewhere above the break and nothing is advised; when huge pages are off, madvise fails harmlessly.
    constexpr std::uintptr_t kGrowth = std::uintptr_t{64} << 20, kHugePage = std::uintptr_t{2} << 20;
    mallopt(M_TOP_PAD, static_cast<int>(kGrowth));
    void* block = std::malloc(1 << 20);
    const auto lo = (reinterpret_cast<std::uintptr_t>(block) + kHugePage - 1) & ~(kHugePage - 1);
    const auto hi = reinterpret_cast<std::uintptr_t>(sbrk(0)) & ~(kHugePage - 1);
    if (block && hi > lo) madvise(reinterpret_cast<void*>(lo), hi - lo, MADV_HUGEPAGE);
    std::free(block);
    mallopt(M_TOP_PAD, 128 << 10);  // glibc's default again
#endif
}

}  // namespace rtlab::app
