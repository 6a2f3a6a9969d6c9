#pragma once

#include "ompl_mm/model/ManipulationModel.h"

#include <Eigen/Core>

namespace ompl_mm
{
    /** A mobile base that moves along world x and y: two prismatic joints on the way from the
        robot's root to its tool link whose axes are the world x and y axes at the zero pose. Mobile
        primitives place the tool at a point of the floor plan by setting these two joints, with no
        inverse kinematics. Keeps a reference to its model. */
    class PlanarBase
    {
    public:
        /** Finds the base joints of model's robot (none found: exists() is false).
            @pre model outlives this object. */
        explicit PlanarBase(const ManipulationModel &model);

        /** True when the robot has both base joints. */
        bool exists() const { return jointX_ >= 0 && jointY_ >= 0; }

        /** Sets the base joints of q (one value per moving joint) so that the tool point is at world
            (x, y), metres; the other joints keep their values. Exact for any q. @pre exists(). */
        void placeTool(const Eigen::Vector2d &toolXY, double *q) const;
        /** True when qa and qb (one value per moving joint) differ in the base joints only, so
            that the tool moves in a straight horizontal line as they interpolate. @pre exists(). */
        bool onlyBaseMoves(const double *qa, const double *qb) const;
        /** Radius about the tool point's vertical axis of a vertical cylinder that holds the
            robot's collision shapes at joint values q, metres (each shape by its bounding sphere). */
        double footprintRadius(const double *q) const;

    private:
        const ManipulationModel &model_;
        int jointX_{-1};
        int jointY_{-1};
    };
}  // namespace ompl_mm
