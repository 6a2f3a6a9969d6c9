#include "ompl_mm/base/ManipulationStateSpace.h"

#include "ompl_mm/base/ManipulationStateSampler.h"

#include <ompl/util/Exception.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <new>

namespace ob = ompl::base;

namespace ompl_mm
{
    namespace
    {
        /** The largest longest-valid-segment fraction OMPL accepts (it requires less than 1). */
        constexpr double MAX_SEGMENT_FRACTION = 1.0 - 1e-9;

        unsigned int positionIndex(unsigned int object)
        {
            return 1 + 2 * object;
        }
        unsigned int yawIndex(unsigned int object)
        {
            return 2 + 2 * object;
        }

        using RealVectorState = ob::RealVectorStateSpace::StateType;
        using AngleState = ob::SO2StateSpace::StateType;

        /** Hands out the parts of one state's block in order, each aligned for any type; with a null
            block it only counts the bytes. */
        class BlockCursor
        {
        public:
            explicit BlockCursor(char *block) : block_(block) {}
            void *take(std::size_t bytes)
            {
                void *part = block_ ? block_ + used_ : nullptr;
                used_ += (bytes + ALIGNMENT - 1) / ALIGNMENT * ALIGNMENT;
                return part;
            }
            std::size_t used() const { return used_; }
            bool building() const { return block_ != nullptr; }

        private:
            static constexpr std::size_t ALIGNMENT = alignof(std::max_align_t);
            char *block_;
            std::size_t used_{0};
        };

        /** Lays out a state of a space with `dof` robot coordinates and `objects` objects in cursor's
            block (the compound, its component pointers, the robot's vector, then per object its
            position vector and its yaw), constructing the parts when the cursor has a block. */
        ob::State *layOut(BlockCursor &cursor, unsigned int dof, unsigned int objects)
        {
            const bool build = cursor.building();
            void *compoundPart = cursor.take(sizeof(ManipulationStateSpace::StateType));
            void *componentsPart = cursor.take(sizeof(ob::State *) * (1 + 2 * objects));
            auto *state = build ? new (compoundPart) ManipulationStateSpace::StateType() : nullptr;
            if (build)
                state->components = static_cast<ob::State **>(componentsPart);
            const auto vector = [&](unsigned int index, unsigned int size)
            {
                void *statePart = cursor.take(sizeof(RealVectorState));
                void *valuesPart = cursor.take(sizeof(double) * size);
                if (!build)
                    return;
                auto *component = new (statePart) RealVectorState();
                component->values = static_cast<double *>(valuesPart);
                state->components[index] = component;
            };
            vector(0, dof);
            for (unsigned int i = 0; i < objects; ++i)
            {
                vector(positionIndex(i), 3);
                void *yawPart = cursor.take(sizeof(AngleState));
                if (build)
                    state->components[yawIndex(i)] = new (yawPart) AngleState();
            }
            return state;
        }

        /** Bounds that enclose every place an object may be: surfaces and sampling regions. */
        ob::RealVectorBounds objectBounds(const Scene &scene)
        {
            Eigen::AlignedBox3d box;
            for (const SupportSurface &s : scene.surfaces)
            {
                box.extend(Eigen::Vector3d(s.min.x(), s.min.y(), s.height));
                box.extend(Eigen::Vector3d(s.max.x(), s.max.y(), s.height));
            }
            for (const SamplingRegion &r : scene.samplingRegions)
                box.extend(r.box);
            for (const MovableObject &o : scene.objects)
                box.extend(o.start.position);
            // a margin keeps bounds non-degenerate when all surfaces share one height
            const double margin = 0.01;
            ob::RealVectorBounds bounds(3);
            for (unsigned int i = 0; i < 3; ++i)
            {
                bounds.setLow(i, box.min()[i] - margin);
                bounds.setHigh(i, box.max()[i] + margin);
            }
            return bounds;
        }
    }  // namespace

