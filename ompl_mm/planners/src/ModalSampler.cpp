#include "ompl_mm/planners/ModalSampler.h"

namespace ompl_mm
{
    ModalSampler::ModalSampler(const ManipulationStateSpace *space, const ManipulationGoal *goal,
                               const ompl::base::State *start, const ompl::base::State *goalState)
        : space_(space),
          goal_(goal),
          start_(space->cloneState(start)),
          goalState_(space->cloneState(goalState)),
          inPlay_(space->objectCount(), 0)
    {
        for (unsigned int i = 0; i < space->objectCount(); ++i)
            if (goal->constrainsObject(i))
                putInPlay(i);
    }

    void ModalSampler::putInPlay(unsigned int object)
    {
        if (inPlay_[object])
            return;
        inPlay_[object] = 1;
        inPlayObjects_.push_back(object);
    }

    void ModalSampler::noteVertex(const ompl::base::State *state)
    {
        // once every object is in play there is nothing left to find
        for (unsigned int i = 0; i < space_->objectCount() && inPlayObjects_.size() < inPlay_.size(); ++i)
            if (!inPlay_[i] && space_->objectMoves(state, start_, i))
                putInPlay(i);
    }

    unsigned int ModalSampler::chooseObject(ompl::RNG &rng) const
    {
        const unsigned int objects = space_->objectCount();
        const auto inPlay = static_cast<unsigned int>(inPlayObjects_.size());
        // no draw while the choice is among all objects anyway: the same searches as without play
        if (inPlay > 0 && inPlay < objects && rng.uniform01() >= probabilities_.anyObject)
            return inPlayObjects_[static_cast<std::size_t>(rng.uniformInt(0, static_cast<int>(inPlay) - 1))];
        return static_cast<unsigned int>(rng.uniformInt(0, static_cast<int>(objects) - 1));
    }

    ModalSampler::~ModalSampler()
    {
        space_->freeState(start_);
        space_->freeState(goalState_);
    }

    void ModalSampler::chooseFixedValue(PartialState &out, unsigned int part, bool forwardTree,
                                        ompl::RNG &rng) const
    {
        const bool isRobot = part == 0;
        if (!isRobot && forwardTree && !goal_->constrainsObject(part - 1))
        {
            // taken from the nearest vertex: a start value here would make the metric charge every
            // vertex that has moved the object (in clutter, those beyond the objects pushed out of
            // the way) and pull the start tree back to where it stood before those pushes
            out.setObjectDefined(part - 1, false);
            return;
        }
        if (!isRobot && !inPlay_[part - 1])
        {
            // where it stands in every vertex; defined, so that goal roots made from the sample
            // leave it there too
            out.setObjectDefined(part - 1, true);
            space_->copyObject(out.state(), start_, part - 1);
            return;
        }
        const bool goalDefines = isRobot ? goal_->constrainsRobot() : goal_->constrainsObject(part - 1);
        // a goal value the goal does not define stays undefined
        const double r = rng.uniform01();
        const ompl::base::State *source = nullptr;
        if (r >= probabilities_.undefined + probabilities_.startValue)
            source = goalDefines ? goalState_ : nullptr;
        else if (r >= probabilities_.undefined)
            source = start_;

        if (isRobot)
        {
            out.setRobotDefined(source != nullptr);
            if (source)
                space_->copyRobot(out.state(), source);
        }
        else
        {
            out.setObjectDefined(part - 1, source != nullptr);
            if (source)
                space_->copyObject(out.state(), source, part - 1);
        }
    }

    bool ModalSampler::sampleObject(PartialState &out, unsigned int object, ompl::RNG &rng) const
    {
        const Scene &scene = space_->model()->scene();
        const int surfaces = static_cast<int>(scene.surfaces.size());
        const int places = surfaces + (sampleInAir_ ? static_cast<int>(scene.samplingRegions.size()) : 0);
        const int place = rng.uniformInt(0, places - 1);
        ObjectPose pose;
        if (place < surfaces)
        {
            const SupportSurface &s = scene.surfaces[place];
            pose.position = {rng.uniformReal(s.min.x(), s.max.x()), rng.uniformReal(s.min.y(), s.max.y()),
                             s.height};
        }
        else
        {
            const Eigen::AlignedBox3d &box = scene.samplingRegions[place - surfaces].box;
            for (int k = 0; k < 3; ++k)
                pose.position[k] = rng.uniformReal(box.min()[k], box.max()[k]);
        }
        // objects turn only with a grasp that holds their yaw, so samples keep the start yaw
        pose.yaw = scene.objects[object].start.yaw;
        space_->setObjectPose(out.state(), object, pose);
        out.setObjectDefined(object, true);
        return place >= surfaces;
    }

    void ModalSampler::sampleRobot(PartialState &out, bool forwardTree, ompl::RNG &rng) const
    {
        out.setRobotDefined(true);
        const ompl::base::State *farEnd = forwardTree ? goalState_ : start_;
        if (rng.uniform01() >= probabilities_.randomRobot && (!forwardTree || goal_->constrainsRobot()))
        {
            space_->copyRobot(out.state(), farEnd);
            return;
        }
        const RobotModel &robot = space_->model()->robot();
        double *q = space_->robotValues(out.state());
        for (unsigned int j = 0; j < robot.dof(); ++j)
            q[j] = rng.uniformReal(robot.variableJoint(j).lower, robot.variableJoint(j).upper);
    }

    void ModalSampler::sample(PartialState &out, bool forwardTree, ompl::RNG &rng) const
    {
        const unsigned int objects = space_->objectCount();
        if (objects > 0 && rng.uniform01() < probabilities_.object)
        {
            const unsigned int chosen = chooseObject(rng);
            out.setGraspedObject(-1);
            if (sampleObject(out, chosen, rng))
            {
                out.setRobotDefined(false);
                out.setGraspedObject(static_cast<int>(chosen));
            }
            else
                chooseFixedValue(out, 0, forwardTree, rng);
            for (unsigned int i = 0; i < objects; ++i)
                if (i != chosen)
                    chooseFixedValue(out, 1 + i, forwardTree, rng);
            return;
        }
        out.setGraspedObject(-1);
        sampleRobot(out, forwardTree, rng);
        for (unsigned int i = 0; i < objects; ++i)
            chooseFixedValue(out, 1 + i, forwardTree, rng);
    }
}  // namespace ompl_mm
