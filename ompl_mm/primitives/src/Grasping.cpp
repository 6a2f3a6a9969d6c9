#include "ompl_mm/primitives/Grasping.h"

#include "ompl_mm/robot/IkSolver.h"

#include <ompl/util/Exception.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ompl_mm
{
    namespace
    {
        const KinematicChain &solvedChain(const ManipulationModel &model, const std::string &tool)
        {
            return tool.empty() ? model.toolPointChain() : model.toolChain(tool);
        }
    }  // namespace

    Grasping::Grasping(const ManipulationStateSpace *space, Settings settings,
                       const InverseKinematicsFactory &factory)
        : space_(space), settings_(std::move(settings)), work_(space->robotDimension())
    {
        if (!(settings_.approachDistance >= 0.0))
            throw ompl::Exception("the approach distance must be at least 0, got " +
                                  std::to_string(settings_.approachDistance));
        const ManipulationModel &model = *space->model();
        const KinematicChain &chain = solvedChain(model, settings_.tool);
        const Eigen::Isometry3d &base = model.scene().robot.basePose;
        ik_ = factory ? factory(chain, base) : std::make_unique<IkSolver>(chain, base);
    }

    Eigen::Isometry3d Grasping::solvedInTool(const double *q) const
    {
        const ManipulationModel &model = *space_->model();
        return model.toolFrame(q).inverse() * ik_->chain().toolPose(q, model.scene().robot.basePose);
    }

    bool Grasping::solve(const Eigen::Isometry3d &target, IkTask task, double *q, IkScope scope)
    {
        std::copy_n(q, work_.size(), work_.begin());
        if (!ik_->solve(target, task, work_.data(), rng_, scope))
            return false;
        std::copy(work_.begin(), work_.end(), q);
        return true;
    }

    bool Grasping::solveGrasp(unsigned int object, const ObjectPose &pose, double *q)
    {
        const Shape &shape = space_->model()->scene().objects[object].shape;
        Eigen::Isometry3d tool = Eigen::Isometry3d::Identity();
        tool.translate(pose.position + Eigen::Vector3d(0.0, 0.0, 0.5 * shape.height()));
        // the approach axis (tool z) down, tilted about the axis between the fingers (tool x)
        tool.rotate(Eigen::AngleAxisd(M_PI + settings_.tilt, Eigen::Vector3d::UnitX()));
        return solve(tool * solvedInTool(q), IkTask::Pose5DFreeYaw, q);
    }

    double Grasping::jointDistance(const double *a, const double *b) const
    {
        double squared = 0.0;
        for (std::size_t j = 0; j < work_.size(); ++j)
            squared += (a[j] - b[j]) * (a[j] - b[j]);
        return std::sqrt(squared);
    }

    bool Grasping::nearestSolution(const double *start, std::size_t compared, Solution &best,
                                   const std::function<bool(Solution &)> &solve)
    {
        Solution trial;
        unsigned int found = 0;
        double nearest = std::numeric_limits<double>::infinity();
        for (unsigned int attempt = 0; attempt < ATTEMPTS && found < CANDIDATES; ++attempt)
        {
            trial.resize(1);
            trial[0].assign(start, start + work_.size());
            if (attempt > 0)
                randomizeChain(trial[0].data());
            if (!solve(trial))
                continue;
            ++found;
            const double distance = jointDistance(start, trial[compared].data());
            if (distance < nearest)
            {
                nearest = distance;
                best.swap(trial);
            }
        }
        return found > 0;
    }

    void Grasping::randomizeChain(double *q)
    {
        const KinematicChain &chain = ik_->chain();
        for (unsigned int i = 0; i < chain.size(); ++i)
            q[chain.variable(i)] = rng_.uniformReal(chain.lower(i), chain.upper(i));
    }

    bool Grasping::solveShortMove(const Eigen::Vector3d &offset, const Eigen::Vector3d &local, double *q)
    {
        const ManipulationModel &model = *space_->model();
        const Eigen::Isometry3d target = Eigen::Translation3d(offset) *
                                         ik_->chain().toolPose(q, model.scene().robot.basePose) *
                                         Eigen::Translation3d(local);
        std::copy_n(q, work_.size(), work_.begin());
        // a restart far from q could not pass the short-move test below
        if (!ik_->solve(target, IkTask::Pose6D, work_.data(), rng_, IkScope::NearSeed))
            return false;
        for (std::size_t j = 0; j < work_.size(); ++j)
            if (std::abs(work_[j] - q[j]) > MAX_SHORT_MOVE)
                return false;
        std::copy(work_.begin(), work_.end(), q);
        return true;
    }

    bool Grasping::solveToolPose(const Eigen::Isometry3d &tool, double *q, IkScope scope)
    {
        return solve(tool * solvedInTool(q), IkTask::Pose6D, q, scope);
    }

    bool Grasping::solveCarry(const Eigen::Isometry3d &grasp, const ObjectPose &target, double *q)
    {
        return solve(target.frame() * grasp.inverse() * solvedInTool(q), IkTask::Pose5DFreeYaw, q);
    }

    ObjectPose Grasping::heldPose(unsigned int object, const Eigen::Isometry3d &toolFrame,
                                  const Eigen::Isometry3d &grasp, double yaw) const
    {
        const Eigen::Isometry3d frame = toolFrame * grasp;
        if (space_->model()->scene().objects[object].shape.turnsFreely())
            return {frame.translation(), yaw};
        const Eigen::Vector3d xAxis = frame.linear().col(0);
        return {frame.translation(), std::atan2(xAxis.y(), xAxis.x())};
    }

    bool Grasping::sameGrasp(const ManipulationStateSpace &space, const ompl::base::State *a,
                             const ompl::base::State *b, unsigned int object)
    {
        const ManipulationModel &model = *space.model();
        const Eigen::Isometry3d inA =
            model.toolFrame(space.robotValues(a)).inverse() * space.objectPose(a, object).frame();
        const Eigen::Isometry3d inB =
            model.toolFrame(space.robotValues(b)).inverse() * space.objectPose(b, object).frame();
        if ((inA.translation() - inB.translation()).norm() > GRASP_TOLERANCE)
            return false;
        if (model.scene().objects[object].shape.turnsFreely())
            return true;
        return Eigen::AngleAxisd(inA.linear().transpose() * inB.linear()).angle() <= GRASP_TOLERANCE;
    }
}  // namespace ompl_mm