    ManipulationStateSpace::ManipulationStateSpace(ManipulationModelPtr model) : model_(std::move(model))
    {
        setName("Manipulation" + getName());
        const RobotModel &robot = model_->robot();
        auto robotSpace = std::make_shared<ob::RealVectorStateSpace>(robot.dof());
        ob::RealVectorBounds jointBounds(robot.dof());
        for (unsigned int i = 0; i < robot.dof(); ++i)
        {
            jointBounds.setLow(i, robot.variableJoint(i).lower);
            jointBounds.setHigh(i, robot.variableJoint(i).upper);
            robotSpace->setDimensionName(i, robot.variableJoint(i).name);
        }
        robotSpace->setBounds(jointBounds);
        robotSpace->setName("robot");
        addSubspace(robotSpace, 1.0);

        const ob::RealVectorBounds bounds = objectBounds(model_->scene());
        for (const MovableObject &object : model_->scene().objects)
        {
            auto position = std::make_shared<ob::RealVectorStateSpace>(3);
            position->setBounds(bounds);
            position->setName(object.name + "_position");
            addSubspace(position, 1.0);
            auto yaw = std::make_shared<ob::SO2StateSpace>();
            yaw->setName(object.name + "_yaw");
            addSubspace(yaw, 1.0);
        }
        lock();
        BlockCursor size(nullptr);
        layOut(size, robotDimension(), objectCount());
        stateBytes_ = size.used();
    }

    ob::State *ManipulationStateSpace::allocState() const
    {
        BlockCursor cursor(static_cast<char *>(::operator new(stateBytes_)));
        return layOut(cursor, robotDimension(), objectCount());
    }

    void ManipulationStateSpace::freeState(ob::State *state) const
    {
        auto *compound = state->as<StateType>();
        for (unsigned int i = 0; i < objectCount(); ++i)
        {
            compound->as<RealVectorState>(positionIndex(i))->~RealVectorState();
            compound->as<AngleState>(yawIndex(i))->~AngleState();
        }
        compound->as<RealVectorState>(0)->~RealVectorState();
        compound->~StateType();
        // the compound opens its block
        ::operator delete(static_cast<void *>(compound));
    }

    double *ManipulationStateSpace::robotValues(ob::State *state) const
    {
        return state->as<StateType>()->as<ob::RealVectorStateSpace::StateType>(0)->values;
    }

    const double *ManipulationStateSpace::robotValues(const ob::State *state) const
    {
        return state->as<StateType>()->as<ob::RealVectorStateSpace::StateType>(0)->values;
    }

    Eigen::Vector3d ManipulationStateSpace::objectPosition(const ob::State *state, unsigned int object) const
    {
        const double *p =
            state->as<StateType>()->as<ob::RealVectorStateSpace::StateType>(positionIndex(object))->values;
        return {p[0], p[1], p[2]};
    }

    double ManipulationStateSpace::objectYaw(const ob::State *state, unsigned int object) const
    {
        return state->as<StateType>()->as<ob::SO2StateSpace::StateType>(yawIndex(object))->value;
    }

    ObjectPose ManipulationStateSpace::objectPose(const ob::State *state, unsigned int object) const
    {
        return {objectPosition(state, object), objectYaw(state, object)};
    }

    void ManipulationStateSpace::setObjectPose(ob::State *state, unsigned int object,
                                               const ObjectPose &pose) const
    {
        double *p =
            state->as<StateType>()->as<ob::RealVectorStateSpace::StateType>(positionIndex(object))->values;
        p[0] = pose.position.x();
        p[1] = pose.position.y();
        p[2] = pose.position.z();
        auto *yaw = state->as<StateType>()->as<ob::SO2StateSpace::StateType>(yawIndex(object));
        yaw->value = pose.yaw;
        getSubspace(yawIndex(object))->enforceBounds(yaw);
    }

    void ManipulationStateSpace::copyObject(ob::State *destination, const ob::State *source,
                                            unsigned int object) const
    {
        for (unsigned int index : {positionIndex(object), yawIndex(object)})
            getSubspace(index)->copyState(destination->as<StateType>()->components[index],
                                          source->as<StateType>()->components[index]);
    }

