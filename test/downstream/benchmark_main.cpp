// A user's benchmark program built against the installed ompl_bench package: it adds a planner of its
// own (OMPL's control RRT under another name and goal bias) and hands the command line to the tool.
#include <ompl_bench/app/BenchmarkApp.h>
#include <ompl_phys/control/PhysicsSetup.h>

#include <ompl/control/planners/rrt/RRT.h>

int main(int argc, char **argv)
{
    ompl_phys::PhysicsSetup::plannerRegistry().add(
        "greedy_rrt", "control RRT with goal bias 0.5",
        [](ompl_phys::PhysicsSetup &setup)
        {
            auto rrt = std::make_shared<ompl::control::RRT>(setup.getSpaceInformation());
            rrt->setGoalBias(0.5);
            return rrt;
        });
    return ompl_bench::benchmarkMain(argc, argv);
}
