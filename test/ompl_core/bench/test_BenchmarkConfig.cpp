// Tests for BenchmarkConfig: a full config and its defaults, comments, blank lines and CRLF line ends,
// paths resolved against the cfg's folder, the accepted bounds of every number, and every error as an
// InputError with its exact message naming file:line (file alone for what no line holds).
#include "ompl_core/bench/BenchmarkConfig.h"

#include "common/InputErrors.h"
#include "common/ScratchDirectory.h"
#include "ompl_core/io/InputError.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using namespace ompl_core;
using ompl_core::test::inputErrorOf;

namespace
{
    /** The name every config of these tests is parsed under: a cfg in the folder "cfgs". */
    const std::string CFG = "cfgs/bench.cfg";

    /** A problem and a planner that make any [benchmark] section a whole config. */
    const std::string PROBLEM = "[problem]\nname=p\nscene=s.xml\n";
    const std::string PLANNER = "[planner]\nrrt=\n";

    BenchmarkConfig parse(const std::string &text)
    {
        return parseBenchmarkConfig(text, CFG);
    }

    /** The InputError message of parsing text as CFG, "" when it parses. */
    std::string errorOf(const std::string &text)
    {
        return inputErrorOf([&] { parseBenchmarkConfig(text, CFG); });
    }

    /** The message of a [benchmark] section holding the one line "key=value" (line 2), "" when it
        parses. */
    std::string benchmarkError(const std::string &key, const std::string &value)
    {
        return errorOf("[benchmark]\n" + key + "=" + value + "\n" + PROBLEM + PLANNER);
    }

    /** A whole config whose [benchmark] section holds the one line "key=value". */
    BenchmarkConfig withBenchmarkLine(const std::string &key, const std::string &value)
    {
        return parse("[benchmark]\n" + key + "=" + value + "\n" + PROBLEM + PLANNER);
    }

    /** Settings as "name=value@file:line", to compare all their fields at once. */
    std::vector<std::string> settingsOf(const std::vector<ParameterSetting> &settings)
    {
        std::vector<std::string> texts;
        for (const ParameterSetting &setting : settings)
            texts.push_back(setting.name + "=" + setting.value + "@" + setting.where.str());
        return texts;
    }

    /** A fresh, empty scratch directory for this test program. */
    std::filesystem::path scratchDirectory()
    {
        return ompl_core::test::scratchDirectory("ompl_core_test_BenchmarkConfig_scratch");
    }
}  // namespace

