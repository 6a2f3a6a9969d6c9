#pragma once

#include "ompl_mm/primitives/PlanarBase.h"
#include "ompl_mm/primitives/Primitive.h"

namespace ompl_mm
{
    /** Push-Mobile (MOPL paper, section IV-C; cited at MOPL): a mobile base pushes one object in a
        straight line across its support surface. The base first transits to `standoff` behind the
        object, opposite the push direction, then base and object move together to the object's
        target; no inverse kinematics is needed because the base joints place the tool directly
        (PlanarBase). */
    class PushMobile : public Primitive
    {
    public:
        /** A push primitive in space; standoff is the distance from the object's centre to the tool
            point while pushing, metres (MOBILE BLOCKED: 0.41 = robot radius + object radius + 1 cm).
            @pre space outlives the primitive.
            @throws ompl::Exception when the robot has no planar base or standoff <= 0. */
        PushMobile(const ManipulationStateSpace *space, double standoff);

        /** Distance from the object's centre to the tool point while pushing, metres. */
        double standoff() const { return standoff_; }

        /** Primitive's hook: useful when all objects rest in both states and some object moves in
            the plane at constant height. */
        bool isUseful(const ompl::base::State *from, const ompl::base::State *to) const override;
        /** Primitive's hook: pushes the sliding object nearest to the tool to its target x, y
            (keeping its height and yaw): a transit segment behind it (left out when the base is
            already there), then a push segment. False when no object slides. */
        bool propagate(const ompl::base::State *from, const ompl::base::State *to,
                       Trajectory &trajectory) const override;

    private:
        /** True when the object slides on its surface between a and b (moves in x, y only). */
        bool slides(const ompl::base::State *a, const ompl::base::State *b, unsigned int object) const;

        PlanarBase base_;
        double standoff_;
    };
}  // namespace ompl_mm
