// Counts every allocation and release of the executable that includes
// this header, by replacing the global operator new and delete. Include it
// in one source file of a test executable only.
#pragma once

#include <atomic>
#include <cstdlib>
#include <new>

namespace jl::test {

inline std::atomic<long long> allocations{0}, releases{0};

inline long long live() { return allocations.load() - releases.load(); }

}  // namespace jl::test

void* operator new(std::size_t size) {
    ++jl::test::allocations;
    if (void* p = std::malloc(size ? size : 1)) return p;
    throw std::bad_alloc();
}
void* operator new[](std::size_t size) { return operator new(size); }
void operator delete(void* p) noexcept {
    if (!p) return;
    ++jl::test::releases;
    std::free(p);
}
void operator delete[](void* p) noexcept { operator delete(p); }
void operator delete(void* p, std::size_t) noexcept { operator delete(p); }
void operator delete[](void* p, std::size_t) noexcept { operator delete(p); }
// The nothrow forms too (std::stable_sort's buffer takes one): left to the
// runtime, a sanitizer's own new would meet this file's free.
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
    ++jl::test::allocations;
    return std::malloc(size ? size : 1);
}
void* operator new[](std::size_t size, const std::nothrow_t& tag) noexcept { return operator new(size, tag); }
void operator delete(void* p, const std::nothrow_t&) noexcept { operator delete(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { operator delete(p); }
