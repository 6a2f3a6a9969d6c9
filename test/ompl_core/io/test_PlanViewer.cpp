// Tests for writePlanViewerPage, threeJsFolder and requireThreeJs: the page inlines three.js, its
// OrbitControls and the viewer; the title and legend are HTML-escaped; the plan data is JSON with
// numbers to 0.1 mm and 1e-5 of a quaternion, and nothing in it can end its <script> element; a
// missing three.js is an InputError that names the file and the package; shared meshes are written
// once, in whole tenths of a millimetre, and solids may have colours of their own.
#include "ompl_core/io/PlanViewer.h"

#include "common/InputErrors.h"
#include "common/ScratchDirectory.h"

// the JSON reader uses the global placeholders of the deprecated <boost/bind.hpp>: keep them, quietly
#define BOOST_BIND_GLOBAL_PLACEHOLDERS
#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

using namespace ompl_core;
using ompl_core::test::contains;
using ompl_core::test::inputErrorOf;

namespace
{
    /** Debian's libjs-three folder, threeJsFolder()'s default. */
    const std::string DEBIAN_THREE_JS_DIR = "/usr/share/javascript/three";
    const std::string ENV_NAME = "OMPL_MM_THREE_JS_DIR";
    const std::string PLAN_DATA_OPEN = "<script type=\"application/json\" id=\"plan-data\">";

    /** Sets (or, with nullopt, unsets) OMPL_MM_THREE_JS_DIR and restores its old value when destroyed. */
    class ScopedThreeJsDir
    {
    public:
        explicit ScopedThreeJsDir(const std::optional<std::string> &value)
        {
            if (const char *old = std::getenv(ENV_NAME.c_str()))
                old_ = old;
            if (value)
                setenv(ENV_NAME.c_str(), value->c_str(), 1);
            else
                unsetenv(ENV_NAME.c_str());
        }
        ~ScopedThreeJsDir()
        {
            if (old_)
                setenv(ENV_NAME.c_str(), old_->c_str(), 1);
            else
                unsetenv(ENV_NAME.c_str());
        }
        ScopedThreeJsDir(const ScopedThreeJsDir &) = delete;
        ScopedThreeJsDir &operator=(const ScopedThreeJsDir &) = delete;

    private:
        std::optional<std::string> old_;
    };

    std::string fileText(const std::string &path)
    {
        std::ifstream in(path, std::ios::binary);
        std::ostringstream text;
        text << in.rdbuf();
        return text.str();
    }

    ViewerSolid box(const Eigen::Vector3d &size, const Eigen::Isometry3d &pose)
    {
        ViewerSolid solid;
        solid.kind = ViewerSolid::Kind::Box;
        solid.size = size;
        solid.pose = pose;
        return solid;
    }

