// Tests for writeSceneSvg.
#include <gtest/gtest.h>
#include <tinyxml2.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

#include "ompl_mm/io/SceneSvg.h"

#include "common/MobileBlocked.h"
#include "common/MoplIterations.h"
#include "common/PandaPick.h"
#include "ompl_core/run/GlobalSeed.h"
#include "ompl_mm/io/LabelLayout.h"

#include <ompl/base/ScopedState.h>
#include <ompl/util/Console.h>

using namespace ompl_mm;
using namespace ompl_mm::test;

namespace
{
    std::string render(const ManipulationSetup &setup, const ManipulationPath *path)
    {
        std::ostringstream out;
        writeSceneSvg(out, setup, path);
        return out.str();
    }

    /** All elements below (and including) e whose class attribute is exactly cls. */
    void collect(const tinyxml2::XMLElement *e, const std::string &cls,
                 std::vector<const tinyxml2::XMLElement *> &found)
    {
        for (; e != nullptr; e = e->NextSiblingElement())
        {
            const char *c = e->Attribute("class");
            if (c != nullptr && cls == c)
                found.push_back(e);
            collect(e->FirstChildElement(), cls, found);
        }
    }

    std::vector<const tinyxml2::XMLElement *> byClass(const tinyxml2::XMLDocument &doc,
                                                      const std::string &cls)
    {
        std::vector<const tinyxml2::XMLElement *> found;
        collect(doc.RootElement(), cls, found);
        return found;
    }

    /** The elements inside group whose class attribute is exactly cls. */
    std::vector<const tinyxml2::XMLElement *> byClassIn(const tinyxml2::XMLElement *group,
                                                        const std::string &cls)
    {
        std::vector<const tinyxml2::XMLElement *> found;
        collect(group->FirstChildElement(), cls, found);
        return found;
    }

    std::string titleOf(const tinyxml2::XMLElement *e)
    {
        const tinyxml2::XMLElement *title = e->FirstChildElement("title");
        return title != nullptr && title->GetText() != nullptr ? title->GetText() : "";
    }

    const tinyxml2::XMLElement *named(const std::vector<const tinyxml2::XMLElement *> &elements,
                                      const std::string &name)
    {
        for (const tinyxml2::XMLElement *e : elements)
            if (titleOf(e) == name)
                return e;
        return nullptr;
    }

    /** A path start -> transit to behind obj2 -> push obj2 0.4 m in -x, as push_mobile would make it. */
    ManipulationPath pushPath(const ManipulationSetup &setup)
    {
        const ManipulationStateSpace &space = *setup.manipulationSpace();
        const int obj2 = setup.model()->scene().objectIndex("obj2");
        const ompl::base::State *start = setup.getProblemDefinition()->getStartState(0);
        ManipulationPath path(setup.getSpaceInformation());
        path.appendFirst(start);

        ompl::base::ScopedState<> state(setup.getStateSpace());
        state = start;
        setRobot(space, state.get(), 1.21, -0.1);
        path.appendLabelled(state.get(), {PrimitiveKind::Transit, -1});

        space.robotValues(state.get())[0] = 0.81;
        ObjectPose pose = space.objectPose(state.get(), obj2);
        pose.position.x() -= 0.4;
        space.setObjectPose(state.get(), obj2, pose);
        path.appendLabelled(state.get(), {PrimitiveKind::Push, obj2});
        return path;
    }

    /** The pixel box of a polygon's points, a circle, or all of a group's elements. */
    Eigen::AlignedBox2d pixelBox(const tinyxml2::XMLElement *e)
    {
        Eigen::AlignedBox2d box;
        if (std::string(e->Name()) == "circle")
        {
            const Eigen::Vector2d c(e->DoubleAttribute("cx"), e->DoubleAttribute("cy"));
            box.extend(c - Eigen::Vector2d::Constant(e->DoubleAttribute("r")));
            box.extend(c + Eigen::Vector2d::Constant(e->DoubleAttribute("r")));
        }
        else if (e->Attribute("points") != nullptr)
        {
            std::istringstream points(e->Attribute("points"));
            double x = 0, y = 0;
            char comma = 0;
            while (points >> x >> comma >> y)
                box.extend(Eigen::Vector2d(x, y));
        }
        for (const tinyxml2::XMLElement *child = e->FirstChildElement(); child != nullptr;
             child = child->NextSiblingElement())
            if (std::string(child->Name()) != "title")
                box.extend(pixelBox(child));
        return box;
    }

