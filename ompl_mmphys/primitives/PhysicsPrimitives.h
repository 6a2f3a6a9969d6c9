/* The primitive factory that knows model="physics" on push primitives. */
#pragma once

#include "ompl_mm/primitives/PrimitiveFactory.h"

namespace ompl_mmphys
{
    /** ompl_mm's primitive factory whose push types (push_mobile, push_interior, push_exterior,
        push_frontal) also take model="physics": a PhysicsPush around the kinematic push the other
        parameters describe, corrected while the object is farther than `push_precision` metres
        from its target (default 0.005) at most `push_corrections` times (default 3, at most 20).
        model="kinematic", the default, builds ompl_mm's push unchanged. */
    ompl_mm::PrimitiveFactory physicsPrimitiveFactory();
}  // namespace ompl_mmphys
