// bench_propagation: time per ODE sub-step inside PhysicsStatePropagator (reseed, write the state,
// step ODE with contacts, judge every sub-step by the knowledge, read the state back) against a
// bare ODE loop on the same world from the same states with the same forces (write the bodies,
// then dSpaceCollide + dWorldQuickStep + dJointGroupEmpty per sub-step, nothing else). The states
// come from a random walk of the robot from the scene's start, so they include pushes and contacts.
// Usage: bench_propagation SCENE.xml... [--steps N] [--repeats R]   (default: 2000 steps, best of 5
// repeats). Exit status: 0 done, 2 bad input.
#include "SceneFilesCommandLine.h"

#include "ompl_core/io/InputError.h"
#include "ompl_core/run/ExitStatus.h"
#include "ompl_phys/control/PhysicsSetup.h"
#include "ompl_phys/scene/PhysicsSceneLoader.h"

#include <ompl/base/ScopedState.h>
#include <ompl/control/spaces/RealVectorControlSpace.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include <boost/program_options.hpp>

#include <algorithm>
#include <chrono>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

namespace po = boost::program_options;

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

    struct Options
    {
        std::vector<std::string> scenes;
        long long steps{2000};  // signed, so that a negative count is caught rather than wrapped
        long long repeats{5};
    };

    /** Reads the command line into options; false when the program should exit with exitCode
        instead (after --help).
        @throws boost::program_options::error for a malformed command line or no scene,
        ompl_core::InputError for a value out of range. */
    bool parseOptions(int argc, char **argv, Options &options, int &exitCode)
    {
        po::options_description named("Options");
        named.add_options()("help,h", "print this help and exit")(
            "steps", po::value(&options.steps)->default_value(options.steps)->value_name("N"),
            "(state, control) pairs of the random walk, each propagated once per repeat (at least 1)")(
            "repeats", po::value(&options.repeats)->default_value(options.repeats)->value_name("R"),
            "repeats of the timing; the best counts (at least 1)");
        if (!benchmarks::parseSceneFilesCommandLine(
                argc, argv, named,
                "Usage: bench_propagation SCENE.xml... [options]\n"
                "Time per ODE sub-step of PhysicsStatePropagator against a bare ODE loop on the "
                "same states and\nforces, per physics scene (a random walk of its robot).\n"
                "Exit status: 0 done, 2 bad input.",
                options.scenes))
        {
            exitCode = 0;
            return false;
        }
        if (options.steps < 1)
            throw ompl_core::InputError("--steps must be at least 1, got " + std::to_string(options.steps));
        if (options.repeats < 1)
            throw ompl_core::InputError("--repeats must be at least 1, got " +
                                        std::to_string(options.repeats));
        return true;
    }

    int run(const Options &options)
    {
        ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
        ompl::RNG::setSeed(1);
        // load every scene first: a bad file should not cost the measurements before it
        std::vector<ompl_phys::PhysicsScene> scenes;
        for (const std::string &file : options.scenes)
            scenes.push_back(ompl_phys::loadPhysicsScene(file));
        std::cout << "| scene | propagator, per sub-step [µs] | bare ODE loop, per sub-step [µs] | ratio |\n"
                  << "|---|---|---|---|\n";
        for (const ompl_phys::PhysicsScene &scene : scenes)
        {
            ompl_phys::PhysicsSetup setup(scene);
            setup.setup();
            const Walk walk = randomWalk(setup, static_cast<std::size_t>(options.steps));
            // best of several repeats: the least disturbed by the rest of the machine
            double propagated = 1e300, bare = 1e300;
            for (long long r = 0; r < options.repeats; ++r)
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
}  // namespace

int main(int argc, char **argv)
{
    return ompl_core::exitStatusOf<po::error>(
        "bench_propagation",
        [&]
        {
            Options options;
            int exitCode = 0;
            return parseOptions(argc, argv, options, exitCode) ? run(options) : exitCode;
        });
}
