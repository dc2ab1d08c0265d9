// SPDX-License-Identifier: MIT
// The PSTD event rule on a hand-built run: lifts joined when at most gap_factor*a_ref apart, kept when the
// group spans at least length_factor*a_ref.
#include <gtest/gtest.h>

#include "tools/pstd/events.hpp"

using namespace tribex::pstd;

TEST(PstdEvents, DetectsOnlyLongQuasiStaticAdvances) {
  tribex::pstd::Run run;
  for (int i = 0; i <= 1000; ++i) {
    StepRecord r;
    r.position = i * 1e-9;
    r.contacts = 2;
    r.mean_half_width = 2e-9;  // a = 2 nm: gap 2 nm, minimum extent 20 nm
    if (i >= 800 && i <= 900) r.mean_half_width = 10e-9;  // a = 10 nm here: 30 nm of creep is not enough
    r.normal_force = 1e-3 - i * 1e-7;
    r.lifted = (i >= 100 && i <= 130) ||            // creep over 30 nm: an event
               i == 300 || i == 303 ||              // 3 nm apart: not joined
               (i >= 500 && i <= 510 && i % 2 == 0) ||  // joined but only 10 nm long
               (i >= 700 && i <= 760 && i % 3 == 0) ||  // 3 nm gaps: never joined
               (i >= 850 && i <= 880);                  // 30 nm < 10 a
    run.steps.push_back(r);
  }
  const auto events = detect_pstd(run, DetectionRule{});
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].first, 100u);
  EXPECT_EQ(events[0].last, 130u);
  EXPECT_EQ(events[0].lifts, 31u);
  EXPECT_NEAR(events[0].end - events[0].start, 30e-9, 1e-15);
  EXPECT_NEAR(events[0].half_width, 2e-9, 1e-20);
  EXPECT_NEAR(mean_half_width(run, 850, 880), 10e-9, 1e-20);
  // A looser gap joins the 3 nm spaced lifts into a 60 nm event.
  EXPECT_EQ(detect_pstd(run, DetectionRule{10.0, 1.5}).size(), 2u);
  // A shorter minimum extent (2 a) accepts the 10 nm group at 500-510 and the 30 nm group at 850-880.
  EXPECT_EQ(detect_pstd(run, DetectionRule{2.0, 1.0}).size(), 3u);
}