TEST(ParseBenchmarkConfig, ReadsEveryKeyOfAFullConfig)
{
    const BenchmarkConfig config = parseBenchmarkConfig(
        "# two problems, three planners\n"  // 1
        "[problem]\n"                       // 2
        "name = corridor\n"                 // 3
        "scene = ../scenes/corridor.xml\n"  // 4
        "time_limit = 2.5\n"                // 5
        "mopl.range = 0.3\n"                // 6
        "goal_bias = 0.1\n"                 // 7
        "\n"                                // 8
        "[problem]\n"                       // 9
        "name=open.v2_b-1\n"                // 10
        "scene=/data/open.xml\n"            // 11
        "[benchmark]\n"                     // 12
        "time_limit=10\n"                   // 13
        "mem_limit=2048\n"                  // 14
        "run_count=50\n"                    // 15
        "output=results\n"                  // 16
        "save_paths=shortest\n"             // 17
        "simplify=false\n"                  // 18
        "seed=42\n"                         // 19
        "[planner]\n"                       // 20
        "mopl=\n"                           // 21
        "mopl.range=0.5\n"                  // 22
        "mopl.name=mopl-short\n"            // 23
        "mopl=\n"                           // 24
        "rrt=\n"                            // 25
        "rrt.goal_bias=0.2\n"               // 26
        "mopl.range=0.7\n",                 // 27
        "cfgs/bench.cfg");

    EXPECT_EQ(config.file, "cfgs/bench.cfg");
    ASSERT_EQ(config.problems.size(), 2u);
    const BenchmarkProblem &corridor = config.problems[0];
    EXPECT_EQ(corridor.name, "corridor");
    EXPECT_EQ(corridor.scene, "scenes/corridor.xml");  // cfgs/../scenes/corridor.xml
    EXPECT_EQ(corridor.sceneWhere.str(), "cfgs/bench.cfg:4");
    ASSERT_TRUE(corridor.timeLimit.has_value());
    EXPECT_EQ(*corridor.timeLimit, 2.5);
    EXPECT_EQ(settingsOf(corridor.parameters), (std::vector<std::string>{"mopl.range=0.3@cfgs/bench.cfg:6",
                                                                         "goal_bias=0.1@cfgs/bench.cfg:7"}));
    EXPECT_EQ(corridor.where.str(), "cfgs/bench.cfg:2");
    const BenchmarkProblem &open = config.problems[1];
    EXPECT_EQ(open.name, "open.v2_b-1");
    EXPECT_EQ(open.scene, "/data/open.xml");  // absolute paths stay
    EXPECT_EQ(open.sceneWhere.str(), "cfgs/bench.cfg:11");
    EXPECT_FALSE(open.timeLimit.has_value());
    EXPECT_TRUE(open.parameters.empty());
    EXPECT_EQ(open.where.str(), "cfgs/bench.cfg:9");

    ASSERT_TRUE(config.timeLimit.has_value());
    EXPECT_EQ(*config.timeLimit, 10.0);
    EXPECT_EQ(config.memoryLimit, 2048.0);
    EXPECT_EQ(config.runCount, 50u);
    EXPECT_EQ(config.output, "cfgs/results");
    EXPECT_EQ(config.savedPaths, SavedPaths::Shortest);
    EXPECT_FALSE(config.simplify);
    EXPECT_EQ(config.seed, 42u);

    // NAME.param and NAME.name go to the latest NAME= above them
    ASSERT_EQ(config.planners.size(), 3u);
    EXPECT_EQ(config.planners[0].type, "mopl");
    EXPECT_EQ(config.planners[0].label, "mopl-short");
    EXPECT_EQ(settingsOf(config.planners[0].parameters),
              (std::vector<std::string>{"range=0.5@cfgs/bench.cfg:22"}));
    EXPECT_EQ(config.planners[0].where.str(), "cfgs/bench.cfg:21");
    EXPECT_EQ(config.planners[1].type, "mopl");
    EXPECT_EQ(config.planners[1].label, "mopl");
    EXPECT_EQ(settingsOf(config.planners[1].parameters),
              (std::vector<std::string>{"range=0.7@cfgs/bench.cfg:27"}));
    EXPECT_EQ(config.planners[1].where.str(), "cfgs/bench.cfg:24");
    EXPECT_EQ(config.planners[2].type, "rrt");
    EXPECT_EQ(config.planners[2].label, "rrt");
    EXPECT_EQ(settingsOf(config.planners[2].parameters),
              (std::vector<std::string>{"goal_bias=0.2@cfgs/bench.cfg:26"}));
    EXPECT_EQ(config.planners[2].where.str(), "cfgs/bench.cfg:25");
}

TEST(ParseBenchmarkConfig, DefaultsWhenKeysAreAbsent)
{
    const BenchmarkConfig config = parse(PROBLEM + PLANNER);
    EXPECT_EQ(config.file, CFG);
    EXPECT_FALSE(config.timeLimit.has_value());
    EXPECT_EQ(config.memoryLimit, 4096.0);
    EXPECT_EQ(config.runCount, 100u);
    EXPECT_TRUE(config.simplify);
    EXPECT_EQ(config.seed, 1u);
    EXPECT_EQ(config.savedPaths, SavedPaths::None);
    EXPECT_EQ(config.output, "cfgs");
    ASSERT_EQ(config.problems.size(), 1u);
    EXPECT_EQ(config.problems[0].scene, "cfgs/s.xml");
    EXPECT_FALSE(config.problems[0].timeLimit.has_value());
    ASSERT_EQ(config.planners.size(), 1u);
    EXPECT_EQ(config.planners[0].label, "rrt");
    EXPECT_TRUE(config.planners[0].parameters.empty());
}

