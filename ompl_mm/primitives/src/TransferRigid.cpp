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
        ompl::base::State *waypoint = space_->cloneState(from);
        double *q = space_->robotValues(waypoint);
        const bool places = space_->restingSurface(to, object) >= 0;
        if (places && !grasping_->solveCarry(held, target.position, q))
        {
            space_->freeState(waypoint);
            return false;
        }
        if (!places)
            space_->copyRobot(waypoint, to);
        ObjectPose carried = grasping_->heldPose(object, model.toolFrame(q), grasp, target.yaw);
        // where the grasp brings it within the IK's tolerance, it is the target (and then rests
        // exactly on its surface); a place that misses is no place
        const bool atTarget = (carried.position - target.position).norm() <= Grasping::GRASP_TOLERANCE;
        if (places && !atTarget)
        {
            space_->freeState(waypoint);
            return false;
        }
        if (atTarget)
            carried.position = target.position;
        space_->setObjectPose(waypoint, object, carried);
        trajectory.append(waypoint, {PrimitiveKind::Transfer, object});
        if (places)
        {
            std::vector<double> retreat(q, q + space_->robotDimension());
            if (grasping_->solveShortMove(Eigen::Vector3d::Zero(),
                                          {0.0, 0.0, -grasping_->settings().approachDistance},
                                          retreat.data()))
            {
                std::copy(retreat.begin(), retreat.end(), q);
                trajectory.append(waypoint, {PrimitiveKind::Transit, -1});
            }
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
