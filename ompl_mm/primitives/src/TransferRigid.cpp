#include "ompl_mm/primitives/TransferRigid.h"

#include <vector>

namespace ompl_mm
{
    TransferRigid::TransferRigid(const ManipulationStateSpace *space, std::shared_ptr<Grasping> grasping)
        : Primitive(space, "transfer_rigid", PrimitiveKind::Transfer), grasping_(std::move(grasping))
    {
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
        const int object = heldObject(from);
        if (object < 0)
            return false;
        const ManipulationModel &model = *space_->model();
        const ObjectPose held = space_->objectPose(from, object);
        const ObjectPose target = space_->objectPose(to, object);
        const Eigen::Isometry3d grasp =
            model.toolFrame(space_->robotValues(from)).inverse() * Grasping::objectFrame(held);
        const unsigned int n = space_->robotDimension();
        const double *start = space_->robotValues(from);
        std::vector<double> placeJoints(start, start + n);
        std::vector<double> retreatJoints;
        const bool places = space_->restingSurface(to, object) >= 0;
        if (places)
        {
            // a place the tool can retreat from along its axis, near the robot's joints
            Grasping::Solution joints;
            const bool found = grasping_->nearestSolution(
                start, 0, joints,
                [&](Grasping::Solution &s)
                {
                    if (!grasping_->solveCarry(grasp, {target.position, held.yaw}, s[0].data()))
                        return false;
                    s.resize(2, s[0]);
                    return grasping_->solveShortMove(Eigen::Vector3d::Zero(),
                                                     {0.0, 0.0, -grasping_->settings().approachDistance},
                                                     s[1].data());
                });
            if (!found)
                return false;
            placeJoints.swap(joints[0]);
            retreatJoints.swap(joints[1]);
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
        std::copy(placeJoints.begin(), placeJoints.end(), space_->robotValues(waypoint));
        space_->setObjectPose(waypoint, object, carried);
        trajectory.append(waypoint, {PrimitiveKind::Transfer, object});
        if (places)
        {
            std::copy(retreatJoints.begin(), retreatJoints.end(), space_->robotValues(waypoint));
            trajectory.append(waypoint, {PrimitiveKind::Transit, -1});
        }
        space_->freeState(waypoint);
        return true;
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
