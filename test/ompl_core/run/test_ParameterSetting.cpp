// Tests for ParameterSetting: "NAME=VALUE" options, applying settings through a planner's declared
// parameters (unknown names, rejected values with the range and the reason), and describing them.
#include "ompl_core/run/ParameterSetting.h"

#include "common/InputErrors.h"

#include <ompl/base/Planner.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/util/Console.h>
#include <ompl/util/Exception.h>

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

using namespace ompl_core;
using ompl_core::test::contains;
using ompl_core::test::inputErrorOf;
using ompl_core::test::startsWith;

namespace
{
    /** A planner that only declares parameters: range (double, with a range suggestion), steps (int,
        no suggestion; its setter throws for a negative value), mode (a string whose setter rejects
        anything but "fast" and "slow" with std::invalid_argument, which OMPL turns into "not set"),
        count (unsigned int in 0:1:100), level (unsigned int from the list 1,2,4) and flag (bool). */
    class TinyPlanner : public ompl::base::Planner
    {
    public:
        explicit TinyPlanner(const ompl::base::SpaceInformationPtr &si) : Planner(si, "Tiny")
        {
            declareParam<double>("range", this, &TinyPlanner::setRange, &TinyPlanner::getRange, "0.:1.:10.");
            params().declareParam<int>(
                "steps",
                [this](int steps)
                {
                    if (steps < 0)
                        throw ompl::Exception("steps must not be negative");
                    steps_ = steps;
                },
                [this] { return steps_; });
            params().declareParam<std::string>(
                "mode",
                [this](const std::string &mode)
                {
                    if (mode != "fast" && mode != "slow")
                        throw std::invalid_argument("unknown mode");
                    mode_ = mode;
                },
                [this] { return mode_; });
            params().declareParam<unsigned int>(
                "count", [this](unsigned int count) { count_ = count; }, [this] { return count_; });
            params()["count"].setRangeSuggestion("0:1:100");
            params().declareParam<unsigned int>(
                "level", [this](unsigned int level) { level_ = level; }, [this] { return level_; });
            params()["level"].setRangeSuggestion("1,2,4");
            params().declareParam<bool>(
                "flag", [this](bool flag) { flag_ = flag; }, [this] { return flag_; });
        }

        void setRange(double range) { range_ = range; }
        double getRange() const { return range_; }
        int steps() const { return steps_; }
        const std::string &mode() const { return mode_; }
        unsigned int count() const { return count_; }
        unsigned int level() const { return level_; }
        bool flag() const { return flag_; }

        ompl::base::PlannerStatus solve(const ompl::base::PlannerTerminationCondition &) override
        {
            return ompl::base::PlannerStatus::ABORT;
        }

    private:
        double range_{0.5};
        int steps_{3};
        std::string mode_{"fast"};
        unsigned int count_{7};
        unsigned int level_{1};
        bool flag_{false};
    };

    ompl::base::SpaceInformationPtr plane()
    {
        auto space = std::make_shared<ompl::base::RealVectorStateSpace>(2);
        space->setBounds(0.0, 1.0);
        return std::make_shared<ompl::base::SpaceInformation>(space);
    }

    /** Settings placed at lines of "s.xml". */
    ParameterSetting at(int line, const std::string &name, const std::string &value)
    {
        return {name, value, SourceLocation{"s.xml", line}};
    }

    /** Silences OMPL's warnings about rejected values for the lifetime of the object. */
    struct QuietOmpl
    {
        QuietOmpl() : level(ompl::msg::getLogLevel()) { ompl::msg::setLogLevel(ompl::msg::LOG_NONE); }
        ~QuietOmpl() { ompl::msg::setLogLevel(level); }
        ompl::msg::LogLevel level;
    };
}  // namespace

// --- parseParameterOption --------------------------------------------------------------------------------

