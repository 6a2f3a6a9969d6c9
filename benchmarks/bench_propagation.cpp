// bench_propagation: time per ODE sub-step inside PhysicsStatePropagator (reseed, write the state,
// step ODE with contacts, judge every sub-step by the knowledge, read the state back) against a
// bare ODE loop on the same world from the same states with the same forces (write the bodies,
// then dSpaceCollide + dWorldQuickStep + dJointGroupEmpty per sub-step, nothing else). The states
// come from a random walk of the robot from the scene's start, so they include pushes and contacts.
// Usage: bench_propagation SCENE.xml... [--steps N] [--repeats R]
#include "ompl_phys/control/PhysicsSetup.h"
#include "ompl_phys/scene/PhysicsSceneLoader.h"

#include <ompl/base/ScopedState.h>
#include <ompl/control/spaces/RealVectorControlSpace.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

namespace
{
    using Clock = std::chrono::steady_clock;

    /** A random walk of the robot from the start: the states it passes and the controls it applies. */
    struct Walk
    {
        std::vector<ompl::base::State *> states;
        std::vector<ompl::control::Control *> controls;
    };

    Walk randomWalk(ompl_phys::PhysicsSetup &setup, std::size_t steps)
    {
        const auto &si = setup.getSpaceInformation();
        auto sampler = si->allocControlSampler();
        Walk walk;
        ompl::base::ScopedState<> current(si->getStateSpace(),
                                          setup.getProblemDefinition()->getStartState(0));
        ompl::control::Control *control = si->allocControl();
        for (std::size_t i = 0; i < steps; ++i)
        {
            if (i % 10 == 0)  // hold a force for ten steps, as planners hold controls
                sampler->sample(control);
            walk.states.push_back(si->cloneState(current.get()));
            walk.controls.push_back(si->cloneControl(control));
            ompl::base::ScopedState<> next(si->getStateSpace());
            si->getStatePropagator()->propagate(current.get(), control, si->getPropagationStepSize(),
                                                next.get());
            if (si->isValid(next.get()))
                current = next;
            else
                current = setup.getProblemDefinition()->getStartState(0);
        }
        si->freeControl(control);
        return walk;
    }

    /** Seconds per ODE sub-step when propagating every walk state with its control. */
    double propagatorSecondsPerSubstep(ompl_phys::PhysicsSetup &setup, const Walk &walk)
    {
        const auto &si = setup.getSpaceInformation();
        const auto &propagator = setup.propagator();
        ompl::base::State *result = si->allocState();
        const unsigned long long before = propagator.counters().substeps;
        const auto start = Clock::now();
        for (std::size_t i = 0; i < walk.states.size(); ++i)
            propagator.propagate(walk.states[i], walk.controls[i], si->getPropagationStepSize(), result);
        const std::chrono::duration<double> elapsed = Clock::now() - start;
        si->freeState(result);
        return elapsed.count() / static_cast<double>(propagator.counters().substeps - before);
    }

    /** Seconds per ODE sub-step of a bare loop from every walk state with its force. */
    double bareSecondsPerSubstep(ompl_phys::PhysicsSetup &setup, const Walk &walk)
    {
        ompl_phys::PhysicsWorld world(setup.world().scenePtr());
        const unsigned int substeps = setup.scene().contact.substeps;
        const double dt = setup.scene().limits.stepSize / substeps;
        std::vector<ompl_phys::BodyStates> states(walk.states.size());
        std::vector<Eigen::Vector2d> forces;
        for (std::size_t i = 0; i < walk.states.size(); ++i)
        {
            setup.physicsSpace().readState(walk.states[i], states[i]);
            const double *f =
                walk.controls[i]->as<ompl::control::RealVectorControlSpace::ControlType>()->values;
            forces.emplace_back(f[0], f[1]);
        }
        const auto start = Clock::now();
        for (std::size_t i = 0; i < states.size(); ++i)
        {
            world.setStates(states[i]);
            for (unsigned int k = 0; k < substeps; ++k)
                world.step(forces[i], dt);
        }
        const std::chrono::duration<double> elapsed = Clock::now() - start;
        return elapsed.count() / static_cast<double>(states.size() * substeps);
    }
}  // namespace

int main(int argc, char **argv)
{
    std::vector<std::string> scenes;
    std::size_t steps = 2000;
    int repeats = 5;
    for (int i = 1; i < argc; ++i)
    {
        if (std::strcmp(argv[i], "--steps") == 0 && i + 1 < argc)
            steps = std::stoul(argv[++i]);
        else if (std::strcmp(argv[i], "--repeats") == 0 && i + 1 < argc)
            repeats = std::stoi(argv[++i]);
        else
            scenes.emplace_back(argv[i]);
    }
    if (scenes.empty() || steps == 0 || repeats < 1)
    {
        std::cerr << "usage: bench_propagation SCENE.xml... [--steps N] [--repeats R]\n";
        return 2;
    }
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    ompl::RNG::setSeed(1);
    std::cout << "| scene | propagator, per sub-step [µs] | bare ODE loop, per sub-step [µs] | ratio |\n"
              << "|---|---|---|---|\n";
    for (const std::string &file : scenes)
    {
        const ompl_phys::PhysicsScene scene = ompl_phys::loadPhysicsScene(file);
        ompl_phys::PhysicsSetup setup(scene);
        setup.setup();
        const Walk walk = randomWalk(setup, steps);
        // best of several repeats: the least disturbed by the rest of the machine
        double propagated = 1e300, bare = 1e300;
        for (int r = 0; r < repeats; ++r)
        {
            propagated = std::min(propagated, propagatorSecondsPerSubstep(setup, walk));
            bare = std::min(bare, bareSecondsPerSubstep(setup, walk));
        }
        std::cout << std::fixed << std::setprecision(2) << "| " << scene.name << " | " << 1e6 * propagated
                  << " | " << 1e6 * bare << " | " << propagated / bare << " |\n";
        for (std::size_t i = 0; i < walk.states.size(); ++i)
        {
            setup.getSpaceInformation()->freeState(walk.states[i]);
            setup.getSpaceInformation()->freeControl(walk.controls[i]);
        }
    }
    return 0;
}