TEST(ParseBenchmarkConfig, PathsResolveAgainstTheCfgsFolder)
{
    // a cfg in the working directory
    const BenchmarkConfig here = parseBenchmarkConfig(PROBLEM + PLANNER, "bench.cfg");
    EXPECT_EQ(here.output, ".");
    EXPECT_EQ(here.problems[0].scene, "s.xml");
    // an absolute cfg path
    const BenchmarkConfig absolute = parseBenchmarkConfig(
        "[problem]\nname=p\nscene=sub/../s.xml\n[benchmark]\noutput=../logs\n" + PLANNER, "/work/cfgs/b.cfg");
    EXPECT_EQ(absolute.problems[0].scene, "/work/cfgs/s.xml");
    EXPECT_EQ(absolute.output, "/work/logs");
    // an absolute output stays
    EXPECT_EQ(withBenchmarkLine("output", "/tmp/logs").output, "/tmp/logs");
}

TEST(ParseBenchmarkConfig, CommentsBlankLinesAndCrlfLineEnds)
{
    const BenchmarkConfig config = parse(
        "\r\n"                                    // 1
        "  # a comment line\r\n"                  // 2
        "[problem]   # a comment after [x]\r\n"   // 3
        "\t\r\n"                                  // 4
        "name = p # a comment after a value\r\n"  // 5
        "scene=s.xml#no space before it\r\n"      // 6
        "   \r\n"                                 // 7
        "[ planner ]\r\n"                         // 8
        "rrt=   \r\n"                             // 9
        "rrt.range = 2 \r\n"                      // 10
        "# the end, with no line end");
    ASSERT_EQ(config.problems.size(), 1u);
    EXPECT_EQ(config.problems[0].name, "p");
    EXPECT_EQ(config.problems[0].scene, "cfgs/s.xml");
    EXPECT_EQ(config.problems[0].where.line, 3);
    EXPECT_EQ(config.problems[0].sceneWhere.line, 6);
    ASSERT_EQ(config.planners.size(), 1u);
    EXPECT_EQ(config.planners[0].where.line, 9);
    EXPECT_EQ(settingsOf(config.planners[0].parameters),
              (std::vector<std::string>{"range=2@cfgs/bench.cfg:10"}));
    // an error in a CRLF file names the right line and no '\r'
    EXPECT_EQ(errorOf("[problem]\r\n\r\n# c\r\nbogus line\r\n"),
              "cfgs/bench.cfg:4: expected 'key = value', got 'bogus line'");
}

TEST(ParseBenchmarkConfig, AByteOrderMarkIsNoPartOfTheFirstLine)
{
    // some Windows editors start UTF-8 files with one
    const BenchmarkConfig config = parse("\xEF\xBB\xBF" + PROBLEM + PLANNER);
    ASSERT_EQ(config.problems.size(), 1u);
    EXPECT_EQ(config.problems[0].where.line, 1);
    EXPECT_EQ(errorOf("\xEF\xBB\xBF"
                      "bogus\n"),
              "cfgs/bench.cfg:1: expected 'key = value', got 'bogus'");
}

TEST(ParseBenchmarkConfig, ValuesMayHoldFurtherEquals)
{
    const BenchmarkConfig config = parse(PROBLEM + "expr = a=b\n" + PLANNER);
    EXPECT_EQ(settingsOf(config.problems[0].parameters),
              (std::vector<std::string>{"expr=a=b@cfgs/bench.cfg:4"}));
}

TEST(ParseBenchmarkConfig, SavePathsAndSimplifyValues)
{
    EXPECT_EQ(withBenchmarkLine("save_paths", "none").savedPaths, SavedPaths::None);
    EXPECT_EQ(withBenchmarkLine("save_paths", "all").savedPaths, SavedPaths::All);
    EXPECT_EQ(withBenchmarkLine("save_paths", "shortest").savedPaths, SavedPaths::Shortest);
    EXPECT_TRUE(withBenchmarkLine("simplify", "1").simplify);
    EXPECT_TRUE(withBenchmarkLine("simplify", "true").simplify);
    EXPECT_FALSE(withBenchmarkLine("simplify", "0").simplify);
    EXPECT_FALSE(withBenchmarkLine("simplify", "false").simplify);
    EXPECT_TRUE(withBenchmarkLine("simulate", "1").simulate);
    EXPECT_FALSE(withBenchmarkLine("simulate", "0").simulate);
    EXPECT_FALSE(withBenchmarkLine("seed", "1").simulate) << "off unless asked";
}

