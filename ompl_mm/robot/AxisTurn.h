#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>

namespace ompl_mm
{
    /** 0, 1 or 2 when the unit axis is +-x, +-y or +-z (most URDF joints'); -1 for any other axis. */
    inline int alignedAxisOf(const Eigen::Vector3d &axis)
    {
        for (int k = 0; k < 3; ++k)
            if (std::abs(axis[k]) == 1.0)
                return k;
        return -1;
    }

    /** rotation = rotation * (turn by angle about the unit axis), for a joint's motion in forward
        kinematics. A turn about +-e_k (aligned = alignedAxisOf(axis) >= 0) mixes the two other columns
        of the rotation only: a sixth of the work of a general rotation product. */
    template <typename Rotation>
    void turnAbout(Rotation &&rotation, const Eigen::Vector3d &axis, int aligned, double angle)
    {
        if (aligned < 0)
        {
            rotation = rotation * Eigen::AngleAxisd(angle, axis).toRotationMatrix();
            return;
        }
        const int a = (aligned + 1) % 3;
        const int b = (aligned + 2) % 3;
        const double signedAngle = axis[aligned] > 0.0 ? angle : -angle;
        const double c = std::cos(signedAngle);
        const double s = std::sin(signedAngle);
        const Eigen::Vector3d columnA = rotation.col(a);
        rotation.col(a) = c * columnA + s * rotation.col(b);
        rotation.col(b) = c * rotation.col(b) - s * columnA;
    }
}  // namespace ompl_mm
