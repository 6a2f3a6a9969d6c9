#include "ompl_phys/knowledge/Violation.h"

namespace ompl_phys
{
    const char *violationName(Violation violation)
    {
        switch (violation)
        {
            case Violation::None:
                return "none";
            case Violation::TouchedFixedBody:
                return "touched_fixed_body";
            case Violation::TouchedOutsideRegion:
                return "touched_outside_push_region";
            case Violation::LeftPushAxis:
                return "left_push_axis";
            case Violation::OutsideRegion:
                return "outside_region";
            case Violation::TooFast:
                return "too_fast";
            case Violation::NotFinite:
                return "not_finite";
            case Violation::TippedOver:
                return "tipped_over";
            case Violation::SankIn:
                return "sank_in";
        }
        return "unknown";
    }
}  // namespace ompl_phys