    Eigen::Isometry3d yawPose(double x, double y, double z, double yaw)
    {
        return Eigen::Translation3d(x, y, z) * Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ());
    }

    /** A fixed box and a fixed mesh wedge, a goal disc, one moving sphere, 3 frames, 2 segments. */
    ViewerPlan smallPlan()
    {
        ViewerPlan plan;
        plan.title = "Plan <b>& co";
        plan.frameStep = 0.07;
        // the table's numbers test the rounding: 0.123456 -> 0.1235, 2.0 -> 2, -0.00001 -> 0
        plan.fixed.push_back({"table",
                              "#8c564b",
                              1.0,
                              {box(Eigen::Vector3d(1.0, 0.5, 0.123456),
                                   Eigen::Isometry3d(Eigen::Translation3d(0.123456, 2.0, -0.00001)))}});
        ViewerSolid wedge;
        wedge.kind = ViewerSolid::Kind::Mesh;
        wedge.vertices = {{0.0, 0.0, -0.1}, {0.2, 0.0, -0.1}, {0.0, 0.2, -0.1},
                          {0.0, 0.0, 0.1},  {0.2, 0.0, 0.1},  {0.0, 0.2, 0.1}};
        wedge.triangles = {{0, 2, 1}, {3, 4, 5}};
        plan.fixed.push_back({"wedge", "#666666", 1.0, {wedge}});

        ViewerSolid disc;
        disc.kind = ViewerSolid::Kind::Cylinder;
        disc.radius = 0.05;
        disc.length = 0.004;
        disc.pose = Eigen::Translation3d(0.92, -1.0, 0.002);
        plan.goals.push_back({"goal", "#2ca02c", 0.3, {disc}});

        ViewerSolid sphere;
        sphere.kind = ViewerSolid::Kind::Sphere;
        sphere.radius = 0.08;
        plan.moving.push_back({"robot</script>", "#1f77b4", 1.0, {sphere}});

        // frame 1 turns the sphere by 30 degrees: q = (0, 0, sin 15deg, cos 15deg)
        plan.frames = {{yawPose(0.0, 0.0, 0.08, 0.0)},
                       {yawPose(0.5, 0.25, 0.08, M_PI / 6)},
                       {yawPose(1.0, 0.5, 0.08, M_PI / 2)}};
        plan.toolPath = {{0.0, 0.0, 0.08}, {0.5, 0.25, 0.08}, {1.0, 0.5, 0.08}};
        plan.segments = {{0, 1, "transit", "#1f77b4"}, {1, 2, "push obj3", "#d62728"}};
        plan.tracks = {0};
        plan.legend = {{"robot", "#1f77b4"}, {"push <obj>", "#d62728"}};
        return plan;
    }

    std::string page(const ViewerPlan &plan)
    {
        std::ostringstream out;
        writePlanViewerPage(out, plan);
        return out.str();
    }

    /** The text between the plan-data tags (up to the first "</script>" after the opening tag, where a
        browser would end the element), or "" when there is no such element. */
    std::string planData(const std::string &html)
    {
        const std::size_t open = html.find(PLAN_DATA_OPEN);
        if (open == std::string::npos)
            return "";
        const std::size_t from = open + PLAN_DATA_OPEN.size();
        const std::size_t close = html.find("</script>", from);
        return close == std::string::npos ? "" : html.substr(from, close - from);
    }

    boost::property_tree::ptree parsed(const std::string &json)
    {
        std::istringstream in(json);
        boost::property_tree::ptree tree;
        boost::property_tree::read_json(in, tree);
        return tree;
    }

    /** The texts of an array's elements (numbers as written). */
    std::vector<std::string> texts(const boost::property_tree::ptree &array)
    {
        std::vector<std::string> values;
        for (const auto &child : array)
            values.push_back(child.second.data());
        return values;
    }

    /** Element i of an array. */
    const boost::property_tree::ptree &at(const boost::property_tree::ptree &array, std::size_t i)
    {
        auto it = array.begin();
        std::advance(it, static_cast<long>(i));
        return it->second;
    }

    class PlanViewerPage : public ::testing::Test
    {
    protected:
        void SetUp() override
        {
            html_ = page(smallPlan());
            json_ = planData(html_);
            ASSERT_FALSE(json_.empty()) << "no plan-data element";
            ASSERT_NO_THROW(tree_ = parsed(json_)) << json_;
        }

        ScopedThreeJsDir debian_{DEBIAN_THREE_JS_DIR};
        std::string html_;
        std::string json_;
        boost::property_tree::ptree tree_;
    };
}  // namespace

TEST_F(PlanViewerPage, InlinesThreeJsOrbitControlsAndTheViewerScript)
{
    EXPECT_TRUE(contains(html_, "REVISION"));
    // the libraries verbatim (neither contains "</script"), each in a <script> element of its own
    EXPECT_TRUE(contains(html_, "<script>" + fileText(DEBIAN_THREE_JS_DIR + "/three.min.js") + "</script>"));
    EXPECT_TRUE(contains(
        html_,
        "<script>" + fileText(DEBIAN_THREE_JS_DIR + "/examples/js/controls/OrbitControls.js") + "</script>"));
    EXPECT_TRUE(contains(html_, "OrbitControls"));
    EXPECT_TRUE(contains(html_, "JSON.parse(document.getElementById('plan-data').textContent)"));
    // no placeholder is left
    for (const char *placeholder :
         {"@TITLE@", "@LEGEND@", "@PLAN@", "@THREE@", "@ORBIT_CONTROLS@", "@VIEWER@"})
        EXPECT_FALSE(contains(html_, placeholder)) << placeholder;
    // the data comes before the libraries, the libraries before the viewer that uses them
    const std::size_t data = html_.find(PLAN_DATA_OPEN), three = html_.find("REVISION"),
                      viewer = html_.find("JSON.parse(document.getElementById('plan-data')");
    EXPECT_LT(data, three);
    EXPECT_LT(three, viewer);
}