TEST(ParseBenchmarkConfig, AcceptsTheBoundsOfEveryNumber)
{
    EXPECT_EQ(withBenchmarkLine("run_count", "1").runCount, 1u);
    EXPECT_EQ(withBenchmarkLine("run_count", "1000000").runCount, 1000000u);
    EXPECT_EQ(withBenchmarkLine("run_count", "1e3").runCount, 1000u);
    EXPECT_EQ(withBenchmarkLine("seed", "1").seed, 1u);
    EXPECT_EQ(withBenchmarkLine("seed", "4294967295").seed, 4294967295u);
    EXPECT_EQ(*withBenchmarkLine("time_limit", "86400").timeLimit, 86400.0);
    EXPECT_EQ(*withBenchmarkLine("time_limit", "0.001").timeLimit, 0.001);
    EXPECT_EQ(withBenchmarkLine("mem_limit", "1").memoryLimit, 1.0);
    EXPECT_EQ(withBenchmarkLine("mem_limit", "1048576").memoryLimit, 1048576.0);
    EXPECT_EQ(*parse("[problem]\nname=p\nscene=s.xml\ntime_limit=86400\n" + PLANNER).problems[0].timeLimit,
              86400.0);
}

TEST(ParseBenchmarkConfig, TheSameKeysInTwoProblems)
{
    const BenchmarkConfig config =
        parse("[problem]\nname=a\nscene=a.xml\nk=1\n[problem]\nname=b\nscene=b.xml\nk=2\n" + PLANNER);
    ASSERT_EQ(config.problems.size(), 2u);
    EXPECT_EQ(settingsOf(config.problems[1].parameters), (std::vector<std::string>{"k=2@cfgs/bench.cfg:8"}));
}

TEST(ParseBenchmarkConfig, PlannersOfOneTypeWithDistinctLabels)
{
    const BenchmarkConfig config =
        parse(PROBLEM + "[planner]\nrrt=\nrrt=\nrrt.name=rrt_2\nprm=\nprm.name=rrt.3\n");
    ASSERT_EQ(config.planners.size(), 3u);
    EXPECT_EQ(config.planners[0].label, "rrt");
    EXPECT_EQ(config.planners[1].label, "rrt_2");
    EXPECT_EQ(config.planners[2].type, "prm");
    EXPECT_EQ(config.planners[2].label, "rrt.3");
}

TEST(LoadBenchmarkConfig, ResolvesPathsAgainstTheFilesFolder)
{
    const std::filesystem::path dir = scratchDirectory();
    const std::string path = (dir / "bench.cfg").string();
    std::ofstream(path) << PROBLEM << PLANNER;
    const BenchmarkConfig config = loadBenchmarkConfig(path);
    EXPECT_EQ(config.file, path);
    EXPECT_EQ(config.problems[0].scene, (dir / "s.xml").string());
    EXPECT_EQ(config.problems[0].sceneWhere.str(), path + ":3");
    EXPECT_EQ(config.output, dir.string());
}

TEST(LoadBenchmarkConfig, ErrorsNameTheFile)
{
    const std::filesystem::path dir = scratchDirectory();
    const std::string missing = (dir / "missing.cfg").string();
    EXPECT_EQ(inputErrorOf([&] { loadBenchmarkConfig(missing); }), missing + ": benchmark config not found");
    const std::string path = (dir / "bad.cfg").string();
    std::ofstream(path) << "[problem]\nname=p\n[bogus]\n";
    EXPECT_EQ(inputErrorOf([&] { loadBenchmarkConfig(path); }),
              path + ":3: unknown section [bogus] (known: [problem], [benchmark], [planner])");
}

// ---- errors of lines and sections ----

TEST(BenchmarkConfigErrors, UnknownSection)
{
    EXPECT_EQ(errorOf("[problem]\nname=p\n[planners]\nrrt=\n"),
              "cfgs/bench.cfg:3: unknown section [planners] (known: [problem], [benchmark], [planner])");
    EXPECT_EQ(errorOf("[]\n"),
              "cfgs/bench.cfg:1: unknown section [] (known: [problem], [benchmark], [planner])");
}

TEST(BenchmarkConfigErrors, MalformedSectionHeader)
{
    EXPECT_EQ(errorOf("# c\n[problem\n"),
              "cfgs/bench.cfg:2: malformed section header '[problem' (expected [name])");
    EXPECT_EQ(errorOf("[problem] x\n"),
              "cfgs/bench.cfg:1: malformed section header '[problem] x' (expected [name])");
}

