// SPDX-License-Identifier: MIT
// Assembling the sliding counterface (seed report, Section 2.1.9): several line scans ("segments") placed
// end to end along the sliding direction, each brought separately into point contact with the substrate,
// then linked into one rigid body. For the apparent-area study (report Fig. 2.24) `copies` copies of that
// counterface move in unison; copy j starts at x = j * L_substrate / copies (the substrate is periodic), and
// each of its segments is again brought into point contact where it lands.
#pragma once

#include <cstddef>
#include <vector>

#include "tools/pstd/model.hpp"
#include "tools/pstd/profiles.hpp"

namespace tribex::pstd {

/// All profiles must share one grid spacing. Throws tools::BadInput if one copy of the counterface is
/// longer than the substrate (it would overlap itself on the periodic substrate).
Model build_model(const Profile& substrate, const std::vector<Profile>& segments, std::size_t copies,
                  const Mechanics& mechanics);

}  // namespace tribex::pstd
