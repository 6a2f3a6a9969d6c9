// Tests for the grasp's depth: the Panda's hand reach measured against its palm mesh's own
// vertices, the automatic grasp height for top and side grasps, an explicit grasp_depth, and a
// pickup whose palm meets every object, which the planner reports with the blocking pair.
#include "ompl_mm/primitives/Grasping.h"

#include "common/MoplIterations.h"
#include "common/PandaPick.h"
#include "ompl_mm/setup/ManipulationSetup.h"

#include <ompl/util/Console.h>

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

using namespace ompl_mm;

namespace
{
    /** The highest z of the Panda hand's collision mesh (its own frame), read from the OBJ file. */
    double palmTopOfHandMesh()
    {
        std::ifstream in(OMPL_MM_SCENES_DIR "/robots/panda/franka_panda/meshes/collision/hand.obj");
        double top = -1.0;
        for (std::string line; std::getline(in, line);)
            if (line.rfind("v ", 0) == 0)
            {
                std::istringstream values(line.substr(2));
                double x, y, z;
                values >> x >> y >> z;
                top = std::max(top, z);
            }
        return top;
    }

    /** The Panda scene with the pickup's parameters set as `pickup` says ("name value ...") and
        its cylinder's length. */
    Scene pandaWith(const std::string &pickup, double length)
    {
        Scene scene = test::pandaPickScene();
        for (PrimitiveSpec &spec : scene.primitives)
            if (spec.type == "pickup")
            {
                std::istringstream pairs(pickup);
                for (std::string name, value; pairs >> name >> value;)
                    spec.params[name] = value;
            }
        scene.objects[0].shape.length = length;
        return scene;
    }

    /** A grasping of the scene's space with a tilt and depth, with the setup that owns the space. */
    struct GraspingOf
    {
        GraspingOf(const Scene &scene, double tilt, std::optional<double> depth = {}) : setup(scene)
        {
            Grasping::Settings settings;
            settings.tilt = tilt;
            settings.depth = depth;
            grasping = std::make_unique<Grasping>(setup.manipulationSpace().get(), settings,
                                                  InverseKinematicsFactory());
        }
        const Grasping *operator->() const { return grasping.get(); }

        ManipulationSetup setup;
        std::unique_ptr<Grasping> grasping;
    };
}  // namespace

TEST(GraspDepth, ThePandasHandReachIsWhereItsPalmMeshBegins)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    // the grasp target sits 0.105 m along the hand's z; the palm's mesh ends below that
    const double expected = 0.105 - palmTopOfHandMesh();
    ASSERT_GT(expected, 0.03);
    const GraspingOf grasping(test::pandaPickScene(), 0.0);
    EXPECT_NEAR(grasping->handReach(), expected, 1.5e-3) << "measured in millimetre steps";
}

TEST(GraspDepth, TopGraspsRiseToKeepThePalmAboveTallObjectsAndSideGraspsDoNot)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    const Scene tall = pandaWith("lift_height 0.05", 0.15);
    const GraspingOf top(tall, 0.0);
    const double reach = top->handReach();
    EXPECT_NEAR(top->graspHeight(0), 0.15 + Grasping::HAND_MARGIN - reach, 1e-12)
        << "the palm 5 mm above the top";
    const GraspingOf tilted(tall, 0.3);
    EXPECT_NEAR(tilted->graspHeight(0), 0.15 + Grasping::HAND_MARGIN - reach * std::cos(0.3), 1e-12);
    // from the side the palm passes beside the cylinder: held at its centre
    EXPECT_DOUBLE_EQ(GraspingOf(tall, M_PI / 2)->graspHeight(0), 0.075);
    // a short object is held at its centre, and an explicit depth is taken as it is
    EXPECT_DOUBLE_EQ(GraspingOf(pandaWith("lift_height 0.05", 0.05), 0.0)->graspHeight(0), 0.025);
    EXPECT_DOUBLE_EQ(GraspingOf(tall, 0.0, 0.1)->graspHeight(0), 0.05);
    EXPECT_DOUBLE_EQ(GraspingOf(tall, 0.0, 0.3)->graspHeight(0), 0.0) << "no deeper than the base";
}

TEST(GraspDepth, ANegativeGraspDepthIsAnErrorAtThePrimitivesLine)
{
    Scene scene = pandaWith("grasp_depth -0.01", 0.07);
    std::string message;
    try
    {
        ManipulationSetup setup(scene);
    }
    catch (const ompl::Exception &e)
    {
        message = e.what();
    }
    EXPECT_NE(message.find("grasp depth must be at least 0"), std::string::npos) << message;
}

TEST(GraspDepth, APickupWhosePalmMeetsEveryObjectIsReportedWithTheBlockingPair)
{
    // a 10 cm cylinder held at its centre: the palm, 4 cm above, sinks into its top on every approach
    ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
    ManipulationSetup setup(pandaWith("grasp_depth 0.05", 0.1));
    setup.mopl()->setSeed(1);
    ASSERT_NE(setup.solve(test::moplIterations(setup, 150)), ompl::base::PlannerStatus::EXACT_SOLUTION);
    const PrimitiveTally::Record &pickup = setup.mopl()->primitiveTally().records().at("pickup");
    EXPECT_TRUE(pickup.neverSucceeded());
    EXPECT_GT(pickup.stopped, 0u);
    const std::string summary = setup.mopl()->primitiveTally().failureSummary();
    EXPECT_NE(summary.find("pickup: "), std::string::npos) << summary;
    EXPECT_NE(summary.find("motion stopped by robot link 'panda_hand' and object 'cyl1'"), std::string::npos)
        << summary;
    // with the automatic depth the same pickup goes through
    ManipulationSetup automatic(pandaWith("lift_height 0.05", 0.1));
    automatic.mopl()->setSeed(1);
    EXPECT_EQ(automatic.solve(test::moplIterations(automatic, 3000)),
              ompl::base::PlannerStatus::EXACT_SOLUTION);
}
