// Tests for writePhysicsSceneSvg on the small scene with a re-simulation made by hand (the robot
// moves 0.5 m along x in 5 steps and pushes the first body 0.2 m): the robot's simulated track is
// drawn from the start circle to the end circle through every step, a moved body's track likewise;
// without a simulation neither track is drawn.
#include "ompl_phys/io/PhysicsSceneSvg.h"

#include "ompl_phys/common/PhysicsTestSupport.h"
#include "ompl_phys/control/PathSimulation.h"
#include "ompl_phys/io/PhysicsColours.h"

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

using namespace ompl_phys;
using namespace ompl_phys::test;

namespace
{
    using Points = std::vector<Eigen::Vector2d>;

    /** The text of attribute name in the element that starts at `at` of svg ("" when absent). */
    std::string attribute(const std::string &svg, std::size_t at, const std::string &name)
    {
        const std::size_t end = svg.find('>', at);
        const std::size_t found = svg.find(" " + name + "=\"", at);
        if (found == std::string::npos || found > end)
            return "";
        const std::size_t first = found + name.size() + 3;
        return svg.substr(first, svg.find('"', first) - first);
    }

    /** The points of every polyline of svg stroked in colour. */
    std::vector<Points> polylines(const std::string &svg, const std::string &colour)
    {
        std::vector<Points> found;
        for (std::size_t at = svg.find("<polyline "); at != std::string::npos;
             at = svg.find("<polyline ", at + 1))
        {
            if (attribute(svg, at, "stroke") != colour)
                continue;
            Points points;
            std::istringstream list(attribute(svg, at, "points"));
            double x, y;
            char comma;
            while (list >> x >> comma >> y)
                points.emplace_back(x, y);
            found.push_back(points);
        }
        return found;
    }

    /** The centre of the first circle of svg whose fill is fill and stroke is stroke ("" for none). */
    Eigen::Vector2d circleCentre(const std::string &svg, const std::string &fill, const std::string &stroke)
    {
        for (std::size_t at = svg.find("<circle "); at != std::string::npos;
             at = svg.find("<circle ", at + 1))
            if (attribute(svg, at, "fill") == fill && attribute(svg, at, "stroke") == stroke)
                return Eigen::Vector2d(std::stod(attribute(svg, at, "cx")),
                                       std::stod(attribute(svg, at, "cy")));
        ADD_FAILURE() << "no circle of fill " << fill << " and stroke " << stroke;
        return Eigen::Vector2d::Zero();
    }

    class PhysicsSvg : public ::testing::Test
    {
    protected:
        PhysicsSvg() : setup_(smallScene())
        {
            const BodyStates start = setup_.world().startStates();
            for (int step = 0; step <= STEPS; ++step)
            {
                BodyStates states = start;
                states[0].position.x() += 0.1 * step;
                states[1].position.x() += 0.04 * step;
                simulated_.states.push_back(states);
                simulated_.robot.positions.push_back(states[0].position);
            }
            simulated_.robot.stepDuration = 0.05;
        }

        std::string svg(const SimulatedPath *simulated)
        {
            std::ostringstream out;
            writePhysicsSceneSvg(out, setup_, simulated, "test");
            return out.str();
        }

        static constexpr int STEPS = 5;
        PhysicsSetup setup_;
        SimulatedPath simulated_;
    };
}  // namespace

TEST_F(PhysicsSvg, TheSimulatedRobotTrackRunsFromTheStartCircleToTheEndCircleThroughEveryStep)
{
    const std::string picture = svg(&simulated_);
    const std::vector<Points> tracks = polylines(picture, ROBOT_COLOUR);
    ASSERT_EQ(tracks.size(), 1u) << picture;
    const Points &track = tracks[0];
    ASSERT_EQ(track.size(), STEPS + 1u);
    const Eigen::Vector2d start = circleCentre(picture, "none", ROBOT_COLOUR);
    const Eigen::Vector2d end = circleCentre(picture, ROBOT_COLOUR, "");
    EXPECT_LT((track.front() - start).norm(), 0.01)
        << track.front().transpose() << " vs " << start.transpose();
    EXPECT_LT((track.back() - end).norm(), 0.01) << track.back().transpose() << " vs " << end.transpose();
    EXPECT_GT((end - start).norm(), 10.0) << "the robot moved 0.5 m";
    for (int step = 1; step < STEPS; ++step)  // evenly along the way
        EXPECT_LT((track[step] - (start + (end - start) * step / STEPS)).norm(), 0.01) << step;
}

TEST_F(PhysicsSvg, AMovedBodysTrackIsDrawnInItsColour)
{
    const std::vector<Points> tracks = polylines(svg(&simulated_), bodyColour(0));
    ASSERT_EQ(tracks.size(), 1u);
    EXPECT_EQ(tracks[0].size(), STEPS + 1u);
    EXPECT_GT((tracks[0].back() - tracks[0].front()).norm(), 4.0) << "the body moved 0.2 m";
}

TEST_F(PhysicsSvg, WithoutASimulationNoTrackIsDrawn)
{
    const std::string picture = svg(nullptr);
    EXPECT_TRUE(polylines(picture, ROBOT_COLOUR).empty());
    EXPECT_TRUE(polylines(picture, bodyColour(0)).empty());
}