    /** The side view's pixels to world (x, z) metres, measured on the floor of KUKA TABLE, a slab
        from x -1 to 1 whose top is at z -0.01 (independent of the writer's own mapping). */
    struct SideScale
    {
        explicit SideScale(const tinyxml2::XMLElement *sideView)
        {
            const tinyxml2::XMLElement *floor = named(byClassIn(sideView, "obstacle"), "floor");
            EXPECT_NE(floor, nullptr);
            if (floor == nullptr)
                return;
            const Eigen::AlignedBox2d box = pixelBox(floor);
            perMetre = box.sizes().x() / 2.0;
            left = box.min().x();
            floorTop = box.min().y();
        }
        /** World (x, z) of a pixel. */
        Eigen::Vector2d world(const Eigen::Vector2d &pixel) const
        {
            return {-1.0 + (pixel.x() - left) / perMetre, -0.01 + (floorTop - pixel.y()) / perMetre};
        }
        double perMetre{1.0};
        double left{0.0};
        double floorTop{0.0};
    };

    /** The world (x, z) box an arm pose covers in the side view. */
    Eigen::AlignedBox2d worldBox(const SideScale &scale, const tinyxml2::XMLElement *pose)
    {
        const Eigen::AlignedBox2d pixels = pixelBox(pose);
        Eigen::AlignedBox2d box;
        box.extend(scale.world(pixels.min())).extend(scale.world(pixels.max()));
        return box;
    }

    /** KUKA TABLE's arm at zero seen from the side (robots/kuka_lwr.urdf): the palm, 0.22 m along x,
        is its widest part; the base's cylinder starts at z 0 and the fingers end 1.10 + 0.245 + 0.05 m up. */
    void expectArmStraightUp(const SideScale &scale, const tinyxml2::XMLElement *pose, double tolerance)
    {
        const Eigen::AlignedBox2d box = worldBox(scale, pose);
        EXPECT_NEAR(box.min().x(), -0.11, tolerance);
        EXPECT_NEAR(box.max().x(), 0.11, tolerance);
        EXPECT_NEAR(box.min().y(), 0.0, tolerance);
        EXPECT_NEAR(box.max().y(), 1.395, tolerance);
    }

    Scene kukaTableScene()
    {
        return loadScene(OMPL_MM_SCENES_DIR "/kuka_table.xml");
    }

    std::size_t countStroke(const tinyxml2::XMLDocument &doc, const std::string &colour)
    {
        std::size_t n = 0;
        for (const tinyxml2::XMLElement *e : byClass(doc, "tool-path"))
            if (e->Attribute("stroke", colour.c_str()) != nullptr)
                ++n;
        return n;
    }
}  // namespace

