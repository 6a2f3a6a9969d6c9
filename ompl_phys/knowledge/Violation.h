#pragma once

#include <cstdint>

namespace ompl_phys
{
    /** Why a simulated state is not acceptable: a broken manipulation-knowledge rule or a planning
        limit. Propagation stops at the first sub-step with a violation. */
    enum class Violation : std::uint8_t
    {
        None = 0,              ///< no rule or limit broken
        TouchedFixedBody,      ///< the robot touched a fixed body
        TouchedOutsideRegion,  ///< the robot touched a constraint-oriented body outside its push region
        LeftPushAxis,          ///< a constraint-oriented body moved off its axis or turned
        OutsideRegion,         ///< the robot or a body left its region
        TooFast,               ///< a speed limit was exceeded
        NotFinite,             ///< the simulation produced NaN or infinity
        TippedOver,            ///< a movable body leaned over (ManipulationKnowledge::TIP_TOLERANCE)
        SankIn,  ///< bodies sank into each other or the floor (ManipulationKnowledge::SINK_TOLERANCE)
    };

    /** The number of Violation values, None included: the size of arrays indexed by violation. */
    constexpr int VIOLATION_KINDS = 9;

    /** A short snake_case name, for logs and result files ("touched_fixed_body"). */
    const char *violationName(Violation violation);
}  // namespace ompl_phys
