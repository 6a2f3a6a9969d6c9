// Tests for PrimitiveTally: attempts and motions counted by kind, a transit's contacts counted
// against the primitive it approaches, the most frequent reason, and the summary of the kinds that
// never succeeded.
#include "ompl_mm/primitives/PrimitiveTally.h"

#include <gtest/gtest.h>

using namespace ompl_mm;

TEST(PrimitiveTally, CountsAttemptsMotionsAndReasonsByKind)
{
    PrimitiveTally tally;
    tally.attempt(PrimitiveKind::Pickup, true);
    tally.attempt(PrimitiveKind::Pickup, false);
    tally.attempt(PrimitiveKind::Pickup, false,
                  "a pose it needs is invalid: robot link 'hand' and object 'a'");
    // the transit to the approach pose is stopped: it counts against the pickup, and completes nothing
    tally.motion(PrimitiveKind::Pickup, PrimitiveKind::Transit, false, "robot link 'hand'", "object 'a'");
    tally.motion(PrimitiveKind::Pickup, PrimitiveKind::Pickup, false, "robot link 'hand'", "object 'a'");
    tally.motion(PrimitiveKind::Transit, PrimitiveKind::Transit, true);
    const PrimitiveTally::Record &pickup = tally.records().at("pickup");
    EXPECT_EQ(pickup.attempts, 3u);
    EXPECT_EQ(pickup.noMotion, 2u);
    EXPECT_EQ(pickup.motions, 2u);
    EXPECT_EQ(pickup.stopped, 2u);
    EXPECT_EQ(pickup.completed, 0u);
    EXPECT_TRUE(pickup.neverSucceeded());
    EXPECT_EQ(pickup.reasons.at("found no motion: inverse kinematics found no solution"), 1u);
    EXPECT_EQ(
        pickup.reasons.at("found no motion: a pose it needs is invalid: robot link 'hand' and object 'a'"),
        1u);
    EXPECT_EQ(
        pickup.mainReason(),
        std::make_pair(std::string("motion stopped by robot link 'hand' and object 'a'"), std::uint64_t{2}));
    const PrimitiveTally::Record &transit = tally.records().at("transit");
    EXPECT_EQ(transit.attempts, 0u) << "a motion is no attempt";
    EXPECT_EQ(transit.completed, 1u);
    EXPECT_FALSE(transit.neverSucceeded()) << "never tried: nothing to report";
    EXPECT_EQ(
        tally.failureSummary(),
        "pickup: 3 attempts, none succeeded; motion stopped by robot link 'hand' and object 'a' (2 of 4)\n");
}

TEST(PrimitiveTally, APrimitiveNoWalkReachedIsSaidSoAndOneThatCompletedIsNotListed)
{
    PrimitiveTally tally;
    tally.attempt(PrimitiveKind::Pickup, true);
    tally.attempt(PrimitiveKind::Transfer, true);
    tally.motion(PrimitiveKind::Pickup, PrimitiveKind::Pickup, true);
    EXPECT_EQ(tally.failureSummary(),
              "transfer: 1 attempts, none succeeded; no walk reached its motions (those before them were "
              "stopped)\n");
    tally.motion(PrimitiveKind::Transfer, PrimitiveKind::Transfer, false);  // stopped by grazing
    EXPECT_EQ(tally.records().at("transfer").mainReason().first,
              "motion stopped without a contact (grazing)");
    tally.motion(PrimitiveKind::Transfer, PrimitiveKind::Transfer, true);
    EXPECT_EQ(tally.failureSummary(), "");
    tally.clear();
    EXPECT_TRUE(tally.records().empty());
}
