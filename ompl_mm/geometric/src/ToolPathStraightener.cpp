#include "ompl_mm/geometric/ToolPathStraightener.h"

#include <ompl/util/Exception.h>

namespace ompl_mm
{
    ToolPathStraightener::ToolPathStraightener(const ompl::base::SpaceInformationPtr &si)
        : si_(si),
          space_(si->getStateSpace()->as<ManipulationStateSpace>()),
          ik_(space_->model()->toolPointChain(), space_->model()->scene().robot.basePose)
    {
        // its waypoints are labelled and checked as the manipulation validator sees motions
        if (!std::dynamic_pointer_cast<const ManipulationMotionValidator>(si->getMotionValidator()))
            throw ompl::Exception(
                "ToolPathStraightener needs a ManipulationMotionValidator on the space information "
                "(ManipulationSetup installs one)");
    }

    bool ToolPathStraightener::halfway(const ompl::base::State *a, const ompl::base::State *b,
                                       const SegmentLabel &label, ompl::base::State *mid)
    {
        const ManipulationModel &model = *space_->model();
        const Eigen::Isometry3d from = model.toolFrame(space_->robotValues(a));
        const Eigen::Isometry3d to = model.toolFrame(space_->robotValues(b));
        const double arc = space_->toolTravel(a, b);
        if (arc - (to.translation() - from.translation()).norm() <= MIN_EXCESS)
            return false;
        for (const double raise : RAISES)
        {
            // the joint-space midpoint's tool moved onto the chord, turned as it is there (halfway
            // between the ends' rotations would twist the arm), solved from that midpoint alone so
            // that the arm keeps its shape
            space_->interpolate(a, b, 0.5, mid);
            const Eigen::Isometry3d target =
                Eigen::Translation3d(0.5 * (from.translation() + to.translation()) +
                                     raise * Eigen::Vector3d::UnitZ()) *
                Eigen::Quaterniond(model.toolFrame(space_->robotValues(mid)).linear());
            if (!ik_.solve(target, IkTask::Pose6D, space_->robotValues(mid), rng_, IkScope::NearSeed))
                continue;
            if (label.kind == PrimitiveKind::Transfer)
            {
                // the carried object keeps its grasp
                const auto object = static_cast<unsigned int>(label.object);
                space_->setObjectPose(mid, object,
                                      ManipulationStateSpace::carriedPose(
                                          space_->objectPose(a, object), space_->objectPose(b, object), from,
                                          to, model.toolFrame(space_->robotValues(mid)), 0.5,
                                          model.scene().objects[object].shape.turnsFreely()));
            }
            if (space_->toolTravel(a, mid) + space_->toolTravel(mid, b) >= arc)
                return false;
            if (si_->checkMotion(a, mid) && si_->checkMotion(mid, b))
                return true;
        }
        return false;
    }

    unsigned int ToolPathStraightener::straighten(ManipulationPath &path,
                                                  const ompl::base::PlannerTerminationCondition &ptc)
    {
        unsigned int added = 0;
        ompl::base::State *mid = space_->allocState();
        for (unsigned int level = 0; level < LEVELS && !ptc; ++level)
        {
            bool changed = false;
            // from the end, so that the segments still to visit keep their indices
            for (std::size_t k = path.getStateCount() - 1; k-- > 0 && !ptc;)
            {
                const SegmentLabel label = path.label(k);
                if ((label.kind != PrimitiveKind::Transit && label.kind != PrimitiveKind::Transfer) ||
                    !halfway(path.getState(k), path.getState(k + 1), label, mid))
                    continue;
                Trajectory straighter(space_);
                straighter.reset(path.getState(k));
                straighter.append(mid, label);
                straighter.append(path.getState(k + 1), label);
                path.replace(k, k + 1, straighter);
                ++added;
                changed = true;
            }
            if (!changed)
                break;
        }
        space_->freeState(mid);
        return added;
    }
}  // namespace ompl_mm
