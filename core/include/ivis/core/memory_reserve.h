/// @file memory_reserve.h
/// @brief Room kept back for the cleanup after an allocation fails: OpenVDB's trees allocate as
///        they free, so a std::bad_alloc that unwinds a volume build with no memory left would end
///        the process (std::terminate) instead of reaching the program's one-line error.
#pragma once

#include <cstddef>

namespace ivis::core {

/// @brief While at least one lives, @a bytes of address space are held back (allocated, never
///        touched) and a new-handler is set. The first operator new that fails frees them: outside
///        an unwinding it then throws std::bad_alloc, so that the unwinding it starts has that
///        room; within one (a destructor allocating) it is retried in that room. Later failures
///        throw std::bad_alloc as usual. Thread-safe; the last one to go puts the previous
///        new-handler back.
class ScopedMemoryReserve {
public:
    /// @brief Holds back @a bytes (16 MiB by default) unless a reserve is held already.
    explicit ScopedMemoryReserve(std::size_t bytes = std::size_t(16) << 20);
    ~ScopedMemoryReserve();
    ScopedMemoryReserve(const ScopedMemoryReserve&) = delete;
    ScopedMemoryReserve& operator=(const ScopedMemoryReserve&) = delete;
};

}  // namespace ivis::core
