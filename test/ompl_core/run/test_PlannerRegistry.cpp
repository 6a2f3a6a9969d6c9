// Tests for PlannerRegistry: names are unique and non-empty, kept in registration order, and an unknown
// name is an InputError listing the known ones.
#include "ompl_core/run/PlannerRegistry.h"

#include "common/InputErrors.h"

#include <ompl/base/Planner.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/util/Exception.h>

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

using namespace ompl_core;
using ompl_core::test::exceptionOf;
using ompl_core::test::inputErrorOf;

namespace
{
    /** A planner that plans nothing. */
    class IdlePlanner : public ompl::base::Planner
    {
    public:
        IdlePlanner(const ompl::base::SpaceInformationPtr &si, const std::string &name) : Planner(si, name) {}

        ompl::base::PlannerStatus solve(const ompl::base::PlannerTerminationCondition &) override
        {
            return ompl::base::PlannerStatus::ABORT;
        }
    };

    /** What the registry's factories build planners for; counts the planners made. */
    struct TinySetup
    {
        ompl::base::SpaceInformationPtr si;
        int made{0};
    };

    TinySetup tinySetup()
    {
        auto space = std::make_shared<ompl::base::RealVectorStateSpace>(2);
        space->setBounds(0.0, 1.0);
        return {std::make_shared<ompl::base::SpaceInformation>(space), 0};
    }

    PlannerRegistry<TinySetup>::Factory idle(const std::string &name)
    {
        return [name](TinySetup &setup)
        {
            ++setup.made;
            return std::make_shared<IdlePlanner>(setup.si, name);
        };
    }

}  // namespace

TEST(PlannerRegistry, KeepsRegistrationOrder)
{
    PlannerRegistry<TinySetup> registry;
    EXPECT_EQ(registry.nameList(), "");
    registry.add("zeta", "last letter", idle("Zeta"));
    registry.add("alpha", "first letter", idle("Alpha"));
    EXPECT_EQ(registry.names(), (std::vector<std::string>{"zeta", "alpha"}));
    EXPECT_EQ(registry.nameList(), "zeta, alpha");
    EXPECT_TRUE(registry.has("alpha"));
    EXPECT_FALSE(registry.has("Alpha"));  // case-sensitive
    EXPECT_EQ(registry.description("zeta"), "last letter");
}

TEST(PlannerRegistry, MakesANewPlannerEachTime)
{
    PlannerRegistry<TinySetup> registry;
    registry.add("idle", "plans nothing", idle("Idle"));
    TinySetup setup = tinySetup();
    const ompl::base::PlannerPtr first = registry.make("idle", setup);
    const ompl::base::PlannerPtr second = registry.make("idle", setup);
    ASSERT_TRUE(first);
    EXPECT_EQ(first->getName(), "Idle");
    EXPECT_NE(first, second);
    EXPECT_EQ(setup.made, 2);
}

TEST(PlannerRegistry, RejectsAnEmptyOrTakenName)
{
    PlannerRegistry<TinySetup> registry;
    registry.add("rrt", "one", idle("RRT"));
    EXPECT_EQ(exceptionOf([&] { registry.add("", "nameless", idle("X")); }),
              "PlannerRegistry: planner name '' is empty or taken");
    EXPECT_EQ(exceptionOf([&] { registry.add("rrt", "two", idle("X")); }),
              "PlannerRegistry: planner name 'rrt' is empty or taken");
    // the first registration stays; a name differing in case is a new name
    EXPECT_EQ(registry.description("rrt"), "one");
    EXPECT_EQ(exceptionOf([&] { registry.add("RRT", "three", idle("X")); }), "");
    EXPECT_EQ(registry.names(), (std::vector<std::string>{"rrt", "RRT"}));
}

TEST(PlannerRegistry, UnknownNameListsTheKnownOnes)
{
    PlannerRegistry<TinySetup> registry;
    registry.add("rrt", "one", idle("RRT"));
    registry.add("est", "two", idle("EST"));
    TinySetup setup = tinySetup();
    EXPECT_EQ(inputErrorOf([&] { registry.make("rrtstar", setup); }),
              "unknown planner 'rrtstar' (known: rrt, est)");
    EXPECT_EQ(inputErrorOf([&] { registry.description("Rrt"); }), "unknown planner 'Rrt' (known: rrt, est)");
    EXPECT_EQ(setup.made, 0);
    // an empty registry lists nothing
    const PlannerRegistry<TinySetup> empty;
    EXPECT_EQ(inputErrorOf([&] { empty.description("rrt"); }), "unknown planner 'rrt' (known: )");
}