TEST(SceneSvg, SceneOnlyIsWellFormedWithOneElementPerObstacleAndObject)
{
    const Scene scene = mobileBlockedScene();
    const ManipulationSetup setup(scene);
    tinyxml2::XMLDocument doc;
    ASSERT_EQ(doc.Parse(render(setup, nullptr).c_str()), tinyxml2::XML_SUCCESS) << doc.ErrorStr();

    const tinyxml2::XMLElement *svg = doc.RootElement();
    ASSERT_STREQ(svg->Name(), "svg");
    ASSERT_NE(svg->Attribute("viewBox"), nullptr);
    double x = 0, y = 0, w = 0, h = 0;
    ASSERT_EQ(std::sscanf(svg->Attribute("viewBox"), "%lf %lf %lf %lf", &x, &y, &w, &h), 4);
    // the pixel size keeps the viewBox's aspect ratio
    EXPECT_NEAR(svg->DoubleAttribute("width") / svg->DoubleAttribute("height"), w / h, 1e-3);

    const auto starts = byClass(doc, "object-start");
    ASSERT_EQ(starts.size(), 4u);
    for (const tinyxml2::XMLElement *e : starts)
    {
        EXPECT_NE(e->Attribute("stroke-dasharray"), nullptr);
        EXPECT_STREQ(e->Attribute("fill"), "none");
    }
    EXPECT_EQ(byClass(doc, "obstacle").size(), scene.obstacles.size());
    EXPECT_EQ(byClass(doc, "surface").size(), scene.surfaces.size());
    EXPECT_TRUE(byClass(doc, "object-end").empty());
    EXPECT_TRUE(byClass(doc, "tool-path").empty());
    // obj3's goal and the mobile robot's goal position
    EXPECT_EQ(byClass(doc, "goal").size(), 2u);
    EXPECT_EQ(byClass(doc, "robot-start").size(), 1u);
}

TEST(SceneSvg, PathIsColouredByPrimitiveWithAPushArrow)
{
    const ManipulationSetup setup(mobileBlockedScene());
    const ManipulationPath path = pushPath(setup);
    ASSERT_EQ(path.checkLabels(), "");
    const std::string svg = render(setup, &path);
    EXPECT_EQ(svg, render(setup, &path));
    tinyxml2::XMLDocument doc;
    ASSERT_EQ(doc.Parse(svg.c_str()), tinyxml2::XML_SUCCESS) << doc.ErrorStr();

    EXPECT_GE(countStroke(doc, "#1f77b4"), 1u);
    EXPECT_GE(countStroke(doc, "#d62728"), 1u);
    EXPECT_EQ(byClass(doc, "waypoint").size(), 3u);
    EXPECT_EQ(byClass(doc, "object-end").size(), 4u);
    EXPECT_EQ(byClass(doc, "robot-end").size(), 1u);

    const auto arrows = byClass(doc, "push-arrow");
    ASSERT_EQ(arrows.size(), 1u);
    EXPECT_NE(arrows[0]->Attribute("marker-end"), nullptr);
    // obj2 moved 0.4 m towards -x: the arrow points left and stays level
    EXPECT_LT(arrows[0]->DoubleAttribute("x2"), arrows[0]->DoubleAttribute("x1"));
    EXPECT_NEAR(arrows[0]->DoubleAttribute("y2"), arrows[0]->DoubleAttribute("y1"), 1e-9);
    // the arrow runs from obj2's start outline to its end disc
    const tinyxml2::XMLElement *from = named(byClass(doc, "object-start"), "obj2");
    const tinyxml2::XMLElement *to = named(byClass(doc, "object-end"), "obj2");
    ASSERT_NE(from, nullptr);
    ASSERT_NE(to, nullptr);
    EXPECT_NEAR(arrows[0]->DoubleAttribute("x1"), from->DoubleAttribute("cx"), 0.011);
    EXPECT_NEAR(arrows[0]->DoubleAttribute("x2"), to->DoubleAttribute("cx"), 0.011);
}

TEST(SceneSvg, NamesAreEscaped)
{
    Scene scene = mobileBlockedScene();
    scene.name = "a<b & \"c\"";
    scene.objects[0].name = "obj<&>1";
    const ManipulationSetup setup(scene);
    tinyxml2::XMLDocument doc;
    ASSERT_EQ(doc.Parse(render(setup, nullptr).c_str()), tinyxml2::XML_SUCCESS) << doc.ErrorStr();
    EXPECT_NE(named(byClass(doc, "object-start"), "obj<&>1"), nullptr);
    const auto titles = byClass(doc, "title");
    ASSERT_EQ(titles.size(), 1u);
    EXPECT_NE(std::string(titles[0]->GetText()).find("a<b & \"c\""), std::string::npos);
}

