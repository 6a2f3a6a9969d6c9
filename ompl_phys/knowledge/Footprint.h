/* The outline of a body seen from above, for reasoning about the floor plan: how far a point is
   from a body standing upright at a pose. Boxes and prisms give their exact rectangle or
   triangle, cylinders and spheres their circle. */
#pragma once

#include "ompl_phys/scene/PhysicsScene.h"

namespace ompl_phys
{
    /** Distance (m) from point to the footprint of shape at (position, yaw); 0 inside it. */
    double footprintDistance(const PhysicsShape &shape, const Eigen::Vector2d &position, double yaw,
                             const Eigen::Vector2d &point);

    /** Rotation about the vertical of an orientation (its x axis projected on the floor), radians. */
    double yawOf(const Eigen::Quaterniond &orientation);
}  // namespace ompl_phys
