// Shared test helpers: the MOBILE BLOCKED scene and fixture, state and scene editing, InputError
// capture.
#pragma once

#include "common/InputErrors.h"
#include "ompl_mm/scene/SceneLoader.h"
#include "ompl_mm/setup/ManipulationSetup.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

namespace ompl_mm::test
{
    using ompl_core::test::contains;
    using ompl_core::test::inputErrorOf;
    using ompl_core::test::startsWith;

    /** MOBILE BLOCKED's push standoff, metres. */
    constexpr double STANDOFF = 0.41;
    /** The label of a transit segment. */
    inline const SegmentLabel TRANSIT{PrimitiveKind::Transit, -1};
    /** The label of a segment that pushes object. */
    inline SegmentLabel pushOf(int object)
    {
        return {PrimitiveKind::Push, object};
    }

    /** The MOBILE BLOCKED scene, loaded from scenes/mobile_blocked.xml. */
    inline Scene mobileBlockedScene()
    {
        return loadScene(OMPL_MM_SCENES_DIR "/mobile_blocked.xml");
    }

    /** A scene with only the one-joint arm of test/data/unit_arm1.urdf (tool link "hand"). */
    inline Scene unitArmScene()
    {
        Scene scene;
        scene.robot.urdfFile = OMPL_MM_TEST_DATA_DIR "/unit_arm1.urdf";
        scene.robot.toolLink = "hand";
        return scene;
    }

    /** The model of scene, its robot read from the scene's URDF file. */
    inline ManipulationModelPtr makeModel(const Scene &scene)
    {
        return std::make_shared<ManipulationModel>(scene, RobotModel::fromUrdfFile(scene.robot.urdfFile));
    }

    /** A support surface over the rectangle min..max at the given height. */
    inline SupportSurface supportSurface(const std::string &name, const Eigen::Vector2d &min,
                                         const Eigen::Vector2d &max, double height = 0.0)
    {
        SupportSurface surface;
        surface.name = name;
        surface.min = min;
        surface.max = max;
        surface.height = height;
        return surface;
    }

    /** A movable upright cylinder (its start pose left at the origin). */
    inline MovableObject cylinderObject(const std::string &name, double radius, double length)
    {
        MovableObject object;
        object.name = name;
        object.shape.kind = Shape::Kind::Cylinder;
        object.shape.radius = radius;
        object.shape.length = length;
        return object;
    }

    /** Sets the two joints (x, y) of a planar robot in state. */
    inline void setRobot(const ManipulationStateSpace &space, ompl::base::State *state, double x, double y)
    {
        space.robotValues(state)[0] = x;
        space.robotValues(state)[1] = y;
    }

    /** Places object `object` of state at (x, y, z) with the given yaw. */
    inline void setObject(const ManipulationStateSpace &space, ompl::base::State *state, unsigned int object,
                          double x, double y, double z = 0.0, double yaw = 0.0)
    {
        space.setObjectPose(state, object, {Eigen::Vector3d(x, y, z), yaw});
    }

    /** The fault found before planning in scene: the ompl_core::InputError message of building a
        ManipulationSetup for it, else the message of its goalFault(), else "". */
    inline std::string setupError(const Scene &scene)
    {
        return ompl_core::test::setupFaultOf<ManipulationSetup>(scene);
    }

    /** A fixture with a ManipulationSetup of a scene (MOBILE BLOCKED unless given) and its state space. */
    class MobileBlockedTest : public ::testing::Test
    {
    protected:
        explicit MobileBlockedTest(const Scene &scene = mobileBlockedScene())
            : setup_(scene), space_(*setup_.manipulationSpace())
        {
        }
        ~MobileBlockedTest() override
        {
            for (ompl::base::State *state : owned_)
                space_.freeState(state);
        }

        /** A new copy of the start state, freed with the fixture. */
        ompl::base::State *startCopy()
        {
            return own(space_.cloneState(setup_.getProblemDefinition()->getStartState(0)));
        }

        /** A newly allocated state with unset values, freed with the fixture. */
        ompl::base::State *newState() { return own(space_.allocState()); }

        /** state, freed with the fixture. */
        ompl::base::State *own(ompl::base::State *state)
        {
            owned_.push_back(state);
            return state;
        }

        ManipulationSetup setup_;
        ManipulationStateSpace &space_;

    private:
        std::vector<ompl::base::State *> owned_;
    };
}  // namespace ompl_mm::test