TEST(SceneSvg, WorldYIsUpAndTheScaleIsTheSameOnBothAxes)
{
    const Scene scene = mobileBlockedScene();
    const ManipulationSetup setup(scene);
    tinyxml2::XMLDocument doc;
    ASSERT_EQ(doc.Parse(render(setup, nullptr).c_str()), tinyxml2::XML_SUCCESS) << doc.ErrorStr();
    const auto starts = byClass(doc, "object-start");
    const tinyxml2::XMLElement *obj1 = named(starts, "obj1");  // x -2.0, y 0.3
    const tinyxml2::XMLElement *obj2 = named(starts, "obj2");  // x 0.8, y -0.1
    const tinyxml2::XMLElement *obj3 = named(starts, "obj3");  // x -1.5, y -1.5
    const tinyxml2::XMLElement *obj4 = named(starts, "obj4");  // x 1.2, y 1.9
    ASSERT_TRUE(obj1 && obj2 && obj3 && obj4);

    // larger world y is higher in the picture (smaller SVG y); x keeps its direction
    EXPECT_LT(obj4->DoubleAttribute("cy"), obj3->DoubleAttribute("cy"));
    EXPECT_LT(obj1->DoubleAttribute("cx"), obj2->DoubleAttribute("cx"));

    // pixels per metre from x, from y and from the drawn radius agree
    const auto &o = scene.objects;
    const double perMetreX = (obj2->DoubleAttribute("cx") - obj1->DoubleAttribute("cx")) /
                             (o[1].start.position.x() - o[0].start.position.x());
    const double perMetreY = -(obj4->DoubleAttribute("cy") - obj3->DoubleAttribute("cy")) /
                             (o[3].start.position.y() - o[2].start.position.y());
    EXPECT_NEAR(perMetreX, perMetreY, 0.01);
    EXPECT_NEAR(obj1->DoubleAttribute("r") / o[0].shape.radius, perMetreX, 0.05);
}

TEST(SceneSvg, MobileRobotHasTheTopViewAlone)
{
    const ManipulationSetup setup(mobileBlockedScene());
    const ManipulationPath path = pushPath(setup);
    tinyxml2::XMLDocument doc;
    ASSERT_EQ(doc.Parse(render(setup, &path).c_str()), tinyxml2::XML_SUCCESS) << doc.ErrorStr();
    EXPECT_TRUE(byClass(doc, "side-view").empty());
    EXPECT_TRUE(byClass(doc, "caption").empty());
    EXPECT_TRUE(byClass(doc, "arm-pose").empty());
    EXPECT_TRUE(byClass(doc, "carried-path").empty());
    EXPECT_EQ(byClass(doc, "scale-bar").size(), 1u);
    EXPECT_DOUBLE_EQ(doc.RootElement()->DoubleAttribute("width"), 800.0);
}

