#include "ompl_mmphys/primitives/PhysicsPush.h"

#include "ompl_mm/base/ManipulationStateSpace.h"

#include <ompl/util/Exception.h>
#include <ompl/util/Time.h>

#include <algorithm>
#include <cmath>

namespace ompl_mmphys
{
    namespace
    {
        /** Tool travel between the states checked along a kinematic push before it is simulated,
            metres: as fine as the planner's default connect step. */
        constexpr double CHECK_SPACING = 0.05;

        /** States a piece of a made segment lies within this of the interpolation, per value: the
            walk and the simplifier interpolate with the space's own interpolate(). */
        constexpr double ON_SEGMENT = 1e-9;

        /** Records one object through a push's execution. */
        class PushObserver : public ExecutionObserver
        {
        public:
            PushObserver(const PlanWorld &world, unsigned int object, std::size_t waypoints)
                : poses(waypoints), world_(world), object_(object)
            {
            }
            void reached(std::size_t waypoint) override { poses[waypoint] = world_.objectPose(object_); }
            void stepped(const double *) override { maxTilt = std::max(maxTilt, world_.objectTilt(object_)); }

            std::vector<ompl_mm::ObjectPose> poses;  ///< per waypoint
            double maxTilt{0.0};                     ///< radians from upright, the most of any step

        private:
            const PlanWorld &world_;
            unsigned int object_;
        };

        void requirePositiveSetting(double value, const char *name)
        {
            if (!(value > 0.0) || !std::isfinite(value))
                throw ompl::Exception("PhysicsPush",
                                      std::string(name) + " must be positive, got " + std::to_string(value));
        }
    }  // namespace

    PhysicsPush::PhysicsPush(const ompl_mm::ManipulationStateSpace *space, ompl_mm::PrimitivePtr kinematic,
                             std::function<double(unsigned int)> standoff, const Settings &settings)
        : Primitive(space, kinematic->name(), kinematic->kind()),
          kinematic_(std::move(kinematic)),
          standoff_(std::move(standoff)),
          settings_(settings),
          made_(space->objectCount())
    {
        requirePositiveSetting(settings.precision, "precision");
        requirePositiveSetting(settings.sampleSpacing, "sampleSpacing");
        requirePositiveSetting(settings.retreat, "retreat");
        requirePositiveSetting(settings.tilt, "tilt");
        requirePositiveSetting(settings.slip, "slip");
        requirePositiveSetting(settings.rock, "rock");
        checkSettings(settings.simulation, "PhysicsPush");
    }

    bool PhysicsPush::isUseful(const ompl::base::State *from, const ompl::base::State *to) const
    {
        return kinematic_->isUseful(from, to);
    }

    void PhysicsPush::setStateValidityChecker(ompl::base::StateValidityCheckerPtr checker)
    {
        kinematic_->setStateValidityChecker(checker);
        Primitive::setStateValidityChecker(std::move(checker));
    }

    bool PhysicsPush::propagate(const ompl::base::State *from, const ompl::base::State *to,
                                ompl_mm::Trajectory &trajectory) const
    {
        return propagate(from, to, trajectory, ompl::base::plannerNonTerminatingCondition());
    }