TEST(BenchmarkConfigErrors, KeyOutsideASection)
{
    EXPECT_EQ(errorOf("# c\n\nname = p\n[problem]\n"), "cfgs/bench.cfg:3: key 'name' is outside any section");
}

TEST(BenchmarkConfigErrors, LineWithoutEquals)
{
    EXPECT_EQ(errorOf("[problem]\nname p\n"), "cfgs/bench.cfg:2: expected 'key = value', got 'name p'");
    EXPECT_EQ(errorOf("[planner]\nrrt\n"), "cfgs/bench.cfg:2: expected 'key = value', got 'rrt'");
}

TEST(BenchmarkConfigErrors, EmptyKey)
{
    EXPECT_EQ(errorOf("[problem]\n  = p\n"), "cfgs/bench.cfg:2: a key is missing before '='");
    EXPECT_EQ(errorOf("[planner]\n=\n"), "cfgs/bench.cfg:2: a key is missing before '='");
}

TEST(BenchmarkConfigErrors, UnknownBenchmarkKey)
{
    EXPECT_EQ(benchmarkError("runs", "5"),
              "cfgs/bench.cfg:2: unknown key 'runs' in [benchmark] (known: time_limit, mem_limit, run_count, "
              "output, save_paths, simplify, simulate, seed)");
}

TEST(BenchmarkConfigErrors, DuplicateKeyInASection)
{
    EXPECT_EQ(errorOf("[problem]\nname=a\nscene=s.xml\nname=b\n"),
              "cfgs/bench.cfg:4: 'name' given twice in this section (first at line 2)");
    EXPECT_EQ(errorOf("[problem]\nname=a\nk=1\nk=1\n"),
              "cfgs/bench.cfg:4: 'k' given twice in this section (first at line 3)");
    EXPECT_EQ(errorOf("[benchmark]\nseed=1\n\nseed=2\n"),
              "cfgs/bench.cfg:4: 'seed' given twice in this section (first at line 2)");
}

TEST(BenchmarkConfigErrors, BenchmarkOrPlannerSectionGivenTwice)
{
    EXPECT_EQ(errorOf("[benchmark]\nseed=2\n[problem]\nname=p\n[benchmark]\n"),
              "cfgs/bench.cfg:5: section [benchmark] given twice (first at line 1)");
    EXPECT_EQ(errorOf(PROBLEM + "[planner]\nrrt=\n[planner]\nprm=\n"),
              "cfgs/bench.cfg:6: section [planner] given twice (first at line 4)");
}

// ---- errors of values ----

TEST(BenchmarkConfigErrors, NonNumericValues)
{
    EXPECT_EQ(benchmarkError("run_count", "ten"),
              "cfgs/bench.cfg:2: 'run_count' must be a number, got 'ten'");
    EXPECT_EQ(benchmarkError("time_limit", ""), "cfgs/bench.cfg:2: 'time_limit' must be a number, got ''");
    EXPECT_EQ(benchmarkError("mem_limit", "inf"),
              "cfgs/bench.cfg:2: 'mem_limit' must be a number, got 'inf'");
    EXPECT_EQ(benchmarkError("seed", "0x10"), "cfgs/bench.cfg:2: 'seed' must be a number, got '0x10'");
    EXPECT_EQ(benchmarkError("time_limit", "5s"),
              "cfgs/bench.cfg:2: 'time_limit' must be a number, got '5s'");
    EXPECT_EQ(errorOf("[problem]\nname=p\ntime_limit=nan\n"),
              "cfgs/bench.cfg:3: 'time_limit' must be a number, got 'nan'");
}

TEST(BenchmarkConfigErrors, TimeLimitOutOfRange)
{
    EXPECT_EQ(benchmarkError("time_limit", "0"),
              "cfgs/bench.cfg:2: 'time_limit' must be in (0, 86400], got 0");
    EXPECT_EQ(benchmarkError("time_limit", "86400.5"),
              "cfgs/bench.cfg:2: 'time_limit' must be in (0, 86400], got 86400.5");
    EXPECT_EQ(benchmarkError("time_limit", "-1"),
              "cfgs/bench.cfg:2: 'time_limit' must be in (0, 86400], got -1");
    // a problem's time limit is checked the same way
    EXPECT_EQ(errorOf("[problem]\nname=p\ntime_limit=0\n"),
              "cfgs/bench.cfg:3: 'time_limit' must be in (0, 86400], got 0");
    EXPECT_EQ(errorOf("[problem]\ntime_limit=1e5\n"),
              "cfgs/bench.cfg:2: 'time_limit' must be in (0, 86400], got 1e5");
}