TEST_F(PlanViewerPage, TitleIsHtmlEscapedInTitleAndHeading)
{
    EXPECT_TRUE(contains(html_, "<title>Plan &lt;b&gt;&amp; co</title>"));
    EXPECT_TRUE(contains(html_, "<div id=\"title\">Plan &lt;b&gt;&amp; co</div>"));
    // outside the plan data (a JSON string, where "<b>" is text) the title is never raw HTML
    std::string outside = html_;
    outside.erase(outside.find(json_), json_.size());
    EXPECT_FALSE(contains(outside, "Plan <b>"));
    EXPECT_EQ(tree_.get<std::string>("title"), "Plan <b>& co");
}

TEST_F(PlanViewerPage, LegendLinesAreEscapedWithTheirColours)
{
    EXPECT_TRUE(contains(html_,
                         "<div id=\"legend\"><div><span style=\"background:#1f77b4\"></span>robot</div>"
                         "<div><span style=\"background:#d62728\"></span>push &lt;obj&gt;</div></div>"));
}

TEST_F(PlanViewerPage, PlanDataHasEveryPartWithItsCount)
{
    EXPECT_EQ(tree_.get<std::string>("frameStep"), "0.07");
    EXPECT_EQ(tree_.get_child("fixed").size(), 2u);
    EXPECT_EQ(tree_.get_child("goals").size(), 1u);
    EXPECT_EQ(tree_.get_child("moving").size(), 1u);
    const auto &frames = tree_.get_child("frames");
    ASSERT_EQ(frames.size(), 3u);
    for (const auto &frame : frames)
    {
        ASSERT_EQ(frame.second.size(), 1u) << "a pose per moving body";
        EXPECT_EQ(at(frame.second, 0).size(), 7u) << "x, y, z, qx, qy, qz, qw";
    }
    const auto &toolPath = tree_.get_child("toolPath");
    ASSERT_EQ(toolPath.size(), 3u);
    EXPECT_EQ(texts(at(toolPath, 1)), (std::vector<std::string>{"0.5", "0.25", "0.08"}));
    EXPECT_EQ(tree_.get_child("segments").size(), 2u);
    EXPECT_EQ(tree_.get_child("tracks").size(), 1u);
}

TEST_F(PlanViewerPage, PositionsHaveAtMostFourDecimalsAndNoNegativeZero)
{
    // 0.123456 -> 0.1235, 2.0 -> 2, -0.00001 -> 0; identity rotation -> 0,0,0,1
    EXPECT_TRUE(contains(json_,
                         "{\"name\":\"table\",\"colour\":\"#8c564b\",\"opacity\":1,\"solids\":["
                         "{\"pose\":[0.1235,2,0,0,0,0,1],\"kind\":\"box\",\"size\":[1,0.5,0.1235]}]}"))
        << json_;
    const auto &table = at(tree_.get_child("fixed"), 0);
    EXPECT_EQ(texts(at(table.get_child("solids"), 0).get_child("pose")),
              (std::vector<std::string>{"0.1235", "2", "0", "0", "0", "0", "1"}));
}

TEST_F(PlanViewerPage, QuaternionComponentsHaveFiveDecimals)
{
    // 30 degrees about z: sin 15deg = 0.258819..., cos 15deg = 0.965925...
    EXPECT_EQ(texts(at(at(tree_.get_child("frames"), 1), 0)),
              (std::vector<std::string>{"0.5", "0.25", "0.08", "0", "0", "0.25882", "0.96593"}));
    // 90 degrees: sin 45deg = cos 45deg = 0.7071067...
    EXPECT_EQ(texts(at(at(tree_.get_child("frames"), 2), 0)),
              (std::vector<std::string>{"1", "0.5", "0.08", "0", "0", "0.70711", "0.70711"}));
}

TEST_F(PlanViewerPage, SegmentsKeepFirstLastLabelAndColour)
{
    EXPECT_TRUE(
        contains(json_,
                 "\"segments\":[{\"first\":0,\"last\":1,\"label\":\"transit\",\"colour\":\"#1f77b4\"},"
                 "{\"first\":1,\"last\":2,\"label\":\"push obj3\",\"colour\":\"#d62728\"}]"))
        << json_;
    const auto &second = at(tree_.get_child("segments"), 1);
    EXPECT_EQ(second.get<std::string>("first"), "1");
    EXPECT_EQ(second.get<std::string>("last"), "2");
    EXPECT_EQ(second.get<std::string>("label"), "push obj3");
    EXPECT_EQ(second.get<std::string>("colour"), "#d62728");
}

