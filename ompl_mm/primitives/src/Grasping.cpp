#include "ompl_mm/primitives/Grasping.h"

#include "ompl_mm/collision/ConvexDistance.h"
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
        if (settings_.depth && !(*settings_.depth >= 0.0))
            throw ompl::Exception("the grasp depth must be at least 0, got " +
                                  std::to_string(*settings_.depth));
    }

    double Grasping::handReach() const
    {
        if (!handReach_)
            handReach_ = measureHandReach();
        return *handReach_;
    }

    double Grasping::measureHandReach() const
    {
        const ManipulationModel &model = *space_->model();
        const RobotModel &robot = model.robot();
        // the links rigid with the tool link: joined to it through fixed joints only
        const auto rigidWithTool = [&robot, tool = model.toolLink()](int link)
        {
            const auto fixedPath = [&robot](int from, int ancestor)
            {
                for (int l = from; l != ancestor; l = robot.links()[l].parent)
                    if (robot.joints()[robot.links()[l].joint].type != Joint::Type::Fixed)
                        return false;
                return true;
            };
            for (int top = tool;; top = robot.links()[top].parent)
            {
                if (robot.isInSubtree(link, top))
                    return fixedPath(link, top);
                if (robot.links()[top].parent < 0 ||
                    robot.joints()[robot.links()[top].joint].type != Joint::Type::Fixed)
                    return false;
            }
        };
        const std::vector<double> zero(robot.dof(), 0.0);
        std::vector<Eigen::Isometry3d> frames;
        robot.forwardKinematics(zero.data(), model.scene().robot.basePose, frames);
        const Eigen::Isometry3d tool = model.toolFrame(zero.data());
        std::vector<std::pair<ConvexShape, Eigen::Isometry3d>> hand;
        for (std::size_t l = 0; l < robot.links().size(); ++l)
            if (rigidWithTool(static_cast<int>(l)))
                for (const LinkShape &s : robot.links()[l].shapes)
                    try
                    {
                        if (auto convex = ConvexShape::of(s.shape, MeshCollision::ConvexHull))
                            hand.emplace_back(*convex, frames[l] * s.origin);
                    }
                    catch (const ompl::Exception &)
                    {
                        // a flat mesh (no hull) has no inside to run into
                    }
        // millimetre steps back along the approach axis until a point lies inside a shape
        const ConvexShape point = ConvexShape::sphere(1e-4);
        for (double back = 0.0; back <= MAX_HAND_REACH; back += 1e-3)
        {
            const Eigen::Isometry3d at = tool * Eigen::Translation3d(0.0, 0.0, -back);
            for (const auto &[shape, frame] : hand)
                if (convexDistance(point, at, shape, frame, 1e-6) <= 0.0)
                    return back;
        }
        return std::numeric_limits<double>::infinity();
    }

    double Grasping::graspHeight(unsigned int object) const
    {
        const Shape &shape = space_->model()->scene().objects[object].shape;
        const double height = shape.height();
        if (settings_.depth)
            return std::max(0.0, height - *settings_.depth);
        // the hand's first shape lies handReach back along the tilted approach axis: beside the
        // object (a side grasp) it takes nothing from the grasp; above it, it must clear the top
        const double reach = handReach();
        if (!std::isfinite(reach) ||
            reach * std::sin(std::abs(settings_.tilt)) >= shape.footprintRadius() + HAND_MARGIN)
            return 0.5 * height;
        return std::max(0.5 * height, height + HAND_MARGIN - reach * std::cos(settings_.tilt));
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
        Eigen::Isometry3d tool = Eigen::Isometry3d::Identity();
        tool.translate(pose.position + Eigen::Vector3d(0.0, 0.0, graspHeight(object)));
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
                                   const std::function<bool(Solution &)> &solve,
                                   const ompl::base::PlannerTerminationCondition &ptc)
    {
        Solution trial;
        unsigned int found = 0;
        double nearest = std::numeric_limits<double>::infinity();
        for (unsigned int attempt = 0; attempt < ATTEMPTS && found < CANDIDATES && !ptc; ++attempt)
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
