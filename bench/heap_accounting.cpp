// SPDX-License-Identifier: MIT
// Heap accounting: peak live heap bytes of one construction.
//
// Every operator new/delete of the process is replaced (below, at global scope) by malloc/free
// plus a running count of live bytes, as reported by malloc_usable_size, and of its maximum.
// A construction's peak memory is then (maximum during the construction) - (live bytes before
// it), with the result still alive at the end, so the output counts as it should. This is exact,
// deterministic and the same rule for both sides: our std::vectors and CGAL's
// Compact_container blocks and spatial-sort copy all come from operator new.
// Rejected alternatives: VmHWM (peak RSS) growth, even in a forked child, undercounts because
// malloc keeps the memory freed by earlier benchmarks resident and hands it out again, and
// counts in pages; mallinfo2() gives current bytes, not the peak; glibc 2.36 has no malloc
// hooks; Google Benchmark's MemoryManager would rerun each construction up to 16 times.
// Not counted: direct malloc calls (GMP limbs in the rare exact predicate stages, both sides).
// The bookkeeping costs two relaxed atomic updates per allocation; both sides allocate O(log n)
// times (geometric growth), so the timings do not notice it.

#include "bench/heap_accounting.hpp"

#include <malloc.h>

#include <atomic>
#include <cstdlib>
#include <new>

namespace {

constinit std::atomic<std::size_t> heap_live_bytes{0};
constinit std::atomic<std::size_t> heap_peak_bytes{0};

void note_allocation(void* block) noexcept {
    const std::size_t bytes = malloc_usable_size(block);
    const std::size_t live = heap_live_bytes.fetch_add(bytes, std::memory_order_relaxed) + bytes;
    std::size_t peak = heap_peak_bytes.load(std::memory_order_relaxed);
    while (live > peak &&
           !heap_peak_bytes.compare_exchange_weak(peak, live, std::memory_order_relaxed)) {
    }
}

void release(void* block) noexcept {
    if (block == nullptr) return;
    heap_live_bytes.fetch_sub(malloc_usable_size(block), std::memory_order_relaxed);
    std::free(block);
}

void* try_allocate(std::size_t size) noexcept {
    void* block = std::malloc(size == 0 ? 1 : size);
    if (block != nullptr) note_allocation(block);
    return block;
}

void* try_allocate_aligned(std::size_t size, std::align_val_t alignment) noexcept {
    const auto align = static_cast<std::size_t>(alignment);
    // aligned_alloc wants a size that is a multiple of the alignment.
    const std::size_t rounded = size == 0 ? align : (size + align - 1) / align * align;
    void* block = std::aligned_alloc(align, rounded);
    if (block != nullptr) note_allocation(block);
    return block;
}

void* allocate(std::size_t size) {
    if (void* block = try_allocate(size)) return block;
    throw std::bad_alloc();
}

void* allocate_aligned(std::size_t size, std::align_val_t alignment) {
    if (void* block = try_allocate_aligned(size, alignment)) return block;
    throw std::bad_alloc();
}

}  // namespace

// All replaceable forms, so that no allocation bypasses the count whichever form a library uses.
void* operator new(std::size_t size) {
    return allocate(size);
}
void* operator new[](std::size_t size) {
    return allocate(size);
}
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
    return try_allocate(size);
}
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept {
    return try_allocate(size);
}
void* operator new(std::size_t size, std::align_val_t alignment) {
    return allocate_aligned(size, alignment);
}
void* operator new[](std::size_t size, std::align_val_t alignment) {
    return allocate_aligned(size, alignment);
}
void* operator new(std::size_t size, std::align_val_t alignment, const std::nothrow_t&) noexcept {
    return try_allocate_aligned(size, alignment);
}
void* operator new[](std::size_t size, std::align_val_t alignment, const std::nothrow_t&) noexcept {
    return try_allocate_aligned(size, alignment);
}
void operator delete(void* block) noexcept {
    release(block);
}
void operator delete[](void* block) noexcept {
    release(block);
}
void operator delete(void* block, std::size_t) noexcept {
    release(block);
}
void operator delete[](void* block, std::size_t) noexcept {
    release(block);
}
void operator delete(void* block, const std::nothrow_t&) noexcept {
    release(block);
}
void operator delete[](void* block, const std::nothrow_t&) noexcept {
    release(block);
}
void operator delete(void* block, std::align_val_t) noexcept {
    release(block);
}
void operator delete[](void* block, std::align_val_t) noexcept {
    release(block);
}
void operator delete(void* block, std::size_t, std::align_val_t) noexcept {
    release(block);
}
void operator delete[](void* block, std::size_t, std::align_val_t) noexcept {
    release(block);
}
void operator delete(void* block, std::align_val_t, const std::nothrow_t&) noexcept {
    release(block);
}
void operator delete[](void* block, std::align_val_t, const std::nothrow_t&) noexcept {
    release(block);
}

namespace exactmesh::bench {

std::size_t start_heap_measurement() {
    const std::size_t before = heap_live_bytes.load(std::memory_order_relaxed);
    heap_peak_bytes.store(before, std::memory_order_relaxed);
    return before;
}

double heap_growth_since(std::size_t before) {
    return static_cast<double>(heap_peak_bytes.load(std::memory_order_relaxed) - before);
}

}  // namespace exactmesh::bench
