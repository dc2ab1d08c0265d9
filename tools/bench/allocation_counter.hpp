// SPDX-License-Identifier: MIT
// Counts heap allocations of the whole process (global operator new is replaced in
// allocation_counter.cpp, linked into the tribex executable through the bench tool), so the
// benchmark can show that the time-step loop allocates nothing.
#pragma once

#include <cstdint>

namespace tribex::bench {
std::uint64_t allocation_count();
}