TEST_F(PlanViewerPage, TracksNameTheBodyAndTakeItsColour)
{
    EXPECT_TRUE(contains(json_, "\"tracks\":[{\"body\":0,\"colour\":\"#1f77b4\"}]")) << json_;
}

TEST_F(PlanViewerPage, SolidsOfEachKindWriteTheirFields)
{
    EXPECT_TRUE(contains(json_,
                         "{\"pose\":[0,0,0,0,0,0,1],\"kind\":\"mesh\",\"vertices\":[0,0,-0.1,0.2,0,-0.1,0,"
                         "0.2,-0.1,0,0,0.1,0.2,0,0.1,0,0.2,0.1],\"triangles\":[0,2,1,3,4,5]}"))
        << json_;
    EXPECT_TRUE(contains(json_,
                         "{\"name\":\"goal\",\"colour\":\"#2ca02c\",\"opacity\":0.3,\"solids\":[{\"pose\":"
                         "[0.92,-1,0.002,0,0,0,1],\"kind\":\"cylinder\",\"radius\":0.05,\"length\":0.004}]}"))
        << json_;
    EXPECT_TRUE(contains(json_, "\"kind\":\"sphere\",\"radius\":0.08}")) << json_;
}

TEST_F(PlanViewerPage, ScriptEndInANameCannotEndThePlanDataElement)
{
    EXPECT_TRUE(contains(json_, "\"name\":\"robot<\\/script>\"")) << json_;
    EXPECT_FALSE(contains(json_, "</")) << json_;
    // the element ends right where the libraries begin, and the JSON gives the name back unchanged
    EXPECT_TRUE(contains(html_, json_ + "</script>\n<script>"));
    EXPECT_EQ(at(tree_.get_child("moving"), 0).get<std::string>("name"), "robot</script>");
}

// Disabled: fails (a bug of PlanViewer.cpp, reported, not fixed here). writePlanViewerPage puts the
// escaped title and legend into the page first, then replaces the first "@PLAN@" it finds, which is
// the one in the title or legend: the JSON lands there, and the plan-data element keeps the text
// "@PLAN@", so the viewer's JSON.parse fails. Titles hold scene names from scene files. Enable with
// the fix.
TEST(PlanViewer, PlaceholderTextInTitleOrLegendStaysText)
{
    const ScopedThreeJsDir debian(DEBIAN_THREE_JS_DIR);
    ViewerPlan plan = smallPlan();
    plan.title = "@PLAN@";
    std::string html = page(plan);
    EXPECT_TRUE(contains(html, "<title>@PLAN@</title>"));
    EXPECT_NO_THROW(parsed(planData(html))) << planData(html).substr(0, 200);

    plan = smallPlan();
    plan.legend = {{"@PLAN@", "#000000"}};
    html = page(plan);
    EXPECT_TRUE(contains(html, "<span style=\"background:#000000\"></span>@PLAN@</div>"));
    EXPECT_NO_THROW(parsed(planData(html))) << planData(html).substr(0, 200);
}

TEST(PlanViewer, ThreeJsFolderIsTheEnvironmentVariableWhenSet)
{
    const ScopedThreeJsDir custom(std::string("/opt/some/three"));
    EXPECT_EQ(threeJsFolder(), "/opt/some/three");
}

TEST(PlanViewer, ThreeJsFolderIsDebiansWithoutTheEnvironmentVariable)
{
    {
        const ScopedThreeJsDir unset(std::nullopt);
        EXPECT_EQ(threeJsFolder(), DEBIAN_THREE_JS_DIR);
    }
    const ScopedThreeJsDir empty(std::string(""));
    EXPECT_EQ(threeJsFolder(), DEBIAN_THREE_JS_DIR) << "an empty value counts as unset";
}

TEST(PlanViewer, MissingThreeJsThrowsNamingTheFileAndThePackage)
{
    const std::filesystem::path empty = ompl_core::test::scratchDirectory("test_PlanViewer_empty");
    const ScopedThreeJsDir custom(empty.string());
    const std::string missing = (empty / "three.min.js").string();

    const std::string required = inputErrorOf([] { requireThreeJs(); });
    EXPECT_TRUE(contains(required, missing)) << required;
    EXPECT_TRUE(contains(required, "libjs-three")) << required;

    std::ostringstream out;
    const std::string written = inputErrorOf([&] { writePlanViewerPage(out, smallPlan()); });
    EXPECT_TRUE(contains(written, missing)) << written;
    EXPECT_TRUE(contains(written, "libjs-three")) << written;
    EXPECT_TRUE(out.str().empty()) << "nothing is written before the check";
}

