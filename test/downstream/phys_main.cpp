// downstream_phys: the smallest program that uses an installed ompl_phys.
// Usage: downstream_phys [SCENE.xml]; without a scene it plans the installed physics scene 1 (the
// package's ompl_phys_SCENES_DIR). Exit 0 when the scene is solved and the controls, re-simulated,
// reach the goal.
#include <ompl_phys/control/PathSimulation.h>
#include <ompl_phys/control/PhysicsSetup.h>
#include <ompl_phys/scene/PhysicsSceneLoader.h>

#include <ompl/util/RandomNumbers.h>

#include <iostream>
#include <string>

int main(int argc, char **argv)
{
    if (argc > 2)
    {
        std::cerr << "usage: downstream_phys [SCENE.xml]\n";
        return 2;
    }
    const std::string file = argc == 2 ? argv[1] : SCENES_DIR "/scene1.xml";
    try
    {
        ompl::RNG::setSeed(1);
        // read the problem: robot, bodies with their knowledge, limits, goal
        const ompl_phys::PhysicsScene scene = ompl_phys::loadPhysicsScene(file);

        // a control::SimpleSetup with the ODE propagator; pick any OMPL control planner
        ompl_phys::PhysicsSetup setup(scene);
        setup.setPlannerByName("kpiece");
        setup.solve(60.0);
        if (!setup.haveExactSolution())
        {
            std::cerr << "downstream_phys: no exact solution found\n";
            return 1;
        }

        // replay the controls in a fresh simulation and compute the quality metrics
        const ompl_phys::SimulatedPath simulated = ompl_phys::simulatePath(setup, setup.getSolutionPath());
        if (!simulated.reachesGoal)
        {
            std::cerr << "downstream_phys: the re-simulated controls miss the goal\n";
            return 1;
        }
        std::cout << "downstream_phys: solved " << scene.name << ", action " << simulated.metrics.action
                  << '\n';
        return 0;
    }
    catch (const ompl::Exception &e)  // bad input: ompl_core::InputError names file:line
    {
        std::cerr << "downstream_phys: " << e.what() << '\n';
        return 2;
    }
}