TEST(SceneSvg, ArmSceneAddsASideViewWithTheArmAtItsStartPose)
{
    const Scene scene = kukaTableScene();
    const ManipulationSetup setup(scene);
    tinyxml2::XMLDocument doc;
    ASSERT_EQ(doc.Parse(render(setup, nullptr).c_str()), tinyxml2::XML_SUCCESS) << doc.ErrorStr();

    const auto captions = byClass(doc, "caption");
    ASSERT_EQ(captions.size(), 2u);
    EXPECT_STREQ(captions[0]->GetText(), "top view (x\u2013y)");
    EXPECT_STREQ(captions[1]->GetText(), "side view (x\u2013z)");
    EXPECT_EQ(byClass(doc, "scale-bar").size(), 2u);
    const auto sideViews = byClass(doc, "side-view");
    ASSERT_EQ(sideViews.size(), 1u);
    const tinyxml2::XMLElement *side = sideViews[0];
    // the side view stands right of the top view
    double dx = 0, dy = 0;
    ASSERT_EQ(std::sscanf(side->Attribute("transform"), "translate(%lf,%lf)", &dx, &dy), 2);
    EXPECT_GT(dx, 100.0);
    EXPECT_LT(dx, doc.RootElement()->DoubleAttribute("width") - 100.0);

    EXPECT_EQ(byClassIn(side, "obstacle").size(), scene.obstacles.size());
    EXPECT_EQ(byClassIn(side, "surface").size(), scene.surfaces.size());
    EXPECT_EQ(byClassIn(side, "object-start").size(), scene.objects.size());
    EXPECT_TRUE(byClassIn(side, "object-end").empty());
    const auto poses = byClassIn(side, "arm-pose");
    ASSERT_EQ(poses.size(), 1u) << "the start alone without a path";
    expectArmStraightUp(SideScale(side), poses[0], 2e-3);

    // table 1's top (0.5 +- 0.27 in x, 0.38 to 0.43 in z), seen from the side
    const tinyxml2::XMLElement *top = named(byClassIn(side, "obstacle"), "table1_top");
    ASSERT_NE(top, nullptr);
    const SideScale scale(side);
    const Eigen::AlignedBox2d pixels = pixelBox(top);
    EXPECT_NEAR(scale.world(pixels.min()).x(), 0.23, 2e-3);
    EXPECT_NEAR(scale.world(pixels.max()).x(), 0.77, 2e-3);
    EXPECT_NEAR(scale.world(pixels.min()).y(), 0.43, 2e-3);
    EXPECT_NEAR(scale.world(pixels.max()).y(), 0.38, 2e-3);
}

TEST(SceneSvg, ArmPathDrawsTheArmAtStartEveryModeSwitchAndEnd)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    const Scene scene = kukaTableScene();
    ompl_core::reseedOmpl(1);
    ManipulationSetup setup(scene);
    setup.mopl()->setSeed(1);
    // far above the few hundred iterations the seed needs, so a regression fails quickly
    ASSERT_EQ(setup.solve(test::moplIterations(setup, 5000)), ompl::base::PlannerStatus::EXACT_SOLUTION);
    const ManipulationPath &path = setup.manipulationPath();
    tinyxml2::XMLDocument doc;
    ASSERT_EQ(doc.Parse(render(setup, &path).c_str()), tinyxml2::XML_SUCCESS) << doc.ErrorStr();
    const auto sideViews = byClass(doc, "side-view");
    ASSERT_EQ(sideViews.size(), 1u);
    const tinyxml2::XMLElement *side = sideViews[0];

    // one pose at the start of each primitive application (a run of equal labels) and one at the end
    const std::map<std::string, unsigned int> counts = path.primitiveCounts();
    const unsigned int runs = std::accumulate(counts.begin(), counts.end(), 0u,
                                              [](unsigned int sum, const auto &c) { return sum + c.second; });
    EXPECT_EQ(runs, 10u) << "3 pickups, 3 transfers and the transits between them";
    const auto poses = byClassIn(side, "arm-pose");
    ASSERT_EQ(poses.size(), runs + 1);
    // the top view draws the arm at the same waypoints
    const auto topViews = byClass(doc, "top-view");
    ASSERT_EQ(topViews.size(), 1u);
    const auto topPoses = byClassIn(topViews[0], "arm-pose");
    ASSERT_EQ(topPoses.size(), poses.size());
    for (std::size_t i = 0; i < poses.size(); ++i)
        EXPECT_EQ(titleOf(topPoses[i]), titleOf(poses[i]));
    EXPECT_EQ(titleOf(poses.front()).rfind("waypoint 0: ", 0), 0u);
    EXPECT_EQ(titleOf(poses.back()), "waypoint " + std::to_string(path.getStateCount() - 1) + ": end");
    // the arm starts and ends at zero (the goal's tolerance: 0.01 rad a joint)
    const SideScale scale(side);
    expectArmStraightUp(scale, poses.front(), 2e-3);
    expectArmStraightUp(scale, poses.back(), 0.03);
    // later poses are drawn more opaque
    for (std::size_t i = 1; i < poses.size(); ++i)
        EXPECT_GT(poses[i]->DoubleAttribute("opacity"), poses[i - 1]->DoubleAttribute("opacity"));

    const std::vector<SegmentLabel> &labels = path.labels();
    EXPECT_EQ(byClassIn(side, "tool-path").size(), labels.size());
    const auto carried = byClassIn(side, "carried-path");
    const std::size_t transfers = static_cast<std::size_t>(
        std::count_if(labels.begin(), labels.end(),
                      [](const SegmentLabel &l) { return l.kind == PrimitiveKind::Transfer; }));
    ASSERT_EQ(carried.size(), transfers);
    // each object's last carried course ends where the object ends, inside its filled outline
    std::map<std::string, Eigen::Vector2d> lastPoint;  // by colour
    for (const tinyxml2::XMLElement *course : carried)
    {
        std::istringstream points(course->Attribute("points"));
        double x = 0, y = 0;
        char comma = 0;
        while (points >> x >> comma >> y)
            lastPoint[course->Attribute("stroke")] = Eigen::Vector2d(x, y);
    }
    ASSERT_EQ(lastPoint.size(), 3u) << "three cylinders carried";
    for (const auto &[colour, at] : lastPoint)
    {
        bool inside = false;
        for (const tinyxml2::XMLElement *end : byClassIn(side, "object-end"))
            inside =
                inside || (end->Attribute("fill", colour.c_str()) != nullptr && pixelBox(end).contains(at));
        EXPECT_TRUE(inside) << colour;
    }
}

