// load_test: continuous planning under load, every answer checked. For --duration seconds it plans
// one run after another, each on a scene drawn from those given (manipulation scenes with
// ompl_mm::PlanningRun and the scene's planner, physics scenes with ompl_phys::PhysicsPlanningRun
// and --phys-planner), with a random seed and a time limit drawn log-uniformly from [--min-limit,
// --max-limit]. A run is a wrong answer when it reports a solution that fails its check (a manipulation path
// that OMPL's PathGeometric::check() rejects or whose end misses the goal; a physics path whose re-simulation
// does not reach the goal), and an overshoot when planning (smoothing included) takes longer than its limit
// plus --slack. Run two at once to load both cores of a 2-core machine. Usage: load_test --mm SCENE... --phys
// SCENE... [--duration S] [--seed N] [--min-limit S]
//        [--max-limit S] [--slack S] [--report-every S] [--phys-planner NAME]
// Prints a line per --report-every seconds and a summary; exit status 0 when no run was wrong or
// overshot, 1 otherwise, 2 for bad input.
#include "ompl_core/run/ExitStatus.h"
#include "ompl_mm/io/PlanningRun.h"
#include "ompl_mm/scene/SceneLoader.h"
#include "ompl_phys/io/PhysicsPlanningRun.h"
#include "ompl_phys/scene/PhysicsSceneLoader.h"

#include <ompl/base/terminationconditions/IterationTerminationCondition.h>
#include <ompl/util/Console.h>

#include <boost/program_options.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <random>
#include <string>
#include <vector>

namespace po = boost::program_options;

namespace
{
    using Clock = std::chrono::steady_clock;

    struct Options
    {
        std::vector<std::string> mmScenes, physScenes;
        std::string physPlanner = "kpiece";
        double duration = 3600.0;
        std::uint32_t seed = 1;
        double minLimit = 0.01, maxLimit = 2.0, slack = 0.05, reportEvery = 300.0;
    };

    /** What the runs so far came to. */
    struct Tally
    {
        unsigned int runs = 0, solved = 0, wrong = 0, overshoots = 0;
        double worstOvershoot = -1e9;  ///< planning time minus limit, largest, s

        void print(std::ostream &out, double seconds) const
        {
            out << std::fixed << std::setprecision(0) << seconds << " s: " << runs << " runs, " << solved
                << " solved, " << wrong << " wrong answers, " << overshoots << " overshoots (largest "
                << std::setprecision(3) << worstOvershoot << " s past the limit)" << std::endl;
        }
    };

    /** What is wrong with the solution of a manipulation run: "" when it passes OMPL's check and
        ends in the goal. */
    std::string manipulationAnswerFault(ompl_mm::PlanningRun &run)
    {
        const ompl::geometric::PathGeometric &path = run.setup().getSolutionPath();
        if (path.getStateCount() == 0)
            return "the path has no state";
        if (!run.pathValid().value_or(false))
            return "the path fails OMPL's check";
        if (!run.setup().getProblemDefinition()->getGoal()->isSatisfied(
                path.getState(path.getStateCount() - 1)))
            return "the path ends outside the goal";
        return "";
    }

