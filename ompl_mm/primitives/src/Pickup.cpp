#include "ompl_mm/primitives/Pickup.h"

#include <ompl/util/Console.h>
#include <ompl/util/Exception.h>

#include <cmath>
#include <vector>

namespace ompl_mm
{
    Pickup::Pickup(const ManipulationStateSpace *space, std::shared_ptr<Grasping> grasping, Settings settings)
        : Primitive(space, "pickup", PrimitiveKind::Pickup),
          grasping_(std::move(grasping)),
          settings_(settings)
    {
        if (!(settings_.liftHeight > 0.0))
            throw ompl::Exception("pickup lift_height must be positive, got " +
                                  std::to_string(settings_.liftHeight));
        if (!(settings_.minPlaneDistance >= 0.0))
            throw ompl::Exception("pickup min_plane_distance must be at least 0, got " +
                                  std::to_string(settings_.minPlaneDistance));
        if (!grasping_->settings().depth)
            OMPL_INFORM(
                "pickup: the hand begins %.4g m behind the tool point along its approach axis; grasps "
                "keep it %.4g m above an object's top (grasp_depth sets the depth instead)",
                grasping_->handReach(), Grasping::HAND_MARGIN);
    }

    bool Pickup::mustRise(const ompl::base::State *from, const ompl::base::State *to,
                          unsigned int object) const
    {
        const Eigen::Vector3d a = space_->objectPosition(from, object);
        const Eigen::Vector3d b = space_->objectPosition(to, object);
        return space_->restingSurface(to, object) < 0 || std::abs(a.z() - b.z()) > SAME_COORDINATE ||
               (a - b).head<2>().norm() > settings_.minPlaneDistance;
    }

    bool Pickup::othersStay(const ompl::base::State *a, const ompl::base::State *b, unsigned int object) const
    {
        for (unsigned int i = 0; i < space_->objectCount(); ++i)
            if (i != object && space_->objectMoves(a, b, i))
                return false;
        return true;
    }

    bool Pickup::isUseful(const ompl::base::State *from, const ompl::base::State *to) const
    {
        return allObjectsRest(from) && anyObject([&](unsigned int i) { return mustRise(from, to, i); });
    }

    bool Pickup::propagate(const ompl::base::State *from, const ompl::base::State *to,
                           Trajectory &trajectory) const
    {
        return propagate(from, to, trajectory, ompl::base::plannerNonTerminatingCondition());
    }

    bool Pickup::propagate(const ompl::base::State *from, const ompl::base::State *to, Trajectory &trajectory,
                           const ompl::base::PlannerTerminationCondition &ptc) const
    {
        const int object = nearestToTool(from, [&](unsigned int i) { return mustRise(from, to, i); });
        if (object < 0)
            return false;

        const ObjectPose pose = space_->objectPose(from, object);
        const double *start = space_->robotValues(from);
        const Eigen::Vector3d none = Eigen::Vector3d::Zero();
        // grasp, approach and lift, the approach nearest to where the robot is
        Grasping::Solution joints;
        const bool found = grasping_->nearestSolution(
            start, 1, joints,
            [&](Grasping::Solution &s)
            {
                if (!grasping_->solveGrasp(object, pose, s[0].data()) || ptc)
                    return false;
                s.resize(3, s[0]);
                return grasping_->solveShortMove(none, {0.0, 0.0, -grasping_->settings().approachDistance},
                                                 s[1].data()) &&
                       grasping_->solveShortMove({0.0, 0.0, settings_.liftHeight}, none, s[2].data());
            },
            ptc);
        if (!found)
            return false;
        const std::vector<double> &graspJoints = joints[0];
        const std::vector<double> &approachJoints = joints[1];
        const std::vector<double> &liftJoints = joints[2];

        const ManipulationModel &model = *space_->model();
        const Eigen::Isometry3d grasp = model.toolFrame(graspJoints.data()).inverse() * pose.frame();
        ompl::base::State *waypoint = space_->cloneState(from);
        double *q = space_->robotValues(waypoint);
        std::copy(approachJoints.begin(), approachJoints.end(), q);
        if (space_->robotMoves(from, waypoint))
            trajectory.append(waypoint, {PrimitiveKind::Transit, -1});
        std::copy(graspJoints.begin(), graspJoints.end(), q);
        trajectory.append(waypoint, {PrimitiveKind::Transit, -1});
        std::copy(liftJoints.begin(), liftJoints.end(), q);
        space_->setObjectPose(waypoint, object,
                              grasping_->heldPose(object, model.toolFrame(q), grasp, pose.yaw));
        trajectory.append(waypoint, {PrimitiveKind::Pickup, object});
        space_->freeState(waypoint);
        return true;
    }

    std::optional<SegmentLabel> Pickup::explain(const ompl::base::State *from,
                                                const ompl::base::State *to) const
    {
        if (!allObjectsRest(from))
            return std::nullopt;
        for (unsigned int i = 0; i < space_->objectCount(); ++i)
            if (space_->objectMoves(from, to, i))
            {
                if (space_->restingSurface(to, i) >= 0 || !othersStay(from, to, i) ||
                    !Grasping::sameGrasp(*space_, from, to, i))
                    return std::nullopt;
                return SegmentLabel{PrimitiveKind::Pickup, static_cast<int>(i)};
            }
        return std::nullopt;
    }

    bool Pickup::grasp(ompl::base::State *state, unsigned int object) const
    {
        return grasping_->solveGrasp(object, space_->objectPose(state, object), space_->robotValues(state));
    }
}  // namespace ompl_mm
