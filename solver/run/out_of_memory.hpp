// SPDX-License-Identifier: MIT
// Out of memory in a run (issue 54 item 13): in set-up exit 2 naming the stage and the request that
// failed, in the loop exit 3 with summary.json written. The size comes from the tribex binary's
// replacement of the global operator new (tools/bench/allocation_counter.cpp: it records a request
// that fails, then throws std::bad_alloc); allocations through malloc (Eigen, HDF5) are not seen.
#pragma once

#include <cstddef>
#include <string>

namespace tribex::solver {

/// Records a failed request (called by the replaced operator new).
void record_failed_allocation(std::size_t bytes);

/// Bytes of the last operator new request that failed (0: none seen).
std::size_t last_failed_allocation();

/// "out of memory while STAGE (a request for 1.2 GB failed; address-space limit 195 MB, ulimit -v)".
std::string out_of_memory_text(const std::string& stage);

}  // namespace tribex::solver
