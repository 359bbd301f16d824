// SPDX-License-Identifier: MIT
#include "allocationcounter.h"

#include <atomic>
#include <cstdlib>
#include <new>

namespace {

std::atomic<bool> g_counting{false};
std::atomic<long> g_allocations{0};

void *countedAlloc(std::size_t size) noexcept
{
    if (g_counting.load(std::memory_order_relaxed))
        g_allocations.fetch_add(1, std::memory_order_relaxed);
    return std::malloc(size == 0 ? 1 : size);
}

void *countedAllocOrThrow(std::size_t size)
{
    if (void *p = countedAlloc(size))
        return p;
    throw std::bad_alloc();
}

} // namespace

namespace semhap::test {

void startCountingAllocations()
{
    g_allocations = 0;
    g_counting = true;
}

long stopCountingAllocations()
{
    g_counting = false;
    return g_allocations.load();
}

} // namespace semhap::test

// Every unaligned form is replaced, so that no pointer from another allocator reaches free.
void *operator new(std::size_t size)
{
    return countedAllocOrThrow(size);
}

void *operator new[](std::size_t size)
{
    return countedAllocOrThrow(size);
}

void *operator new(std::size_t size, const std::nothrow_t &) noexcept
{
    return countedAlloc(size);
}

void *operator new[](std::size_t size, const std::nothrow_t &) noexcept
{
    return countedAlloc(size);
}

void operator delete(void *p) noexcept
{
    std::free(p);
}

void operator delete[](void *p) noexcept
{
    std::free(p);
}

void operator delete(void *p, std::size_t) noexcept
{
    std::free(p);
}

void operator delete[](void *p, std::size_t) noexcept
{
    std::free(p);
}

void operator delete(void *p, const std::nothrow_t &) noexcept
{
    std::free(p);
}

void operator delete[](void *p, const std::nothrow_t &) noexcept
{
    std::free(p);
}
