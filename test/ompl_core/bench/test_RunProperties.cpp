// Tests for RunProperties: a run record's numbers become REAL properties (exact text), counts INTEGER and
// flags BOOLEAN (0/1); texts and non-finite numbers are left out; nested records are prefixed with their
// key and '_', except "stats"; properties already set are kept.
#include "ompl_core/bench/RunProperties.h"

#include "ompl_core/io/TextFormat.h"

#include <gtest/gtest.h>

#include <limits>
#include <map>
#include <string>

using namespace ompl_core;
// the expected values: OMPL's RunProperties is this map (OMPL 1.5) or a struct derived from it (1.7)
using Properties = std::map<std::string, std::string>;

namespace
{
    Properties propertiesOf(const RunRecord &record)
    {
        ompl::tools::Benchmark::RunProperties properties;
        addRunProperties(record, properties);
        return properties;
    }
}  // namespace

TEST(AddRunProperties, NumbersCountsAndFlagsWithTheirTypes)
{
    RunRecord record;
    record.addNumber("path_length_m", 0.1)
        .addNumber("action", -2.5e-7)
        .addNumber("zero", 0.0)
        .addCount("path_vertices", 42)
        .addCount("huge", 18446744073709551615ull)
        .addFlag("reaches_goal", true)
        .addFlag("approximate", false);
    EXPECT_EQ(propertiesOf(record), (Properties{{"path_length_m REAL", "0.10000000000000001"},
                                                {"action REAL", "-2.4999999999999999e-07"},
                                                {"zero REAL", "0"},
                                                {"path_vertices INTEGER", "42"},
                                                {"huge INTEGER", "18446744073709551615"},
                                                {"reaches_goal BOOLEAN", "1"},
                                                {"approximate BOOLEAN", "0"}}));
    // REAL values are the exact text of the number: they read back to the same double
    EXPECT_EQ(std::stod(propertiesOf(record).at("path_length_m REAL")), 0.1);
    EXPECT_EQ(propertiesOf(record).at("action REAL"), exactText(-2.5e-7));
}

TEST(AddRunProperties, TextsAndNonFiniteNumbersAreLeftOut)
{
    RunRecord record;
    record.addText("status", "Exact solution")
        .addTexts("goal_occupied_by", {"box", "cup"})
        .addNumber("nan", std::numeric_limits<double>::quiet_NaN())
        .addNumber("inf", std::numeric_limits<double>::infinity())
        .addNumber("minus_inf", -std::numeric_limits<double>::infinity())
        .addNumber("time_s", 1.5);
    EXPECT_EQ(propertiesOf(record), (Properties{{"time_s REAL", "1.5"}}));
    EXPECT_TRUE(propertiesOf(RunRecord()).empty());
}

TEST(AddRunProperties, NestedRecordsArePrefixedExceptStats)
{
    RunRecord stats;
    stats.addCount("iterations", 120).addNumber("time_nearest_s", 0.25);
    RunRecord primitives;
    primitives.addCount("push", 3).addCount("transit", 4);
    RunRecord stops;
    stops.addCount("goal", 1);
    RunRecord outer;
    outer.addRecord("stops", stops).addFlag("done", true);
    RunRecord record;
    record.addRecord("stats", stats).addRecord("primitives", primitives).addRecord("phys", outer);
    EXPECT_EQ(propertiesOf(record), (Properties{{"iterations INTEGER", "120"},
                                                {"time_nearest_s REAL", "0.25"},
                                                {"primitives_push INTEGER", "3"},
                                                {"primitives_transit INTEGER", "4"},
                                                {"phys_stops_goal INTEGER", "1"},
                                                {"phys_done BOOLEAN", "1"}}));
}

TEST(AddRunProperties, StatsInsideANestedRecordKeepsTheOuterPrefix)
{
    RunRecord stats;
    stats.addCount("substeps", 9);
    RunRecord inner;
    inner.addRecord("stats", stats);
    RunRecord record;
    record.addRecord("control", inner);
    EXPECT_EQ(propertiesOf(record), (Properties{{"control_substeps INTEGER", "9"}}));
}

TEST(AddRunProperties, PropertiesAlreadySetAreKept)
{
    RunRecord stats;
    stats.addCount("iterations", 120);
    RunRecord record;
    record.addNumber("time", 9.0).addFlag("solved", false).addRecord("stats", stats).addCount("moves", 2);
    // Benchmark's own time and the planner's own statistics stay
    ompl::tools::Benchmark::RunProperties properties;
    properties.insert({{"time REAL", "0.5"}, {"solved BOOLEAN", "1"}, {"iterations INTEGER", "118"}});
    addRunProperties(record, properties);
    EXPECT_EQ(Properties(properties), (Properties{{"time REAL", "0.5"},
                                                  {"solved BOOLEAN", "1"},
                                                  {"iterations INTEGER", "118"},
                                                  {"moves INTEGER", "2"}}));
}
