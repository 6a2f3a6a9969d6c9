#include "OpenDEPeer.h"

#include "ompl_core/io/InputError.h"
#include "ompl_core/io/TextFormat.h"
#include "ompl_phys/base/RobotProjection.h"
#include "ompl_phys/control/RobotGridDecomposition.h"

#include <ompl/base/ScopedState.h>
#include <ompl/base/goals/GoalSampleableRegion.h>
#include <ompl/control/planners/kpiece/KPIECE1.h>
#include <ompl/control/planners/rrt/RRT.h>
#include <ompl/control/planners/syclop/SyclopRRT.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace opende_peer
{
    namespace ob = ompl::base;
    namespace oc = ompl::control;
    using ompl_phys::PhysicsShape;

    const std::vector<std::string> &peerDifferences()
    {
        static const std::vector<std::string> differences{
            "Constraint-oriented bodies are plain free bodies: OpenDEStateValidityChecker judges "
            "collisions and bounds only, so where the robot may push such a body (its push region) and "
            "how the body may move (along its push axis, without turning) go unchecked.",
            "One ODE step per propagation step (OpenDEStatePropagator): the propagation step is the "
            "scene's step / substeps and a control lasts min_steps·substeps to max_steps·substeps of "
            "them, the same range in seconds as ours in finer increments.",
            "No NaN/Inf check: a non-finite state passes RealVectorStateSpace's bounds check.",
            "ODE's random generator, from which QuickStep draws its constraint order, is never reseeded: "
            "the same state and force need not give the same step twice, so a replay may drift from its "
            "plan.",
            "Validity is judged after each ODE step by colliding the state again "
            "(OpenDEStateValidityChecker); the contacts the propagator found are not kept.",
            "Region and speed limits are per-body bounds of the state space, set on its components (the "
            "extension's setters give every body one bound).",
            "Goal states are sampled with the robot in the goal disc and every other body at its start "
            "(ours pushes the goal's occupants aside); the demo's goal, a GoalRegion, cannot be sampled, "
            "which SyclopRRT needs."};
        return differences;
    }

    namespace
    {
        /** Contacts are created this far before geometry touches, metres: ours' value. */
        constexpr double SURFACE_LAYER = 0.001;
        /** How far below the floor and above it a body centre may be, metres: ours' state bounds. */
        constexpr double Z_BELOW = 1.0;
        constexpr double Z_ABOVE = 2.0;

        void toOde(const Eigen::Quaterniond &rotation, dQuaternion out)
        {
            out[0] = rotation.w();
            out[1] = rotation.x();
            out[2] = rotation.y();
            out[3] = rotation.z();
        }

        ob::RealVectorBounds positionBounds(const Eigen::AlignedBox2d &region)
        {
            ob::RealVectorBounds bounds(3);
            bounds.setLow(0, region.min().x());
            bounds.setHigh(0, region.max().x());
            bounds.setLow(1, region.min().y());
            bounds.setHigh(1, region.max().y());
            bounds.setLow(2, -Z_BELOW);
            bounds.setHigh(2, Z_ABOVE);
            return bounds;
        }

        /** The robot centre on the floor (world x, y), from a state of the peer's space. */
        Eigen::Vector2d robotPosition(const ob::State *state)
        {
            const double *p = state->as<oc::OpenDEStateSpace::StateType>()->getBodyPosition(0);
            return {p[0], p[1]};
        }

        /** The robot's position on the floor, in ours' cells (RobotProjection), for KPIECE1. */
        class PeerProjection : public ob::ProjectionEvaluator
        {
        public:
            PeerProjection(const ob::StateSpace *space, const Eigen::AlignedBox2d &region)
                : ob::ProjectionEvaluator(space), region_(region)
            {
            }

            unsigned int getDimension() const override { return 2; }

            void defaultCellSizes() override
            {
                constexpr double cells = ompl_phys::RobotProjection::CELLS_PER_SIDE;
                cellSizes_ = {region_.sizes().x() / cells, region_.sizes().y() / cells};
            }

            void project(const ob::State *state, Eigen::Ref<Eigen::VectorXd> projection) const override
            {
                projection = robotPosition(state);
            }

        private:
            Eigen::AlignedBox2d region_;
        };

        /** The extension's state space with the demo's additions: a distance (the robot's on the
            floor) and a default projection. */
        class PeerStateSpace : public oc::OpenDEStateSpace
        {
        public:
            explicit PeerStateSpace(const std::shared_ptr<PeerEnvironment> &environment)
                : oc::OpenDEStateSpace(environment), region_(environment->scene().limits.robotRegion)
            {
            }

            double distance(const ob::State *a, const ob::State *b) const override
            {
                return (robotPosition(a) - robotPosition(b)).norm();
            }

            void registerProjections() override
            {
                registerDefaultProjection(std::make_shared<PeerProjection>(this, region_));
            }

        private:
            Eigen::AlignedBox2d region_;
        };

        /** The robot centre within the scene's goal disc. Sampleable, as SyclopRRT needs (the demo's
            GoalRegion is not): the start with the robot moved to a uniform point of the disc. */
        class PeerGoal : public ob::GoalSampleableRegion
        {
        public:
            PeerGoal(const ob::SpaceInformationPtr &si, const ompl_phys::GoalDisc &goal,
                     const ob::State *start)
                : ob::GoalSampleableRegion(si), centre_(goal.centre), start_(si->getStateSpace(), start)
            {
                setThreshold(goal.radius);
            }

            double distanceGoal(const ob::State *state) const override
            {
                return (robotPosition(state) - centre_).norm();
            }

            void sampleGoal(ob::State *state) const override
            {
                // uniform in the disc: radius by the square root of a uniform number
                const double radius = getThreshold() * std::sqrt(rng_.uniform01());
                const double angle = rng_.uniformReal(-M_PI, M_PI);
                si_->copyState(state, start_.get());
                double *p = state->as<oc::OpenDEStateSpace::StateType>()->getBodyPosition(0);
                p[0] = centre_.x() + radius * std::cos(angle);
                p[1] = centre_.y() + radius * std::sin(angle);
            }

            unsigned int maxSampleCount() const override { return std::numeric_limits<unsigned int>::max(); }

        private:
            Eigen::Vector2d centre_;
            ob::ScopedState<> start_;
            mutable ompl::RNG rng_;
        };

        /** Ours' SyCLoP grid (RobotGridDecomposition) on the peer's states. */
        class PeerGrid : public oc::GridDecomposition
        {
        public:
            explicit PeerGrid(const Eigen::AlignedBox2d &region)
                : oc::GridDecomposition(ompl_phys::RobotGridDecomposition::DEFAULT_CELLS_PER_SIDE, 2,
                                        ompl_phys::floorBounds(region))
            {
            }

            void project(const ob::State *state, std::vector<double> &coord) const override
            {
                const Eigen::Vector2d robot = robotPosition(state);
                coord = {robot.x(), robot.y()};
            }

            void sampleFullState(const ob::StateSamplerPtr &sampler, const std::vector<double> &coord,
                                 ob::State *state) const override
            {
                sampler->sampleUniform(state);
                double *p = state->as<oc::OpenDEStateSpace::StateType>()->getBodyPosition(0);
                p[0] = coord[0];
                p[1] = coord[1];
            }
        };
    }  // namespace

    PeerEnvironment::PeerEnvironment(ompl_phys::PhysicsScenePtr scene) : scene_(std::move(scene))
    {
        const ompl_phys::ContactParameters &contact = scene_->contact;
        world_ = dWorldCreate();
        space_ = dHashSpaceCreate(nullptr);
        collisionSpaces_.push_back(space_);
        dWorldSetGravity(world_, 0.0, 0.0, contact.gravity);
        dWorldSetQuickStepNumIterations(world_, static_cast<int>(contact.iterations));
        dWorldSetContactSurfaceLayer(world_, SURFACE_LAYER);
        dWorldSetAutoDisableFlag(world_, 0);
        floor_ = dCreatePlane(space_, 0.0, 0.0, 1.0, 0.0);

        dBodyID robot = dBodyCreate(world_);
        dMass robotMass;
        dMassSetSphereTotal(&robotMass, scene_->robot.mass, scene_->robot.radius);
        dBodySetMass(robot, &robotMass);
        const Eigen::Vector3d &start = scene_->robot.start;
        dBodySetPosition(robot, start.x(), start.y(), start.z());
        robot_ = dCreateSphere(space_, scene_->robot.radius);
        dGeomSetBody(robot_, robot);
        stateBodies_.push_back(robot);

        for (const ompl_phys::PhysicsBody &body : scene_->bodies)
        {
            dGeomID geom = ompl_phys::createShapeGeom(space_, body.shape, prisms_);
            const Eigen::Vector3d position = body.start.translation();
            dQuaternion rotation;
            toOde(Eigen::Quaterniond(body.start.linear()), rotation);
            if (body.kind == ompl_phys::BodyKind::Fixed)
            {
                dGeomSetPosition(geom, position.x(), position.y(), position.z());
                dGeomSetQuaternion(geom, rotation);
                fixed_.push_back(geom);
                continue;
            }
            dBodyID dynamic = dBodyCreate(world_);
            ompl_phys::setShapeMass(dynamic, body.shape, body.mass);
            dBodySetPosition(dynamic, position.x(), position.y(), position.z());
            dBodySetQuaternion(dynamic, rotation);
            dGeomSetBody(geom, dynamic);
            movable_.push_back(geom);
            stateBodies_.push_back(dynamic);
        }

        maxContacts_ = contact.maxContacts;
        stepSize_ = scene_->limits.stepSize / contact.substeps;
        minControlSteps_ = scene_->limits.minControlSteps * contact.substeps;
        maxControlSteps_ = scene_->limits.maxControlSteps * contact.substeps;
    }

    PeerEnvironment::~PeerEnvironment()
    {
        dSpaceDestroy(space_);  // destroys its geoms
        dWorldDestroy(world_);  // destroys its bodies
    }

    void PeerEnvironment::getControlBounds(std::vector<double> &lower, std::vector<double> &upper) const
    {
        lower.assign(2, -scene_->limits.maxForce);
        upper.assign(2, scene_->limits.maxForce);
    }

    void PeerEnvironment::applyControl(const double *control) const
    {
        dBodyAddForce(stateBodies_.front(), control[0], control[1], 0.0);
    }

    bool PeerEnvironment::isValidCollision(dGeomID geom1, dGeomID geom2, const dContact & /*contact*/) const
    {
        auto fixed = [this](dGeomID geom) { return geom != floor_ && !dGeomGetBody(geom); };
        return !((geom1 == robot_ && fixed(geom2)) || (geom2 == robot_ && fixed(geom1)));
    }

    unsigned int PeerEnvironment::getMaxContacts(dGeomID geom1, dGeomID geom2) const
    {
        return dGeomGetBody(geom1) || dGeomGetBody(geom2) ? maxContacts_ : 0;
    }

    void PeerEnvironment::setupContact(dGeomID geom1, dGeomID geom2, dContact &contact) const
    {
        const bool robotOnFloor =
            (geom1 == robot_ && geom2 == floor_) || (geom2 == robot_ && geom1 == floor_);
        contact.surface = dSurfaceParameters{};
        contact.surface.mode = dContactSoftERP | dContactSoftCFM | dContactApprox1;
        contact.surface.mu = robotOnFloor ? scene_->materials.robotFloor : scene_->materials.defaultMu;
        contact.surface.soft_erp = scene_->contact.erp;
        contact.surface.soft_cfm = scene_->contact.cfm;
    }

    void PeerEnvironment::placeBodies(const ompl_phys::BodyStates &states) const
    {
        for (std::size_t i = 0; i < stateBodies_.size(); ++i)
        {
            const ompl_phys::BodyState &s = states[i];
            dBodyID body = stateBodies_[i];
            dQuaternion rotation;
            toOde(s.orientation, rotation);
            dBodySetPosition(body, s.position.x(), s.position.y(), s.position.z());
            dBodySetQuaternion(body, rotation);
            dBodySetLinearVel(body, s.linearVelocity.x(), s.linearVelocity.y(), s.linearVelocity.z());
            dBodySetAngularVel(body, s.angularVelocity.x(), s.angularVelocity.y(), s.angularVelocity.z());
        }
    }

    const std::vector<std::string> &PeerSetup::plannerNames()
    {
        static const std::vector<std::string> names{"rrt", "kpiece", "sycloprrt"};
        return names;
    }

    PeerSetup::PeerSetup(ompl_phys::PhysicsScenePtr scene)
        : PeerSetup(std::make_shared<PeerEnvironment>(std::move(scene)))
    {
    }

    PeerSetup::PeerSetup(std::shared_ptr<PeerEnvironment> environment)
        : oc::OpenDESimpleSetup(std::make_shared<PeerStateSpace>(environment)),
          environment_(std::move(environment))
    {
        const ompl_phys::PlanningLimits &limits = environment_->scene().limits;
        auto &space = *getStateSpace()->as<oc::OpenDEStateSpace>();
        // the components of body i: position, linear velocity, angular velocity, orientation
        for (unsigned int i = 0; i < space.getNrBodies(); ++i)
        {
            const bool robot = i == 0;
            space.getSubspace(4 * i)->as<ob::RealVectorStateSpace>()->setBounds(
                positionBounds(robot ? limits.robotRegion : limits.bodyRegion));
            const double speed = robot ? limits.maxRobotSpeed : limits.maxBodySpeed;
            space.getSubspace(4 * i + 1)->as<ob::RealVectorStateSpace>()->setBounds(-speed, speed);
            space.getSubspace(4 * i + 2)->as<ob::RealVectorStateSpace>()->setBounds(-limits.maxAngularSpeed,
                                                                                    limits.maxAngularSpeed);
        }
        si_->setStateValidityChecker(std::make_shared<oc::OpenDEStateValidityChecker>(si_));
        setGoal(std::make_shared<PeerGoal>(si_, environment_->scene().goal, getCurrentState().get()));
        decomposition_ = std::make_shared<PeerGrid>(limits.robotRegion);
    }

    void PeerSetup::setPlannerByName(const std::string &name)
    {
        ob::PlannerPtr planner;
        if (name == "rrt")
            planner = std::make_shared<oc::RRT>(si_);
        else if (name == "kpiece")
            planner = std::make_shared<oc::KPIECE1>(si_);
        else if (name == "sycloprrt")
            planner = std::make_shared<oc::SyclopRRT>(si_, decomposition_);
        else
            throw ompl_core::InputError("the OpenDE peer has no planner '" + name + "'");
        if (planner->params().hasParam("goal_bias"))
            planner->params().setParam("goal_bias",
                                       ompl_core::exactText(environment_->scene().limits.goalBias));
        setPlanner(planner);
    }

    ompl_phys::BodyStates PeerSetup::bodyStates(const ob::State *state) const
    {
        const auto *s = state->as<oc::OpenDEStateSpace::StateType>();
        ompl_phys::BodyStates states(environment_->stateBodies_.size());
        for (unsigned int i = 0; i < states.size(); ++i)
        {
            const ob::SO3StateSpace::StateType &q = s->getBodyRotation(i);
            states[i].position = Eigen::Map<const Eigen::Vector3d>(s->getBodyPosition(i));
            states[i].orientation = Eigen::Quaterniond(q.w, q.x, q.y, q.z);
            states[i].linearVelocity = Eigen::Map<const Eigen::Vector3d>(s->getBodyLinearVelocity(i));
            states[i].angularVelocity = Eigen::Map<const Eigen::Vector3d>(s->getBodyAngularVelocity(i));
        }
        return states;
    }
}  // namespace opende_peer
