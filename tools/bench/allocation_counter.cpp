// SPDX-License-Identifier: MIT
#include "tools/bench/allocation_counter.hpp"

#include <atomic>
#include <cstdlib>
#include <new>

#include "solver/run/out_of_memory.hpp"

namespace {
std::atomic<std::uint64_t> g_allocations{0};
}

#if defined(__SANITIZE_ADDRESS__)
// AddressSanitizer owns operator new/delete and checks that they pair; replacing them here would
// mix its allocator with malloc/free. Under the sanitizer the benchmark reports no count.
namespace tribex::bench {
std::uint64_t allocation_count() { return 0; }
}  // namespace tribex::bench
#else
namespace tribex::bench {
std::uint64_t allocation_count() { return g_allocations.load(std::memory_order_relaxed); }
}  // namespace tribex::bench

// Every replaceable form (plain and nothrow, scalar and array) counts and goes to malloc/free, so
// that memory allocated through any of them is released by the matching delete below.
void* operator new(std::size_t size) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size ? size : 1)) return p;
  tribex::solver::record_failed_allocation(size);  // an out-of-memory message names it (solver/run/out_of_memory.hpp)
  throw std::bad_alloc();
}
void* operator new[](std::size_t size) { return ::operator new(size); }
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  return std::malloc(size ? size : 1);
}
void* operator new[](std::size_t size, const std::nothrow_t& tag) noexcept { return ::operator new(size, tag); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }
#endif