TEST(ParseParameterOption, SplitsAtTheFirstEquals)
{
    const ParameterSetting s = parseParameterOption("range=0.5");
    EXPECT_EQ(s.name, "range");
    EXPECT_EQ(s.value, "0.5");
    EXPECT_EQ(s.where.file, "command line option --param");
    EXPECT_EQ(s.where.line, 0);
    // the value may hold further '=' or be empty
    EXPECT_EQ(parseParameterOption("expr=a=b").value, "a=b");
    EXPECT_EQ(parseParameterOption("flag=").value, "");
    EXPECT_EQ(parseParameterOption("flag=").name, "flag");
}

TEST(ParseParameterOption, RejectsAMissingEqualsOrName)
{
    EXPECT_EQ(inputErrorOf([] { parseParameterOption("range"); }),
              "command line option --param: expected NAME=VALUE, got 'range'");
    EXPECT_EQ(inputErrorOf([] { parseParameterOption("=0.5"); }),
              "command line option --param: expected NAME=VALUE, got '=0.5'");
    EXPECT_EQ(inputErrorOf([] { parseParameterOption(""); }),
              "command line option --param: expected NAME=VALUE, got ''");
    // a one-letter name is a name
    EXPECT_EQ(inputErrorOf([] { parseParameterOption("r=1"); }), "");
}

// --- applyParameters --------------------------------------------------------------------------------------

TEST(ApplyParameters, SetsEachInOrderAndLaterSettingsWin)
{
    TinyPlanner planner(plane());
    applyParameters(planner,
                    {at(1, "range", "2.5"), at(2, "steps", "7"), at(3, "range", "4"), at(4, "mode", "slow")});
    EXPECT_EQ(planner.getRange(), 4.0);
    EXPECT_EQ(planner.steps(), 7);
    EXPECT_EQ(planner.mode(), "slow");
    EXPECT_NO_THROW(applyParameters(planner, {}));
}

TEST(ApplyParameters, UnknownNameListsTheKnownOnes)
{
    TinyPlanner planner(plane());
    EXPECT_EQ(
        inputErrorOf(
            [&] {
                applyParameters(planner, {at(1, "range", "1"), at(4, "rnage", "2")});
            }),
        "s.xml:4: unknown parameter 'rnage' of planner Tiny (known: count, flag, level, mode, range, steps)");
    // the settings before it were applied
    EXPECT_EQ(planner.getRange(), 1.0);
    // from the command line: no line
    EXPECT_EQ(inputErrorOf([&] { applyParameters(planner, {parseParameterOption("Range=1")}); }),
              "command line option --param: unknown parameter 'Range' of planner Tiny (known: count, flag, "
              "level, mode, range, steps)");
}

TEST(ApplyParameters, RejectedValueNamesTheRange)
{
    const QuietOmpl quiet;
    TinyPlanner planner(plane());
    // OMPL cannot convert it (its conversion throws, and its message follows)
    for (const char *value : {"far", ""})
    {
        const std::string message = inputErrorOf([&] { applyParameters(planner, {at(5, "range", value)}); });
        EXPECT_TRUE(startsWith(message, std::string("s.xml:5: bad value '") + value +
                                            "' for parameter 'range' of planner Tiny (range 0.:1.:10.)"))
            << message;
    }
    EXPECT_EQ(planner.getRange(), 0.5);
    // the setter throws std::invalid_argument, which OMPL turns into "not set": no reason to give; and a
    // parameter without a range suggestion gets none in the message
    EXPECT_EQ(inputErrorOf([&] { applyParameters(planner, {at(6, "mode", "medium")}); }),
              "s.xml:6: bad value 'medium' for parameter 'mode' of planner Tiny");
    EXPECT_EQ(planner.mode(), "fast");
}

TEST(ApplyParameters, RejectedValueGivesTheReasonOfAThrowingSetter)
{
    const QuietOmpl quiet;
    TinyPlanner planner(plane());
    EXPECT_EQ(inputErrorOf([&] { applyParameters(planner, {at(7, "steps", "-1")}); }),
              "s.xml:7: bad value '-1' for parameter 'steps' of planner Tiny: steps must not be negative");
    EXPECT_EQ(planner.steps(), 3);
    // just inside: zero is accepted
    EXPECT_EQ(inputErrorOf([&] { applyParameters(planner, {at(7, "steps", "0")}); }), "");
    EXPECT_EQ(planner.steps(), 0);
    // OMPL's conversion throwing something other than std::invalid_argument (out of range for a double)
    const std::string message = inputErrorOf([&] { applyParameters(planner, {at(8, "range", "1e999")}); });
    EXPECT_TRUE(startsWith(
        message, "s.xml:8: bad value '1e999' for parameter 'range' of planner Tiny (range 0.:1.:10.): "))
        << message;
}

