#pragma once

#include "ompl_phys/scene/PhysicsScene.h"

namespace ompl_phys
{
    /** Distance (m) from point to the footprint of shape standing upright at (position, yaw); 0
        inside it. The footprint is the outline of the body seen from above, for reasoning about
        the floor plan: boxes and prisms give their exact rectangle or triangle, cylinders and
        spheres their circle. position, yaw (radians) and point are on the floor, world frame. */
    double footprintDistance(const PhysicsShape &shape, const Eigen::Vector2d &position, double yaw,
                             const Eigen::Vector2d &point);

    /** The cross product of two vectors on the floor (the z of their 3-D cross product): positive
        when b turns counter-clockwise from a. */
    double cross(const Eigen::Vector2d &a, const Eigen::Vector2d &b);

    /** Rotation about the vertical of an orientation (its x axis projected on the floor), radians in
        [-pi, pi]. */
    double yawOf(const Eigen::Quaterniond &orientation);
}  // namespace ompl_phys
