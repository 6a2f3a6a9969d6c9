#include "ompl_mm/primitives/TransferRigid.h"

#include <ompl/util/Exception.h>

#include <cmath>
#include <string>
#include <vector>

namespace ompl_mm
{
    TransferRigid::TransferRigid(const ManipulationStateSpace *space, std::shared_ptr<Grasping> grasping,
                                 double placeHeight)
        : Primitive(space, "transfer_rigid", PrimitiveKind::Transfer),
          grasping_(std::move(grasping)),
          placeHeight_(placeHeight)
    {
        if (!(placeHeight_ >= 0.0) || !std::isfinite(placeHeight_))
            throw ompl::Exception("transfer_rigid place_height must be at least 0, got " +
                                  std::to_string(placeHeight_));
    }

    int TransferRigid::heldObject(const ompl::base::State *state) const
    {
        int held = -1;
        for (unsigned int i = 0; i < space_->objectCount(); ++i)
            if (space_->restingSurface(state, i) < 0)
            {
                if (held >= 0)
                    return -1;
                held = static_cast<int>(i);
            }
        return held;
    }

    bool TransferRigid::isUseful(const ompl::base::State *from, const ompl::base::State *) const
    {
        return heldObject(from) >= 0;
    }

    bool TransferRigid::propagate(const ompl::base::State *from, const ompl::base::State *to,
                                  Trajectory &trajectory) const
    {
        return propagate(from, to, trajectory, ompl::base::plannerNonTerminatingCondition());
    }

    bool TransferRigid::propagate(const ompl::base::State *from, const ompl::base::State *to,
                                  Trajectory &trajectory,
                                  const ompl::base::PlannerTerminationCondition &ptc) const
    {
        const int object = heldObject(from);
        if (object < 0)
            return false;
        const ManipulationModel &model = *space_->model();
        const ObjectPose held = space_->objectPose(from, object);
        const ObjectPose target = space_->objectPose(to, object);
        const Eigen::Isometry3d grasp = model.toolFrame(space_->robotValues(from)).inverse() * held.frame();
        const unsigned int n = space_->robotDimension();
        const double *start = space_->robotValues(from);
        std::vector<double> placeJoints;
        Grasping::Solution joints;
        const bool places = space_->restingSurface(to, object) >= 0;
        if (places)
        {
            // a place the tool can retreat from along its axis, near the robot's joints
            if (!grasping_->nearestSolution(
                    start, 0, joints,
                    [&](Grasping::Solution &s) {
                        return solvePlace(grasp, {target.position, held.yaw}, s, ptc);
                    },
                    ptc))
                return false;
            placeJoints = joints[0];
        }
        else
            placeJoints.assign(space_->robotValues(to), space_->robotValues(to) + n);
        ObjectPose carried =
            grasping_->heldPose(object, model.toolFrame(placeJoints.data()), grasp, target.yaw);
        // where the grasp brings it within the IK's tolerance, it is the target (and then rests
        // exactly on its surface)
        if ((carried.position - target.position).norm() <= Grasping::GRASP_TOLERANCE)
            carried.position = target.position;
        else if (places)
            return false;  // a place that misses is no place
        ompl::base::State *waypoint = space_->cloneState(from);
        if (joints.size() > 2)
        {
            const std::vector<double> &above = joints[2];
            std::copy(above.begin(), above.end(), space_->robotValues(waypoint));
            space_->setObjectPose(
                waypoint, object,
                grasping_->heldPose(object, model.toolFrame(above.data()), grasp, target.yaw));
            trajectory.append(waypoint, {PrimitiveKind::Transfer, object});
        }
        std::copy(placeJoints.begin(), placeJoints.end(), space_->robotValues(waypoint));
        space_->setObjectPose(waypoint, object, carried);
        trajectory.append(waypoint, {PrimitiveKind::Transfer, object});
        if (places)
        {
            std::copy(joints[1].begin(), joints[1].end(), space_->robotValues(waypoint));
            trajectory.append(waypoint, {PrimitiveKind::Transit, -1});
        }
        space_->freeState(waypoint);
        return true;
    }

    bool TransferRigid::solvePlace(const Eigen::Isometry3d &grasp, const ObjectPose &place,
                                   Grasping::Solution &solution,
                                   const ompl::base::PlannerTerminationCondition &ptc) const
    {
        const Eigen::Vector3d none = Eigen::Vector3d::Zero();
        std::vector<double> above;
        if (placeHeight_ > 0.0)
        {
            // above the place first, then straight down to it
            const ObjectPose abovePlace{place.position + Eigen::Vector3d(0.0, 0.0, placeHeight_), place.yaw};
            if (!grasping_->solveCarry(grasp, abovePlace, solution[0].data()))
                return false;
            above = solution[0];
            if (!grasping_->solveShortMove({0.0, 0.0, -placeHeight_}, none, solution[0].data()))
                return false;
        }
        else if (!grasping_->solveCarry(grasp, place, solution[0].data()))
            return false;
        if (ptc)
            return false;  // out of time: the short moves would only cost more
        solution.resize(2, solution[0]);
        if (!above.empty())
            solution.push_back(std::move(above));
        return grasping_->solveShortMove(none, {0.0, 0.0, -grasping_->settings().approachDistance},
                                         solution[1].data());
    }

    std::optional<SegmentLabel> TransferRigid::explain(const ompl::base::State *from,
                                                       const ompl::base::State *to) const
    {
        const int object = heldObject(from);
        if (object < 0)
            return std::nullopt;
        for (unsigned int i = 0; i < space_->objectCount(); ++i)
            if (static_cast<int>(i) != object && space_->objectMoves(from, to, i))
                return std::nullopt;
        if (!Grasping::sameGrasp(*space_, from, to, object))
            return std::nullopt;
        return SegmentLabel{PrimitiveKind::Transfer, object};
    }
}  // namespace ompl_mm
