// soak: plans many times in one process, as a long-running program does (a service, a robot's planning
// node, a notebook), and reports its resident memory every so many plans. It alternates a manipulation
// scene (MOPL) and a physics scene (KPIECE1 by default), each on a setup kept alive and cleared between
// plans as an OMPL user would, with a new setup of each made, planned once and dropped every
// --new-setup-every plans. Seeds follow the plan's number (reseedOmpl), so a run is repeatable.
// Usage: soak MANIPULATION.xml PHYSICS.xml [--plans N] [--every K] [--csv FILE] [--mm-time-limit S]
//        [--phys-time-limit S] [--phys-planner NAME] [--new-setup-every M]
// Prints one line per K plans: plans, resident MB, solved so far of each kind, seconds. Exit status:
// 0 done, 2 bad input.
#include "SceneFilesCommandLine.h"

#include "ompl_core/io/OutputFile.h"
#include "ompl_core/run/ExitStatus.h"
#include "ompl_core/run/GlobalSeed.h"
#include "ompl_mm/scene/SceneLoader.h"
#include "ompl_mm/setup/ManipulationSetup.h"
#include "ompl_phys/control/PhysicsSetup.h"
#include "ompl_phys/scene/PhysicsSceneLoader.h"

#include <ompl/util/Console.h>

#include <unistd.h>

#include <chrono>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace po = boost::program_options;

namespace
{
    /** The process's resident memory, MB (from /proc/self/statm). */
    double residentMegabytes()
    {
        std::ifstream statm("/proc/self/statm");
        long total = 0, resident = 0;
        statm >> total >> resident;
        return static_cast<double>(resident) * static_cast<double>(::sysconf(_SC_PAGESIZE)) /
               (1024.0 * 1024.0);
    }

    struct Options
    {
        unsigned int plans = 10000;
        unsigned int every = 1000;
        unsigned int newSetupEvery = 100;
        double mmTimeLimit = 10.0;
        double physTimeLimit = 0.5;
        std::string physPlanner = "kpiece";
        std::string csv;
    };

    /** One plan on setup (cleared first), seeded by its number; true when solved exactly. */
    template <typename Setup>
    bool plan(Setup &setup, unsigned int number, double timeLimit)
    {
        setup.clear();
        ompl_core::reseedOmpl(number);
        return setup.solve(timeLimit) == ompl::base::PlannerStatus::EXACT_SOLUTION;
    }

    int soak(const std::string &mmScene, const std::string &physScene, const Options &options)
    {
        const ompl_mm::Scene manipulation = ompl_mm::loadScene(mmScene);
        const ompl_phys::PhysicsScene physics = ompl_phys::loadPhysicsScene(physScene);
        const auto newPhysicsSetup = [&]
        {
            auto setup = std::make_unique<ompl_phys::PhysicsSetup>(physics);
            setup->setPlannerByName(options.physPlanner);
            return setup;
        };
        ompl_mm::ManipulationSetup mmSetup(manipulation);
        const std::unique_ptr<ompl_phys::PhysicsSetup> physSetup = newPhysicsSetup();
        std::ofstream csv;
        if (!options.csv.empty())
        {
            csv.open(options.csv);
            if (!csv)
                throw ompl_core::OutputError(options.csv + ": cannot write the file");
            csv << "plans,resident_mb,mm_solved,phys_solved,seconds\n";
        }
        const auto report =
            [&](unsigned int plans, unsigned int mmSolved, unsigned int physSolved, double seconds)
        {
            const double resident = residentMegabytes();
            std::cout << std::setw(6) << plans << " plans  " << std::fixed << std::setprecision(1)
                      << std::setw(7) << resident << " MB  mm solved " << mmSolved << "  phys solved "
                      << physSolved << "  " << std::setprecision(0) << seconds << " s" << std::endl;
            if (csv.is_open())
                csv << plans << ',' << std::fixed << std::setprecision(3) << resident << ',' << mmSolved
                    << ',' << physSolved << ',' << std::setprecision(1) << seconds << '\n'
                    << std::flush;
        };
        const auto start = std::chrono::steady_clock::now();
        unsigned int mmSolved = 0, physSolved = 0;
        report(0, 0, 0, 0.0);
        for (unsigned int k = 1; k <= options.plans; ++k)
        {
            const bool fresh = k % options.newSetupEvery == 0 || k % options.newSetupEvery == 1;
            if (k % 2 == 1)
            {
                if (fresh)
                {
                    ompl_mm::ManipulationSetup dropped(manipulation);
                    mmSolved += plan(dropped, k, options.mmTimeLimit);
                }
                else
                    mmSolved += plan(mmSetup, k, options.mmTimeLimit);
            }
            else
                physSolved += plan(fresh ? *newPhysicsSetup() : *physSetup, k, options.physTimeLimit);
            if (k % options.every == 0)
                report(k, mmSolved, physSolved,
                       std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        }
        return 0;
    }
}  // namespace

int main(int argc, char **argv)
{
    Options options;
    po::options_description named("Options");
    named.add_options()("help,h", "print this help")  //
        ("plans", po::value(&options.plans)->default_value(options.plans),
         "plans in all, alternating the scenes")  //
        ("every", po::value(&options.every)->default_value(options.every),
         "report the memory every so many plans")                                    //
        ("csv", po::value(&options.csv), "also write the reports to this CSV file")  //
        ("mm-time-limit", po::value(&options.mmTimeLimit)->default_value(options.mmTimeLimit),
         "seconds per manipulation plan")  //
        ("phys-time-limit", po::value(&options.physTimeLimit)->default_value(options.physTimeLimit),
         "seconds per physics plan")  //
        ("phys-planner", po::value(&options.physPlanner)->default_value(options.physPlanner),
         "planner of the physics plans")  //
        ("new-setup-every", po::value(&options.newSetupEvery)->default_value(options.newSetupEvery),
         "every so many plans, plan once on a new setup of each kind and drop it");
    const std::string usage =
        "usage: soak MANIPULATION.xml PHYSICS.xml [options]\n"
        "Plans many times in one process, alternating the two scenes on setups kept alive (cleared between\n"
        "plans) and new ones, and reports the resident memory. Exit status: 0 done, 2 bad input.";
    return ompl_core::exitStatusOf<po::error>(
        "soak",
        [&]
        {
            std::vector<std::string> scenes;
            if (!benchmarks::parseSceneFilesCommandLine(argc, argv, named, usage, scenes))
                return 0;
            if (scenes.size() != 2)
                throw po::error("give one manipulation scene and one physics scene");
            if (options.plans == 0 || options.every == 0 || options.newSetupEvery < 2 ||
                !(options.mmTimeLimit > 0.0) || !(options.physTimeLimit > 0.0))
                throw po::error(
                    "--plans and --every must be at least 1, --new-setup-every at least 2, "
                    "the time limits above 0");
            ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
            return soak(scenes[0], scenes[1], options);
        });
}