    void ManipulationStateSpace::copyRobot(ob::State *destination, const ob::State *source) const
    {
        std::copy_n(robotValues(source), robotDimension(), robotValues(destination));
    }

    bool ManipulationStateSpace::objectMoves(const ob::State *a, const ob::State *b,
                                             unsigned int object) const
    {
        return (objectPosition(a, object) - objectPosition(b, object)).cwiseAbs().maxCoeff() >
                   SAME_COORDINATE ||
               std::abs(objectYaw(a, object) - objectYaw(b, object)) > SAME_COORDINATE;
    }

    bool ManipulationStateSpace::anyObjectMoves(const ob::State *a, const ob::State *b) const
    {
        for (unsigned int i = 0; i < objectCount(); ++i)
            if (objectMoves(a, b, i))
                return true;
        return false;
    }

    bool ManipulationStateSpace::robotMoves(const ob::State *a, const ob::State *b) const
    {
        const double *qa = robotValues(a);
        const double *qb = robotValues(b);
        for (unsigned int i = 0; i < robotDimension(); ++i)
            if (std::abs(qa[i] - qb[i]) > SAME_COORDINATE)
                return true;
        return false;
    }

    int ManipulationStateSpace::restingSurface(const ob::State *state, unsigned int object) const
    {
        return model_->scene().restingSurface(objectPosition(state, object));
    }

    Eigen::Vector3d ManipulationStateSpace::toolPosition(const ob::State *state) const
    {
        return model_->toolFrame(robotValues(state)).translation();
    }

    ob::StateSamplerPtr ManipulationStateSpace::allocDefaultStateSampler() const
    {
        return std::make_shared<ManipulationStateSampler>(this);
    }

    double ManipulationStateSpace::toolTravel(const ob::State *from, const ob::State *to) const
    {
        const unsigned int steps = std::max(1u, validSegmentCount(from, to));
        ob::State *between = allocState();
        double length = 0.0;
        Eigen::Vector3d previous = toolPosition(from);
        for (unsigned int k = 1; k <= steps; ++k)
        {
            interpolate(from, to, static_cast<double>(k) / steps, between);
            const Eigen::Vector3d tool = toolPosition(between);
            length += (tool - previous).norm();
            previous = tool;
        }
        freeState(between);
        return length;
    }

    void ManipulationStateSpace::setSegmentResolution(double step)
    {
        for (unsigned int i = 0; i < getSubspaceCount(); ++i)
        {
            const ob::StateSpacePtr &space = getSubspace(i);
            // OMPL takes fractions below 1 only: a step longer than a subspace checks it once per motion
            space->setLongestValidSegmentFraction(
                std::min(MAX_SEGMENT_FRACTION, step / space->getMaximumExtent()));
        }
        setup();  // the longest valid segment is computed here
    }

    bool ManipulationStateSpace::isCarried(const ob::State *from, const ob::State *to,
                                           unsigned int object) const
    {
        return objectMoves(from, to, object) &&
               (restingSurface(from, object) < 0 || restingSurface(to, object) < 0);
    }

    ObjectPose ManipulationStateSpace::carriedPose(const ObjectPose &from, const ObjectPose &to,
                                                   const Eigen::Isometry3d &toolFrom,
                                                   const Eigen::Isometry3d &toolTo,
                                                   const Eigen::Isometry3d &toolAt, double t,
                                                   bool turnsFreely)
    {
        const auto frame = [](const ObjectPose &pose)
        {
            Eigen::Isometry3d f = Eigen::Isometry3d::Identity();
            f.translate(pose.position).rotate(Eigen::AngleAxisd(pose.yaw, Eigen::Vector3d::UnitZ()));
            return f;
        };
        // the grasp (object in the tool frame) moves linearly from one end's to the other's, so
        // interpolating in two steps equals one step; a primitive keeps one grasp along a segment
        const Eigen::Isometry3d graspFrom = toolFrom.inverse() * frame(from);
        const Eigen::Isometry3d graspTo = toolTo.inverse() * frame(to);
        Eigen::Isometry3d grasp = Eigen::Isometry3d::Identity();
        grasp.translation() = (1.0 - t) * graspFrom.translation() + t * graspTo.translation();
        grasp.linear() = Eigen::Quaterniond(graspFrom.linear())
                             .slerp(t, Eigen::Quaterniond(graspTo.linear()))
                             .toRotationMatrix();
        const Eigen::Isometry3d carried = toolAt * grasp;
        if (turnsFreely)  // its yaw is not held: it goes its own way, as uncarried yaws do
            return {carried.translation(), from.yaw + t * std::remainder(to.yaw - from.yaw, 2.0 * M_PI)};
        // the object stays upright: keep only the rotation about the vertical
        const Eigen::Vector3d xAxis = carried.linear().col(0);
        return {carried.translation(), std::atan2(xAxis.y(), xAxis.x())};
    }