    int loadTest(const Options &options)
    {
        std::vector<ompl_mm::Scene> mmScenes;
        for (const std::string &path : options.mmScenes)
            mmScenes.push_back(ompl_mm::loadScene(path));
        std::vector<ompl_phys::PhysicsScene> physScenes;
        for (const std::string &path : options.physScenes)
            physScenes.push_back(ompl_phys::loadPhysicsScene(path));
        std::mt19937 rng(options.seed);
        std::uniform_real_distribution<double> logLimit(std::log(options.minLimit),
                                                        std::log(options.maxLimit));
        std::uniform_int_distribution<std::size_t> pick(0, mmScenes.size() + physScenes.size() - 1);
        const auto forever = ompl::base::plannerNonTerminatingCondition();
        Tally tally;
        const Clock::time_point start = Clock::now();
        double nextReport = options.reportEvery;
        const auto seconds = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };
        while (seconds() < options.duration)
        {
            const std::size_t scene = pick(rng);
            const std::uint32_t seed = rng();
            const double limit = std::exp(logLimit(rng));
            bool solved = false;
            std::string fault;
            double planning = 0.0;
            if (scene < mmScenes.size())
            {
                ompl_mm::PlanningRun run(mmScenes[scene], {"", seed, limit, {}});
                run.solve(forever);
                planning = run.phases().solve;
                solved = run.solved();
                fault = solved ? manipulationAnswerFault(run) : "";
            }
            else
            {
                const ompl_phys::PhysicsScene &physics = physScenes[scene - mmScenes.size()];
                ompl_phys::PhysicsPlanningRun run(physics, {options.physPlanner, seed, limit, {}});
                run.solve(forever);
                planning = run.phases().solve;
                solved = run.solved();
                if (solved && !(run.simulated() != nullptr && run.simulated()->reachesGoal))
                    fault = "the re-simulated path does not reach the goal";
            }
            ++tally.runs;
            tally.solved += solved;
            const double overshoot = planning - limit;
            tally.worstOvershoot = std::max(tally.worstOvershoot, overshoot);
            if (!fault.empty() || overshoot > options.slack)
            {
                tally.wrong += !fault.empty();
                tally.overshoots += overshoot > options.slack;
                std::cout << (fault.empty() ? "overshoot" : "WRONG ANSWER (" + fault + ")") << ": scene "
                          << (scene < mmScenes.size() ? options.mmScenes[scene]
                                                      : options.physScenes[scene - mmScenes.size()])
                          << " seed " << seed << " limit " << limit << " s, planning " << planning << " s"
                          << std::endl;
            }
            if (seconds() >= nextReport)
            {
                tally.print(std::cout, seconds());
                nextReport += options.reportEvery;
            }
        }
        std::cout << "summary: ";
        tally.print(std::cout, seconds());
        return tally.wrong == 0 && tally.overshoots == 0 ? 0 : 1;
    }
}  // namespace

int main(int argc, char **argv)
{
    Options options;
    po::options_description named("Options");
    named.add_options()("help,h", "print this help")                                                        //
        ("mm", po::value(&options.mmScenes)->multitoken(), "manipulation scenes")                           //
        ("phys", po::value(&options.physScenes)->multitoken(), "physics scenes")                            //
        ("duration", po::value(&options.duration)->default_value(options.duration), "seconds of planning")  //
        ("seed", po::value(&options.seed)->default_value(options.seed),
         "seed of the draws of scenes, seeds, limits")  //
        ("min-limit", po::value(&options.minLimit)->default_value(options.minLimit),
         "shortest time limit, s")  //
        ("max-limit", po::value(&options.maxLimit)->default_value(options.maxLimit),
         "longest time limit, s")  //
        ("slack", po::value(&options.slack)->default_value(options.slack),
         "planning past the limit allowed, s")  //
        ("report-every", po::value(&options.reportEvery)->default_value(options.reportEvery),
         "seconds between progress lines");
    const std::string usage =
        "usage: load_test --mm SCENE... --phys SCENE... [options]\n"
        "Plans one run after another on the scenes with random seeds and time limits, checking every\n"
        "answer and every run's time. Exit status: 0 no wrong answer and no overshoot, 1 otherwise, 2 bad "
        "input.";
    return ompl_core::exitStatusOf<po::error>(
        "load_test",
        [&]
        {
            po::variables_map vm;
            po::store(po::parse_command_line(argc, argv, named), vm);
            po::notify(vm);
            if (vm.count("help"))
            {
                std::cout << usage << "\n\n" << named;
                return 0;
            }
            if (options.mmScenes.empty() && options.physScenes.empty())
                throw po::error("no scene given (--mm, --phys)");
            if (!(options.minLimit > 0.0) || !(options.maxLimit >= options.minLimit) ||
                !(options.duration > 0.0) || !(options.slack >= 0.0) || !(options.reportEvery > 0.0))
                throw po::error(
                    "the limits, the duration and --report-every must be above 0, --slack not below");
            ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
            return loadTest(options);
        });
}