namespace
{
    /** The polygons' corners of a group, in pixels. */
    std::vector<std::vector<Eigen::Vector2d>> polygonsIn(const tinyxml2::XMLElement *group)
    {
        std::vector<std::vector<Eigen::Vector2d>> polygons;
        for (const tinyxml2::XMLElement *e = group->FirstChildElement(); e != nullptr;
             e = e->NextSiblingElement())
        {
            if (std::string(e->Name()) != "polygon")
                continue;
            polygons.emplace_back();
            std::istringstream points(e->Attribute("points"));
            double x = 0, y = 0;
            char comma = 0;
            while (points >> x >> comma >> y)
                polygons.back().emplace_back(x, y);
        }
        return polygons;
    }

    /** The label texts' boxes, as LabelLayout estimates them for 12 px text. */
    std::vector<Eigen::AlignedBox2d> labelBoxes(const tinyxml2::XMLDocument &doc)
    {
        const ompl_mm::LabelLayout estimate(
            Eigen::AlignedBox2d(Eigen::Vector2d::Zero(), Eigen::Vector2d::Ones()), 12.0);
        std::vector<Eigen::AlignedBox2d> boxes;
        for (const tinyxml2::XMLElement *label : byClass(doc, "label"))
            boxes.push_back(estimate.textBox(label->GetText(),
                                             {label->DoubleAttribute("x"), label->DoubleAttribute("y")}));
        return boxes;
    }

    void expectApart(const std::vector<Eigen::AlignedBox2d> &boxes)
    {
        for (std::size_t a = 0; a < boxes.size(); ++a)
            for (std::size_t b = a + 1; b < boxes.size(); ++b)
            {
                const Eigen::AlignedBox2d common = boxes[a].intersection(boxes[b]);
                EXPECT_TRUE(common.isEmpty() || common.volume() == 0.0) << "labels " << a << " and " << b;
            }
    }
}  // namespace