TEST(PlanViewer, MissingOrbitControlsThrowsNamingItsFile)
{
    const std::filesystem::path folder = ompl_core::test::scratchDirectory("test_PlanViewer_no_controls");
    std::ofstream(folder / "three.min.js") << "var THREE = {REVISION: '0'};\n";
    const ScopedThreeJsDir custom(folder.string());
    const std::string message = inputErrorOf([] { requireThreeJs(); });
    EXPECT_TRUE(contains(message, (folder / "examples/js/controls/OrbitControls.js").string())) << message;
    EXPECT_TRUE(contains(message, "libjs-three")) << message;
}

TEST(PlanViewer, ScriptEndInsideALibraryIsEscaped)
{
    // a library that contains "</script" must not end its element early
    const std::filesystem::path folder = ompl_core::test::scratchDirectory("test_PlanViewer_script_end");
    std::filesystem::create_directories(folder / "examples/js/controls");
    std::ofstream(folder / "three.min.js") << "var THREE = {REVISION: '0', s: '</script>'};\n";
    std::ofstream(folder / "examples/js/controls/OrbitControls.js") << "THREE.OrbitControls = 1;\n";
    const ScopedThreeJsDir custom(folder.string());
    const std::string html = page(smallPlan());
    EXPECT_TRUE(contains(html, "<script>var THREE = {REVISION: '0', s: '<\\/script>'};\n</script>"));
    EXPECT_TRUE(contains(html, "<script>THREE.OrbitControls = 1;\n</script>"));
}

TEST(PlanViewer, SharedMeshesAreWrittenOnceInTenthsOfAMillimetre)
{
    const ScopedThreeJsDir debian(DEBIAN_THREE_JS_DIR);
    auto wedge = std::make_shared<ViewerMesh>();
    wedge->vertices = {{0.0, 0.0, 0.0}, {0.12346, -0.00004, 0.0}, {0.0, 0.2, -1.00006}};
    wedge->triangles = {{0, 1, 2}};
    ViewerSolid a;
    a.kind = ViewerSolid::Kind::Mesh;
    a.mesh = wedge;
    a.colour = "#404040";
    ViewerSolid b = a;
    b.colour.clear();
    b.pose = Eigen::Translation3d(1.0, 0.0, 0.0);
    ViewerPlan plan = smallPlan();
    plan.moving.push_back({"link", "#ffffff", 1.0, {a, b}});
    plan.goals.push_back({"goal link", "#ffffff", 0.3, {b}});
    for (auto &frame : plan.frames)
        frame.push_back(Eigen::Isometry3d::Identity());
    const std::string json = planData(page(plan));
    const boost::property_tree::ptree tree = parsed(json);
    EXPECT_EQ(tree.get<std::string>("meshUnit"), "0.0001");
    const auto &meshes = tree.get_child("meshes");
    ASSERT_EQ(meshes.size(), 1u) << "three uses, one mesh";
    // 0.12346 -> 1235 (rounded to nearest), -0.00004 -> 0, -1.00006 -> -10001
    EXPECT_EQ(texts(at(meshes, 0).get_child("vertices")),
              (std::vector<std::string>{"0", "0", "0", "1235", "0", "0", "0", "2000", "-10001"}));
    EXPECT_EQ(texts(at(meshes, 0).get_child("triangles")), (std::vector<std::string>{"0", "1", "2"}));
    const auto &solids = at(tree.get_child("moving"), 1).get_child("solids");
    ASSERT_EQ(solids.size(), 2u);
    EXPECT_EQ(at(solids, 0).get<std::string>("mesh"), "0");
    EXPECT_EQ(at(solids, 0).get<std::string>("colour"), "#404040");
    EXPECT_EQ(at(solids, 1).count("colour"), 0u) << "the body's colour";
    EXPECT_EQ(at(at(tree.get_child("goals"), 1).get_child("solids"), 0).get<std::string>("mesh"), "0");
    // the inline wedge of the small plan keeps its own vertices
    EXPECT_TRUE(contains(json, "\"kind\":\"mesh\",\"vertices\":[0,0,-0.1,")) << json;
}
