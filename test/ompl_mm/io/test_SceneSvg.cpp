// Tests for writeSceneSvg.
#include <gtest/gtest.h>
#include <tinyxml2.h>

#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "ompl_mm/io/SceneSvg.h"

#include "common/MobileBlocked.h"

#include <ompl/base/ScopedState.h>

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
