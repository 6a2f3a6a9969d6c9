// downstream_plan: the smallest program that uses an installed ompl_mm.
// Usage: downstream_plan [SCENE.xml]; without a scene it plans the installed MOBILE BLOCKED (the
// package's ompl_mm_SCENES_DIR). Exit 0 when the scene is solved and the path, also after OMPL's
// own simplification, re-checks.
#include <ompl_mm/scene/SceneLoader.h>
#include <ompl_mm/setup/ManipulationSetup.h>

#include <iostream>
#include <string>

int main(int argc, char **argv)
{
    if (argc > 2)
    {
        std::cerr << "usage: downstream_plan [SCENE.xml]\n";
        return 2;
    }
    const std::string file = argc == 2 ? argv[1] : SCENES_DIR "/mobile_blocked.xml";
    try
    {
        // read the problem: robot, obstacles, objects, start, goal, primitives, planner settings
        const ompl_mm::Scene scene = ompl_mm::loadScene(file);

        // a SimpleSetup with the manipulation state space, the goal and the MOPL planner
        ompl_mm::ManipulationSetup setup(scene);
        setup.mopl()->setSeed(1);

        // plan like with any SimpleSetup
        setup.solve(60.0);
        if (!setup.getProblemDefinition()->hasExactSolution())
        {
            std::cerr << "downstream_plan: no exact solution found\n";
            return 1;
        }

        // re-check every waypoint and segment of the solution, also after OMPL's simplifier
        if (!setup.manipulationPath().check())
        {
            std::cerr << "downstream_plan: the solution path failed its re-check\n";
            return 1;
        }
        setup.simplifySolution();
        if (!setup.manipulationPath().check() || !setup.manipulationPath().checkLabels().empty())
        {
            std::cerr << "downstream_plan: the simplified path failed its re-check\n";
            return 1;
        }
        std::cout << "downstream_plan: solved " << scene.name << " with "
                  << setup.manipulationPath().getStateCount() << " waypoints\n";
        return 0;
    }
    catch (const ompl::Exception &e)  // bad input: ompl_core::InputError names file:line
    {
        std::cerr << "downstream_plan: " << e.what() << '\n';
        return 2;
    }
}