    bool PhysicsPush::propagate(const ompl::base::State *, const ompl::base::State *to,
                                ompl_mm::Trajectory &trajectory,
                                const ompl::base::PlannerTerminationCondition &ptc) const
    {  // from is trajectory.back()
        // pushes of at most maxPushDistance, each aimed past its goal by as much as the last one
        // fell short of its aim along its line: a pusher stops its object short by the clearance
        // that its kinematic standoff leaves, and such a shortfall repeats while sideways drift,
        // which the next push corrects, does not
        const int object = nearestSlidingObject(trajectory.back(), to);
        if (object < 0)
            return false;
        const auto k = static_cast<unsigned int>(object);
        const Eigen::Vector2d target = space_->objectPosition(to, k).head<2>();
        const double distance = (target - space_->objectPosition(trajectory.back(), k).head<2>()).norm();
        const unsigned int pushes =
            static_cast<unsigned int>(std::ceil(distance / settings_.maxPushDistance)) +
            settings_.corrections;
        ompl::base::State *aim = space_->cloneState(to);
        double shortfall = 0.0;
        bool pushed = false;
        for (unsigned int attempt = 0; attempt < pushes && !ptc; ++attempt)
        {
            const Eigen::Vector2d from = space_->objectPosition(trajectory.back(), k).head<2>();
            const Eigen::Vector2d way = target - from;
            if (way.norm() <= settings_.precision)
                break;
            const Eigen::Vector2d goal =
                from + std::min(way.norm(), settings_.maxPushDistance) * way.normalized();
            ompl_mm::ObjectPose aimed = space_->objectPose(to, k);
            aimed.position.head<2>() = goal + shortfall * way.normalized();
            space_->setObjectPose(aim, k, aimed);
            const Outcome outcome = pushOnce(trajectory.back(), aim, trajectory, ptc);
            pushed = pushed || outcome != Outcome::Failed;
            if (outcome != Outcome::Pushed && outcome != Outcome::Cut)
                break;
            const Eigen::Vector2d reached = space_->objectPosition(trajectory.back(), k).head<2>();
            if (outcome == Outcome::Pushed)  // a cut push says nothing of the clearance
                shortfall = std::max(0.0, (aimed.position.head<2>() - reached).dot(way.normalized()));
        }
        space_->freeState(aim);
        return pushed;
    }

    PhysicsPush::Outcome PhysicsPush::pushOnce(const ompl::base::State *from, const ompl::base::State *to,
                                               ompl_mm::Trajectory &trajectory,
                                               const ompl::base::PlannerTerminationCondition &ptc) const
    {
        ompl_mm::Trajectory kinematicMotion(space_);
        kinematicMotion.reset(from);
        if (!kinematic_->propagate(from, to, kinematicMotion, ptc))
        {
            rejectBecause(kinematic_->takeRejection());
            return Outcome::Failed;
        }
        const ompl_mm::Trajectory motion = reachablePart(kinematicMotion);
        std::size_t first = 0;  // the first push segment
        while (first + 1 < motion.size() && motion.label(first).kind != ompl_mm::PrimitiveKind::Push)
            ++first;
        if (first + 1 >= motion.size())
        {  // the way to the push start is blocked: only the way there is worth walking
            for (std::size_t i = 1; i < motion.size(); ++i)
                trajectory.append(motion.state(i), motion.label(i - 1));
            return motion.size() > 1 ? Outcome::Approached : Outcome::Failed;
        }
        const ompl_mm::SegmentLabel push = motion.label(first);
        const auto object = static_cast<unsigned int>(push.object);
        std::size_t last = first;  // the waypoint where pushing ends
        while (last + 1 < motion.size() && motion.label(last) == push)
            ++last;

        // the robot's waypoints from the push's start: pushes split every sampleSpacing of tool
        // travel, then the kinematic push's retreat or one of our own, all labelled as the push
        std::vector<ompl::base::State *> waypoints{space_->cloneState(motion.state(first))};
        std::size_t pushEnd = 0;  // the waypoint where pushing ends
        for (std::size_t i = first; i < motion.size() - 1; ++i)
        {
            const double travel = space_->toolTravel(motion.state(i), motion.state(i + 1));
            const auto pieces =
                i < last ? std::max<std::size_t>(
                               1, static_cast<std::size_t>(std::ceil(travel / settings_.sampleSpacing)))
                         : 1;
            for (std::size_t k = 1; k <= pieces; ++k)
            {
                ompl::base::State *state = space_->allocState();
                space_->interpolate(motion.state(i), motion.state(i + 1),
                                    static_cast<double>(k) / static_cast<double>(pieces), state);
                waypoints.push_back(state);
            }
            if (i + 1 == last)
                pushEnd = waypoints.size() - 1;
        }
        if (last + 1 == motion.size())
            waypoints.push_back(retreatFrom(motion.state(last - 1), motion.state(last)));

        // simulate; while the object slides around the pusher, end the push before it does
        SimulatedPush simulated = simulate(waypoints, from, push);
        bool cut = false;
        for (std::size_t slip = slipWaypoint(waypoints, simulated.poses, pushEnd); slip > 0;
             slip = slipWaypoint(waypoints, simulated.poses, pushEnd))
        {
            if (slip == 1)
            {
                for (ompl::base::State *state : waypoints)
                    space_->freeState(state);
                rejectBecause("object '" + space_->model()->scene().objects[object].name +
                              "' slides off the pusher");
                return Outcome::Failed;
            }
            pushEnd = slip - 1;
            for (std::size_t i = pushEnd + 1; i < waypoints.size(); ++i)
                space_->freeState(waypoints[i]);
            waypoints.resize(pushEnd + 1);
            waypoints.push_back(retreatFrom(waypoints[pushEnd - 1], waypoints[pushEnd]));
            simulated = simulate(waypoints, from, push);
            cut = true;
        }

        const ompl_mm::Scene &scene = space_->model()->scene();
        const std::string &name = scene.objects[object].name;
        const int surface = surfaceUnder(scene, simulated.poses.back().position);
        const double tilt = simulated.tilt;
        bool made = false;
        if (tilt > settings_.tilt)
            rejectBecause("the push tips object '" + name + "' over (more than " +
                          std::to_string(std::lround(settings_.tilt * 180.0 / M_PI)) + " degrees)");
        else if (simulated.maxTilt > settings_.rock)
            rejectBecause("the push rocks object '" + name + "' (more than " +
                          std::to_string(std::lround(settings_.rock * 180.0 / M_PI)) +
                          " degrees from upright)");
        else if (surface < 0)
            rejectBecause("the push moves object '" + name + "' off its surface");
        else
        {
            made = true;
            for (std::size_t i = 1; i <= first; ++i)
                trajectory.append(motion.state(i), motion.label(i - 1));
            const double height = scene.surfaces[static_cast<std::size_t>(surface)].height;
            for (std::size_t i = 1; i < waypoints.size(); ++i)
            {
                ompl_mm::ObjectPose pose = simulated.poses[i];
                pose.position.z() = height;  // resting, as the planner's states hold objects
                space_->setObjectPose(waypoints[i], object, pose);
                // the robot touches the object until it has backed away at the end, where the
                // object stays exactly where physics left it: the next motion starts from there
                const bool end = i + 1 == waypoints.size();
                if (!end)
                    keepStandoff(waypoints[i], object);
                appendMade(trajectory, waypoints[i], push, end);
            }
        }
        for (ompl::base::State *state : waypoints)
            space_->freeState(state);
        if (!made)
            return Outcome::Failed;
        return cut ? Outcome::Cut : Outcome::Pushed;
    }