    ManipulationStateSpace::MotionEnds ManipulationStateSpace::motionEnds(const ob::State *from,
                                                                          const ob::State *to) const
    {
        MotionEnds ends;
        for (unsigned int i = 0; i < objectCount() && !ends.carries; ++i)
            ends.carries = isCarried(from, to, i);
        if (ends.carries)
        {
            ends.toolFrom = model_->toolFrame(robotValues(from));
            ends.toolTo = model_->toolFrame(robotValues(to));
        }
        return ends;
    }

    void ManipulationStateSpace::interpolate(const ob::State *from, const ob::State *to, double t,
                                             ob::State *state) const
    {
        // the ends are read before state is written: state may be from or to
        interpolate(from, to, t, state, motionEnds(from, to));
    }

    void ManipulationStateSpace::interpolate(const ob::State *from, const ob::State *to, double t,
                                             ob::State *state, const MotionEnds &ends) const
    {
        // the ends exactly: from + (to - from) * 1 may differ from `to` in the last bit, which puts
        // a joint that inverse kinematics left at its limit outside it
        if (t == 0.0 || t == 1.0)
        {
            const ob::State *end = t == 0.0 ? from : to;
            if (end != state)
                copyState(state, end);
            return;
        }
        getSubspace(0)->interpolate(from->as<StateType>()->components[0], to->as<StateType>()->components[0],
                                    t, state->as<StateType>()->components[0]);
        const Eigen::Isometry3d toolAt =
            ends.carries ? model_->toolFrame(robotValues(state)) : Eigen::Isometry3d();
        for (unsigned int i = 0; i < objectCount(); ++i)
        {
            // object i's pose is read before it is written (state may be from or to)
            if (ends.carries && isCarried(from, to, i))
            {
                setObjectPose(state, i,
                              carriedPose(objectPose(from, i), objectPose(to, i), ends.toolFrom, ends.toolTo,
                                          toolAt, t, model_->scene().objects[i].shape.turnsFreely()));
                continue;
            }
            for (unsigned int index : {positionIndex(i), yawIndex(i)})
                getSubspace(index)->interpolate(from->as<StateType>()->components[index],
                                                to->as<StateType>()->components[index], t,
                                                state->as<StateType>()->components[index]);
        }
    }

    void ManipulationStateSpace::printState(const ob::State *state, std::ostream &out) const
    {
        out << "robot [";
        for (unsigned int i = 0; i < robotDimension(); ++i)
            out << (i ? " " : "") << robotValues(state)[i];
        out << "]";
        for (unsigned int i = 0; i < objectCount(); ++i)
        {
            const ObjectPose pose = objectPose(state, i);
            out << " " << model_->scene().objects[i].name << " (" << pose.position.x() << " "
                << pose.position.y() << " " << pose.position.z() << " yaw " << pose.yaw << ")";
        }
        out << std::endl;
    }

    const ManipulationStateSpace *manipulationSpaceOf(const ompl::base::StateSpace *space,
                                                      const std::string &user)
    {
        const auto *manipulation = dynamic_cast<const ManipulationStateSpace *>(space);
        if (!manipulation)
            throw ompl::Exception(user, "needs a ManipulationStateSpace, got " + space->getName());
        return manipulation;
    }
}  // namespace ompl_mm
