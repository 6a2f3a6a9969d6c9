#pragma once

#include "ompl_mm/primitives/PlanarBase.h"
#include "ompl_mm/primitives/Primitive.h"

#include <optional>
#include <vector>

namespace ompl_mm
{
    /** Push-Mobile (MOPL paper, section IV-C; cited at MOPL): a mobile base pushes one object in a
        straight line across its support surface. The base first transits to the object's standoff
        behind it, opposite the push direction, then base and object move together to the object's
        target; no inverse kinematics is needed because the base joints place the tool directly
        (PlanarBase). */
    class PushMobile : public Primitive
    {
    public:
        /** Margin between robot and object while pushing that the default standoff leaves, metres. */
        static constexpr double CLEARANCE = 0.01;

        /** A push primitive in space. standoff is the distance from an object's centre to the tool
            point while pushing, metres, for every object (MOBILE BLOCKED: 0.41 = robot radius +
            object radius + 1 cm); without it each object gets the robot's footprint radius (at the
            scene's start) plus the object's (a box's half diagonal) plus CLEARANCE.
            @pre space outlives the primitive.
            @throws ompl::Exception when the robot has no planar base, or a given standoff is not
            positive or is smaller than the robot's and some object's footprint radii together (the
            robot would overlap the object it pushes). */
        explicit PushMobile(const ManipulationStateSpace *space,
                            std::optional<double> standoff = std::nullopt);

        /** Distance from the object's centre to the tool point while pushing it, metres. */
        double standoff(unsigned int object) const { return standoffs_[object]; }

        /** Primitive's hook: useful when all objects rest in both states and some object moves in
            the plane at constant height. */
        bool isUseful(const ompl::base::State *from, const ompl::base::State *to) const override;
        /** Primitive's hook: pushes the sliding object nearest to the tool to its target x, y
            (keeping its height and yaw): a transit segment behind it (left out when the base is
            already there), then a push segment. False when no object slides. */
        bool propagate(const ompl::base::State *from, const ompl::base::State *to,
                       Trajectory &trajectory) const override;
        /** Primitive's hook: a push segment when every object rests at both ends, exactly one
            slides (x, y only), only the base joints move, and the tool is at the object's standoff
            behind it on the push line at both ends (within 1e-6 m), so that it stays there all
            along the interpolation. */
        std::optional<SegmentLabel> explain(const ompl::base::State *from,
                                            const ompl::base::State *to) const override;

    private:
        PlanarBase base_;
        std::vector<double> standoffs_;
    };
}  // namespace ompl_mm