    PhysicsPush::SimulatedPush PhysicsPush::simulate(const std::vector<ompl::base::State *> &waypoints,
                                                     const ompl::base::State *from,
                                                     ompl_mm::SegmentLabel push) const
    {
        // the robot from the push's start, only the pushed object in the world
        const auto object = static_cast<unsigned int>(push.object);
        std::vector<const double *> robot;
        for (const ompl::base::State *state : waypoints)
            robot.push_back(space_->robotValues(state));
        const std::vector<ompl_mm::SegmentLabel> labels(waypoints.size() - 1, push);
        std::vector<bool> present(space_->objectCount(), false);
        present[object] = true;
        const ompl::time::point started = ompl::time::now();
        PlanWorld world(space_->model(), robot.front(), objectPoses(*space_, from),
                        settings_.simulation.world, present);
        MotionExecution execution(world, settings_.simulation);
        PushObserver observer(world, object, waypoints.size());
        execution.execute(robot, labels, observer);
        simulationTime_ += ompl::time::seconds(ompl::time::now() - started);
        ++simulations_;
        return {std::move(observer.poses), world.objectTilt(object), observer.maxTilt};
    }

    std::size_t PhysicsPush::slipWaypoint(const std::vector<ompl::base::State *> &waypoints,
                                          const std::vector<ompl_mm::ObjectPose> &poses,
                                          std::size_t pushEnd) const
    {
        const double limit = std::cos(settings_.slip);
        for (std::size_t i = 1; i <= pushEnd; ++i)
        {
            const Eigen::Vector2d tool = space_->toolPosition(waypoints[i]).head<2>();
            const Eigen::Vector2d heading = tool - space_->toolPosition(waypoints[i - 1]).head<2>();
            const Eigen::Vector2d toObject = poses[i].position.head<2>() - tool;
            if (heading.norm() > 0.0 && toObject.norm() > 0.0 &&
                heading.dot(toObject) < limit * heading.norm() * toObject.norm())
                return i;
        }
        return 0;
    }