TEST(BenchmarkConfigErrors, RunCountOutOfRangeOrNotWhole)
{
    EXPECT_EQ(benchmarkError("run_count", "0"),
              "cfgs/bench.cfg:2: 'run_count' must be in [1, 1000000], got 0");
    EXPECT_EQ(benchmarkError("run_count", "1000001"),
              "cfgs/bench.cfg:2: 'run_count' must be in [1, 1000000], got 1000001");
    EXPECT_EQ(benchmarkError("run_count", "1.5"),
              "cfgs/bench.cfg:2: 'run_count' must be a whole number, got 1.5");
}

TEST(BenchmarkConfigErrors, SeedOutOfRangeOrNotWhole)
{
    // the bounds are written in full: 4294967296 is not "outside [1, 4.29497e+09]"
    EXPECT_EQ(benchmarkError("seed", "0"), "cfgs/bench.cfg:2: 'seed' must be in [1, 4294967295], got 0");
    EXPECT_EQ(benchmarkError("seed", "4294967296"),
              "cfgs/bench.cfg:2: 'seed' must be in [1, 4294967295], got 4294967296");
    EXPECT_EQ(benchmarkError("seed", "2.5"), "cfgs/bench.cfg:2: 'seed' must be a whole number, got 2.5");
}

TEST(BenchmarkConfigErrors, MemLimitOutOfRange)
{
    // the bounds are written in full: 1048577 is not "outside [1, 1.04858e+06]"
    EXPECT_EQ(benchmarkError("mem_limit", "0"),
              "cfgs/bench.cfg:2: 'mem_limit' must be in [1, 1048576], got 0");
    EXPECT_EQ(benchmarkError("mem_limit", "1048577"),
              "cfgs/bench.cfg:2: 'mem_limit' must be in [1, 1048576], got 1048577");
}

TEST(BenchmarkConfigErrors, BadSimplifyAndSavePathsValues)
{
    EXPECT_EQ(benchmarkError("simplify", "yes"),
              "cfgs/bench.cfg:2: 'simplify' must be 0, 1, true or false, got 'yes'");
    EXPECT_EQ(benchmarkError("simplify", "True"),
              "cfgs/bench.cfg:2: 'simplify' must be 0, 1, true or false, got 'True'");
    EXPECT_EQ(benchmarkError("simplify", ""),
              "cfgs/bench.cfg:2: 'simplify' must be 0, 1, true or false, got ''");
    EXPECT_EQ(benchmarkError("save_paths", "best"),
              "cfgs/bench.cfg:2: 'save_paths' must be none, all or shortest, got 'best'");
    EXPECT_EQ(benchmarkError("save_paths", "All"),
              "cfgs/bench.cfg:2: 'save_paths' must be none, all or shortest, got 'All'");
}

TEST(BenchmarkConfigErrors, EmptySceneOrOutput)
{
    EXPECT_EQ(errorOf("[problem]\nname=p\nscene =  \n"), "cfgs/bench.cfg:3: scene needs a file name");
    EXPECT_EQ(benchmarkError("output", ""), "cfgs/bench.cfg:2: output needs a folder");
}

// ---- errors of planners ----

TEST(BenchmarkConfigErrors, PlannerLineWithAValue)
{
    EXPECT_EQ(errorOf("[planner]\nrrt = fast\n"),
              "cfgs/bench.cfg:2: planner 'rrt=' takes no value; set its parameters with rrt.NAME=VALUE");
}

TEST(BenchmarkConfigErrors, ParameterBeforeItsPlanner)
{
    EXPECT_EQ(errorOf("[planner]\nrrt.range=1\nrrt=\n"),
              "cfgs/bench.cfg:2: 'rrt.range' names no planner: add one with 'rrt=' on a line before");
    // another planner's line does not count
    EXPECT_EQ(errorOf("[planner]\nprm=\nrrt.name=fast\n"),
              "cfgs/bench.cfg:3: 'rrt.name' names no planner: add one with 'rrt=' on a line before");
}