TEST(SceneSvg, MeshArmIsDrawnFromAboveByItsLinksConvexHulls)
{
    const ManipulationSetup setup(pandaPickScene());
    tinyxml2::XMLDocument doc;
    ASSERT_EQ(doc.Parse(render(setup, nullptr).c_str()), tinyxml2::XML_SUCCESS) << doc.ErrorStr();
    const auto topViews = byClass(doc, "top-view");
    ASSERT_EQ(topViews.size(), 1u);
    const auto poses = byClassIn(topViews[0], "arm-pose");
    ASSERT_EQ(poses.size(), 1u) << "the start alone without a path";
    const std::vector<std::vector<Eigen::Vector2d>> drawn = polygonsIn(poses[0]);

    // the top view's pixels from the floor, a 2 m square about the origin
    const tinyxml2::XMLElement *floor = named(byClassIn(topViews[0], "obstacle"), "floor");
    ASSERT_NE(floor, nullptr);
    const Eigen::AlignedBox2d floorPixels = pixelBox(floor);
    const double perMetre = floorPixels.sizes().x() / 2.0;
    EXPECT_NEAR(floorPixels.sizes().y() / 2.0, perMetre, 0.02);
    const auto pixelOf = [&](const Eigen::Vector3d &p)
    {
        return Eigen::Vector2d(floorPixels.min().x() + (p.x() + 1.0) * perMetre,
                               floorPixels.min().y() + (1.0 - p.y()) * perMetre);
    };

    // each link mesh at the start is outlined by the hull of all its vertices seen from above: the
    // polygon's box is the box of every vertex (computed here from the mesh, not its hull)
    const RobotModel &robot = setup.model()->robot();
    const ManipulationStateSpace &space = *setup.manipulationSpace();
    std::vector<Eigen::Isometry3d> frames;
    robot.forwardKinematics(space.robotValues(setup.getProblemDefinition()->getStartState(0)),
                            setup.model()->scene().robot.basePose, frames);
    std::size_t k = 0, detailed = 0;
    for (std::size_t l = 0; l < robot.links().size(); ++l)
        for (const LinkShape &shape : robot.links()[l].shapes)
        {
            ASSERT_LT(k, drawn.size());
            ASSERT_EQ(shape.shape.kind, Shape::Kind::Mesh);
            Eigen::AlignedBox2d expected, polygon;
            for (const Eigen::Vector3d &v : shape.shape.mesh->vertices)
                expected.extend(pixelOf(frames[l] * shape.origin * v));
            for (const Eigen::Vector2d &corner : drawn[k])
                polygon.extend(corner);
            EXPECT_LT((polygon.min() - expected.min()).cwiseAbs().maxCoeff(), 0.05) << robot.links()[l].name;
            EXPECT_LT((polygon.max() - expected.max()).cwiseAbs().maxCoeff(), 0.05) << robot.links()[l].name;
            detailed += drawn[k].size() > 8 ? 1 : 0;
            ++k;
        }
    EXPECT_EQ(k, drawn.size()) << "one polygon per link shape";
    EXPECT_GT(detailed, k / 2) << "hulls, not bounding boxes";
}

TEST(SceneSvg, LabelsNeverOverlap)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    for (const Scene &scene : {pandaPickScene(), kukaTableScene()})
    {
        ompl_core::reseedOmpl(1);
        ManipulationSetup setup(scene);
        setup.mopl()->setSeed(1);
        // far above the iterations either seed needs, so a regression fails quickly
        ASSERT_EQ(setup.solve(test::moplIterations(setup, 5000)), ompl::base::PlannerStatus::EXACT_SOLUTION)
            << scene.name;
        tinyxml2::XMLDocument doc;
        ASSERT_EQ(doc.Parse(render(setup, &setup.manipulationPath()).c_str()), tinyxml2::XML_SUCCESS);
        const std::vector<Eigen::AlignedBox2d> boxes = labelBoxes(doc);
        // every goal is named, and the objects where they end (KUKA TABLE: 3, a crowded table)
        EXPECT_GE(boxes.size(), 2 * scene.objectGoals.size()) << scene.name;
        expectApart(boxes);
        // no label covers a goal symbol's centre
        for (const tinyxml2::XMLElement *goal : byClass(doc, "goal"))
        {
            const tinyxml2::XMLElement *ring = goal->FirstChildElement("g")->FirstChildElement("circle");
            const Eigen::Vector2d centre(ring->DoubleAttribute("cx"), ring->DoubleAttribute("cy"));
            for (const Eigen::AlignedBox2d &box : boxes)
                EXPECT_FALSE(box.contains(centre)) << scene.name;
        }
    }
}