    ompl::base::State *PhysicsPush::retreatFrom(const ompl::base::State *before,
                                                const ompl::base::State *end) const
    {
        const double travel = space_->toolTravel(before, end);
        ompl::base::State *back = space_->cloneState(end);
        space_->interpolate(end, before, std::min(1.0, settings_.retreat / std::max(travel, 1e-9)), back);
        return back;
    }

    ompl_mm::Trajectory PhysicsPush::reachablePart(const ompl_mm::Trajectory &motion) const
    {
        ompl_mm::Trajectory reachable(space_);
        reachable.reset(motion.state(0));
        ompl::base::State *state = space_->allocState();
        for (std::size_t i = 0; i + 1 < motion.size(); ++i)
        {
            const ompl::base::State *a = motion.state(i);
            const ompl::base::State *b = motion.state(i + 1);
            const auto samples = std::max<std::size_t>(
                1, static_cast<std::size_t>(std::ceil(space_->toolTravel(a, b) / CHECK_SPACING)));
            std::size_t valid = 0;
            for (; valid < samples; ++valid)
            {
                space_->interpolate(a, b, static_cast<double>(valid + 1) / static_cast<double>(samples),
                                    state);
                if (!acceptable(state))
                    break;
            }
            if (valid > 0)
            {
                space_->interpolate(a, b, static_cast<double>(valid) / static_cast<double>(samples), state);
                reachable.append(state, motion.label(i));
            }
            if (valid < samples)
                break;
        }
        space_->freeState(state);
        return reachable;
    }

    void PhysicsPush::keepStandoff(ompl::base::State *state, unsigned int object) const
    {
        ompl_mm::ObjectPose pose = space_->objectPose(state, object);
        const Eigen::Vector2d tool = space_->toolPosition(state).head<2>();
        const Eigen::Vector2d away = pose.position.head<2>() - tool;
        const double standoff = standoff_(object);
        if (away.norm() >= standoff || away.norm() == 0.0)
            return;
        pose.position.head<2>() = tool + standoff * away.normalized();
        space_->setObjectPose(state, object, pose);
    }

    void PhysicsPush::appendMade(ompl_mm::Trajectory &trajectory, const ompl::base::State *state,
                                 ompl_mm::SegmentLabel label, bool branchable) const
    {
        Made made{{}, {}, label};
        space_->copyToReals(made.from, trajectory.back());
        space_->copyToReals(made.to, state);
        made_[static_cast<std::size_t>(label.object)].push_back(std::move(made));
        trajectory.append(state, label, branchable);
    }

    std::optional<ompl_mm::SegmentLabel> PhysicsPush::explain(const ompl::base::State *from,
                                                              const ompl::base::State *to) const
    {
        std::vector<double> a, b;
        space_->copyToReals(a, from);
        space_->copyToReals(b, to);
        for (const std::vector<Made> &pushes : made_)
            for (const Made &made : pushes)
                if (liesOn(made, a, b))
                    return made.label;
        return std::nullopt;
    }

    bool PhysicsPush::liesOn(const Made &made, const std::vector<double> &from,
                             const std::vector<double> &to) const
    {
        if (made.from == from && made.to == to)
            return true;
        // where along the segment from and to are, read off the value that changes most
        std::size_t widest = 0;
        for (std::size_t i = 1; i < made.from.size(); ++i)
            if (std::abs(made.to[i] - made.from[i]) > std::abs(made.to[widest] - made.from[widest]))
                widest = i;
        const double span = made.to[widest] - made.from[widest];
        if (span == 0.0)
            return false;
        const double s = (from[widest] - made.from[widest]) / span;
        const double t = (to[widest] - made.from[widest]) / span;
        if (!(s >= -ON_SEGMENT && s < t && t <= 1.0 + ON_SEGMENT))
            return false;
        for (std::size_t i = 0; i < made.from.size(); ++i)
        {
            const double delta = made.to[i] - made.from[i];
            if (std::abs(made.from[i] + s * delta - from[i]) > ON_SEGMENT ||
                std::abs(made.from[i] + t * delta - to[i]) > ON_SEGMENT)
                return false;
        }
        return true;
    }
}  // namespace ompl_mmphys