TEST(BenchmarkConfigErrors, ParameterWithoutAName)
{
    EXPECT_EQ(errorOf("[planner]\nrrt=\nrrt.=1\n"), "cfgs/bench.cfg:3: 'rrt.' names no parameter");
}

TEST(BenchmarkConfigErrors, BadProblemName)
{
    const std::string rule = "' must be letters, digits, '_', '-' or '.'";
    EXPECT_EQ(errorOf("[problem]\nname=my problem\n"), "cfgs/bench.cfg:2: problem name 'my problem" + rule);
    EXPECT_EQ(errorOf("[problem]\nname=a/b\n"), "cfgs/bench.cfg:2: problem name 'a/b" + rule);
    EXPECT_EQ(errorOf("[problem]\nname=a;b\n"), "cfgs/bench.cfg:2: problem name 'a;b" + rule);
    EXPECT_EQ(errorOf("[problem]\nname=\n"), "cfgs/bench.cfg:2: problem name '" + rule);
}

TEST(BenchmarkConfigErrors, BadPlannerNameOrLabel)
{
    const std::string rule = "' must be letters, digits, '_', '-' or '.'";
    EXPECT_EQ(errorOf("[planner]\nr/t=\n"), "cfgs/bench.cfg:2: planner name 'r/t" + rule);
    EXPECT_EQ(errorOf("[planner]\nmy rrt =\n"), "cfgs/bench.cfg:2: planner name 'my rrt" + rule);
    EXPECT_EQ(errorOf("[planner]\nrrt=\nrrt.name=my rrt\n"),
              "cfgs/bench.cfg:3: planner label 'my rrt" + rule);
    EXPECT_EQ(errorOf("[planner]\nrrt=\nrrt.name=\n"), "cfgs/bench.cfg:3: planner label '" + rule);
}

// ---- errors of the whole config ----

TEST(BenchmarkConfigErrors, ProblemWithoutName)
{
    EXPECT_EQ(errorOf("[problem]\nscene=s.xml\n" + PLANNER), "cfgs/bench.cfg:1: [problem] without a name");
    // the second problem's [problem] line
    EXPECT_EQ(errorOf(PROBLEM + "\n[problem]\nscene=s.xml\n" + PLANNER),
              "cfgs/bench.cfg:5: [problem] without a name");
}

TEST(BenchmarkConfigErrors, ProblemWithoutScene)
{
    EXPECT_EQ(errorOf("[problem]\nname=p\n" + PLANNER), "cfgs/bench.cfg:1: [problem] 'p' without a scene");
}

TEST(BenchmarkConfigErrors, DuplicateProblemName)
{
    EXPECT_EQ(errorOf(PROBLEM + "# again\n" + PROBLEM + PLANNER),
              "cfgs/bench.cfg:5: problem name 'p' given twice (first at line 1)");
}

TEST(BenchmarkConfigErrors, NoProblem)
{
    // no line holds what is missing: the message names the file alone
    EXPECT_EQ(errorOf(PLANNER), "cfgs/bench.cfg: no [problem] section");
    EXPECT_EQ(errorOf(""), "cfgs/bench.cfg: no [problem] section");
    EXPECT_EQ(errorOf("[benchmark]\nseed=3\n" + PLANNER), "cfgs/bench.cfg: no [problem] section");
}

TEST(BenchmarkConfigErrors, NoPlanner)
{
    EXPECT_EQ(errorOf(PROBLEM), "cfgs/bench.cfg: no planner: list some in a [planner] section");
    EXPECT_EQ(errorOf(PROBLEM + "[planner]\n# none yet\n"),
              "cfgs/bench.cfg: no planner: list some in a [planner] section");
}

TEST(BenchmarkConfigErrors, TwoPlannersWithOneLabel)
{
    EXPECT_EQ(
        errorOf(PROBLEM + "[planner]\nrrt=\nrrt.range=1\nrrt=\n"),
        "cfgs/bench.cfg:7: two planners are labelled 'rrt' (the other at line 5): give one a label with "
        "rrt.name=LABEL");
    // a label may collide with another type's default label
    EXPECT_EQ(
        errorOf(PROBLEM + "[planner]\nrrt=\nrrt.name=prm\nprm=\n"),
        "cfgs/bench.cfg:7: two planners are labelled 'prm' (the other at line 5): give one a label with "
        "prm.name=LABEL");
}