TEST(ApplyParameters, ValuesAreCheckedAgainstTheirTypeAndRangeBeforeOMPLConvertsThem)
{
    const QuietOmpl quiet;
    TinyPlanner planner(plane());
    const auto problem = [&](const std::string &name, const std::string &value)
    { return inputErrorOf([&] { applyParameters(planner, {at(9, name, value)}); }); };
    // OMPL's own conversion would wrap -1 to 4294967295, truncate 1.5 to 1 and read 0x10 or inf
    const struct
    {
        const char *name, *value, *range, *reason;
    } rejected[] = {
        {"count", "-1", " (range 0:1:100)", "out of the range of its type"},
        {"count", "1.5", " (range 0:1:100)", "must be a whole number"},
        {"count", "0x10", " (range 0:1:100)", "not a finite decimal number"},
        {"count", "1e20", " (range 0:1:100)", "out of the range of its type"},
        {"count", "101", " (range 0:1:100)", "out of range"},
        {"range", "inf", " (range 0.:1.:10.)", "not a finite decimal number"},
        {"range", "nan", " (range 0.:1.:10.)", "not a finite decimal number"},
        {"range", "-0.001", " (range 0.:1.:10.)", "out of range"},
        {"range", "10.001", " (range 0.:1.:10.)", "out of range"},
        {"level", "3", " (range 1,2,4)", "must be one of 1,2,4"},
        {"flag", "2", "", "must be 0 or 1 (or true/false)"},
    };
    for (const auto &bad : rejected)
        EXPECT_EQ(problem(bad.name, bad.value), std::string("s.xml:9: bad value '") + bad.value +
                                                    "' for parameter '" + bad.name + "' of planner Tiny" +
                                                    bad.range + ": " + bad.reason);
    EXPECT_EQ(planner.count(), 7u);
    EXPECT_EQ(planner.getRange(), 0.5);
    EXPECT_EQ(planner.level(), 1u);
    // just inside: both bounds, a whole number written as a real, a listed value, true
    EXPECT_EQ(problem("count", "100"), "");
    EXPECT_EQ(planner.count(), 100u);
    EXPECT_EQ(problem("count", "1e1"), "");
    EXPECT_EQ(planner.count(), 10u);
    EXPECT_EQ(problem("count", "0"), "");
    EXPECT_EQ(planner.count(), 0u);
    EXPECT_EQ(problem("range", "10"), "");
    EXPECT_EQ(planner.getRange(), 10.0);
    EXPECT_EQ(problem("range", "0"), "");
    EXPECT_EQ(planner.getRange(), 0.0);
    EXPECT_EQ(problem("level", "4"), "");
    EXPECT_EQ(planner.level(), 4u);
    EXPECT_EQ(problem("flag", "true"), "");
    EXPECT_TRUE(planner.flag());
    EXPECT_EQ(problem("flag", "0"), "");
    EXPECT_FALSE(planner.flag());
}

TEST(DescribeParameters, NameValueAndRangeInNameOrder)
{
    TinyPlanner planner(plane());
    planner.setRange(2.0);
    const std::vector<std::string> described = describeParameters(planner);
    ASSERT_EQ(described.size(), 6u);
    EXPECT_EQ(described[0], "count = 7 (range 0:1:100)");
    EXPECT_EQ(described[1], "flag = 0");
    EXPECT_EQ(described[2], "level = 1 (range 1,2,4)");
    EXPECT_EQ(described[3], "mode = fast");
    EXPECT_EQ(described[4], "range = 2 (range 0.:1.:10.)");
    EXPECT_EQ(described[5], "steps = 3");
}
