/* Push-Mobile (MOPL paper, section IV-C): a mobile base pushes one object in a straight line
   across its support surface. The base first transits to `standoff` behind the object, opposite
   the push direction, then base and object move together to the object's target; no inverse
   kinematics is needed because the base joints place the tool directly. */
#pragma once

#include "ompl_mm/primitives/PlanarBase.h"
#include "ompl_mm/primitives/Primitive.h"

namespace ompl_mm
{
    class PushMobile : public Primitive
    {
    public:
        /** @param standoff distance from the object's centre to the tool point while pushing,
            metres (MOBILE BLOCKED: 0.41 = robot radius + object radius + 1 cm).
            @throws ompl::Exception when the robot has no planar base or standoff <= 0. */
        PushMobile(const ManipulationStateSpace *space, double standoff);

        double standoff() const { return standoff_; }

        /** Useful when all objects rest in both states and some object moves in the plane at
            constant height. */
        bool isUseful(const ompl::base::State *from, const ompl::base::State *to) const override;
        /** Pushes the moving object nearest to the tool to its target position. */
        bool propagate(const ompl::base::State *from, const ompl::base::State *to,
                       Trajectory &trajectory) const override;

    private:
        /** True when the object slides on its surface between a and b (moves in x, y only). */
        bool slides(const ompl::base::State *a, const ompl::base::State *b, unsigned int object) const;

        PlanarBase base_;
        double standoff_;
    };
}  // namespace ompl_mm
