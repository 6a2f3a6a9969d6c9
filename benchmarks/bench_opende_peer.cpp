// bench_opende_peer: why not OMPL's own ODE extension? Ours (ompl_phys) beside the extension set up on
// the same scene data (the peer, OpenDEPeer.h), per physics scene:
// - time per ODE step of each side's propagator, alone and with the validity check of its result,
//   against a bare ODE loop on the side's own world (collide, QuickStep, empty the contacts), over the
//   same (state, force) pairs from a random tree grown from the scene's start;
// - per planner (RRT, KPIECE1, SyclopRRT) and seed 1..N: exact solutions, the median planning time,
//   and how many solutions, replayed open loop from their controls in a fresh world, reach the goal
//   without a fault: one geometric rule for both (the robot inside a fixed body, a movable body
//   tipped over or sunk into a fixed body or the floor) and each side's own rules.
// Usage: bench_opende_peer SCENE.xml... [--seeds N] [--time-limit S] [--planners LIST]
// Exit status: 0 done, 2 bad input.
#include "OpenDEPeer.h"
#include "ReplayJudge.h"

#include "SceneFilesCommandLine.h"

#include "ompl_core/io/InputError.h"
#include "ompl_core/io/TextFormat.h"
#include "ompl_core/run/ExitStatus.h"
#include "ompl_core/run/GlobalSeed.h"
#include "ompl_phys/control/PathSimulation.h"
#include "ompl_phys/control/PhysicsSetup.h"
#include "ompl_phys/scene/PhysicsSceneLoader.h"

#include <ompl/base/ScopedState.h>
#include <ompl/control/PathControl.h>
#include <ompl/control/spaces/RealVectorControlSpace.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include <boost/program_options.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <functional>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace po = boost::program_options;
namespace ob = ompl::base;
namespace oc = ompl::control;

namespace
{
    using Clock = std::chrono::steady_clock;

    /** (state, force) pairs each propagator is timed on, per scene. */
    constexpr std::size_t STEP_PAIRS = 2000;
    /** Timings are the best of this many repeats: the least disturbed by the rest of the machine. */
    constexpr int TIMING_REPEATS = 5;
    /** Seed of the random tree the timed pairs come from. */
    constexpr std::uint_fast32_t TREE_SEED = 1;
    /** ODE's global data, for the peer's worlds, while it lives (ours initialises ODE for its own). */
    class OdeLibrary
    {
    public:
        OdeLibrary() { dInitODE2(0); }
        ~OdeLibrary() { dCloseODE(); }
        OdeLibrary(const OdeLibrary &) = delete;
        OdeLibrary &operator=(const OdeLibrary &) = delete;
    };

    /** Every moving body's state and the force on the robot from it: one timed step. */
    struct StepPair
    {
        ompl_phys::BodyStates states;  ///< robot first, then the movable bodies in scene order
        Eigen::Vector2d force;         ///< on the robot, world x and y, N
    };

    /** count pairs from a random tree grown from the scene's start in ours' world as a planner grows
        one: each pair is a random node with a random force, whose result after one scene step joins
        the tree when it keeps ours' state rules (regions, speeds, the robot clear of fixed bodies).
        So the states stay within the limits planners keep and include pushes and contacts. */
    std::vector<StepPair> randomTreePairs(const ompl_phys::PhysicsSetup &setup, std::size_t count)
    {
        const ompl_phys::PhysicsScene &scene = setup.scene();
        ompl_phys::PhysicsWorld world(setup.world().scenePtr());
        ompl_phys::PhysicsWorld::resetRandomSeed();  // the same tree whatever ran before
        ompl::RNG rng(TREE_SEED);
        const double dt = scene.limits.stepSize / scene.contact.substeps;
        const double f = scene.limits.maxForce;
        std::vector<ompl_phys::BodyStates> tree{world.startStates()};
        std::vector<StepPair> pairs;
        while (pairs.size() < count)
        {
            const auto node = static_cast<std::size_t>(rng.uniformInt(0, static_cast<int>(tree.size()) - 1));
            pairs.push_back({tree[node], Eigen::Vector2d(rng.uniformReal(-f, f), rng.uniformReal(-f, f))});
            world.setStates(pairs.back().states);
            for (unsigned int k = 0; k < scene.contact.substeps; ++k)
                world.step(pairs.back().force, dt);
            ompl_phys::BodyStates next;
            world.readStates(next);
            if (setup.knowledge().checkStates(next) == ompl_phys::Violation::None)
                tree.push_back(std::move(next));
        }
        return pairs;
    }

    /** Seconds per ODE step, each the best of TIMING_REPEATS. */
    struct StepCost
    {
        double propagate{0.0};  ///< the side's propagator
        double validated{0.0};  ///< the propagator, then the validity check of its result, as planners do
        double bare{0.0};       ///< collide, QuickStep, empty the contacts: nothing else
    };

    /** The best of TIMING_REPEATS calls of secondsPerStep. */
    double fastest(const std::function<double()> &secondsPerStep)
    {
        double best = std::numeric_limits<double>::infinity();
        for (int r = 0; r < TIMING_REPEATS; ++r)
            best = std::min(best, secondsPerStep());
        return best;
    }

    double secondsSince(Clock::time_point start)
    {
        return std::chrono::duration<double>(Clock::now() - start).count();
    }

    /** The pairs as states and controls of si, written by writeState; freed with the object. */
    class OmplPairs
    {
    public:
        OmplPairs(oc::SpaceInformationPtr si, const std::vector<StepPair> &pairs,
                  const std::function<void(const ompl_phys::BodyStates &, ob::State *)> &writeState)
            : si_(std::move(si))
        {
            for (const StepPair &pair : pairs)
            {
                states_.push_back(si_->allocState());
                writeState(pair.states, states_.back());
                controls_.push_back(si_->allocControl());
                double *force = controls_.back()->as<oc::RealVectorControlSpace::ControlType>()->values;
                force[0] = pair.force.x();
                force[1] = pair.force.y();
            }
        }
        ~OmplPairs()
        {
            for (std::size_t i = 0; i < states_.size(); ++i)
            {
                si_->freeState(states_[i]);
                si_->freeControl(controls_[i]);
            }
        }
        OmplPairs(const OmplPairs &) = delete;
        OmplPairs &operator=(const OmplPairs &) = delete;

        std::size_t size() const { return states_.size(); }
        const ob::State *state(std::size_t i) const { return states_[i]; }
        const oc::Control *control(std::size_t i) const { return controls_[i]; }

    private:
        oc::SpaceInformationPtr si_;
        std::vector<ob::State *> states_;
        std::vector<oc::Control *> controls_;
    };

    /** Seconds to propagate every timed pair for duration, validating each result when asked. */
    double propagationSeconds(const oc::SpaceInformationPtr &si, const OmplPairs &timed, double duration,
                              bool validate)
    {
        ob::ScopedState<> result(si->getStateSpace());
        const Clock::time_point start = Clock::now();
        for (std::size_t i = 0; i < timed.size(); ++i)
        {
            si->getStatePropagator()->propagate(timed.state(i), timed.control(i), duration, result.get());
            if (validate)
                si->isValid(result.get());
        }
        return secondsSince(start);
    }

    /** Ours: PhysicsStatePropagator (a scene step of `substeps` ODE steps per call, fewer when a rule
        breaks) against PhysicsWorld::step in a world of its own. */
    StepCost oursStepCost(const ompl_phys::PhysicsSetup &setup, const std::vector<StepPair> &pairs)
    {
        const oc::SpaceInformationPtr &si = setup.getSpaceInformation();
        const OmplPairs timed(si, pairs,
                              [&](const ompl_phys::BodyStates &states, ob::State *state)
                              { setup.physicsSpace().writeState(states, state); });
        auto propagated = [&](bool validate)
        {
            const unsigned long long before = setup.propagator().counters().substeps;
            const double seconds = propagationSeconds(si, timed, si->getPropagationStepSize(), validate);
            return seconds / static_cast<double>(setup.propagator().counters().substeps - before);
        };

        ompl_phys::PhysicsWorld world(setup.world().scenePtr());
        const unsigned int substeps = setup.scene().contact.substeps;
        const double dt = si->getPropagationStepSize() / substeps;
        auto bare = [&]
        {
            const Clock::time_point start = Clock::now();
            for (const StepPair &pair : pairs)
            {
                world.setStates(pair.states);
                for (unsigned int k = 0; k < substeps; ++k)
                    world.step(pair.force, dt);
            }
            return secondsSince(start) / static_cast<double>(pairs.size() * substeps);
        };
        return {fastest([&] { return propagated(false); }), fastest([&] { return propagated(true); }),
                fastest(bare)};
    }

    /** The peer's contacts and nothing else (no validity, no allocation): the bare loop's callback. */
    void createPeerContacts(void *data, dGeomID a, dGeomID b)
    {
        const auto &environment = *static_cast<const opende_peer::PeerEnvironment *>(data);
        const unsigned int most = environment.getMaxContacts(a, b);
        if (most == 0)
            return;
        std::array<dContact, 16> contacts;  // the scene loader allows at most 16 per pair
        const int count = dCollide(a, b, static_cast<int>(most), &contacts[0].geom, sizeof(dContact));
        for (int i = 0; i < count; ++i)
        {
            environment.setupContact(a, b, contacts[i]);
            dJointID joint = dJointCreateContact(environment.world_, environment.contactGroup_, &contacts[i]);
            dJointAttach(joint, dGeomGetBody(a), dGeomGetBody(b));
        }
    }

    /** The peer: OpenDEStatePropagator (one ODE step per call) against a bare loop in its world. */
    StepCost peerStepCost(const opende_peer::PeerSetup &setup, const std::vector<StepPair> &pairs)
    {
        const oc::SpaceInformationPtr &si = setup.getSpaceInformation();
        const opende_peer::PeerEnvironment &environment = setup.environment();
        const auto &space = *setup.getStateSpace()->as<oc::OpenDEStateSpace>();
        const OmplPairs timed(si, pairs,
                              [&](const ompl_phys::BodyStates &states, ob::State *state)
                              {
                                  environment.placeBodies(states);
                                  space.readState(state);
                              });
        const double dt = environment.stepSize_;
        const auto steps = static_cast<double>(pairs.size());
        auto propagated = [&](bool validate) { return propagationSeconds(si, timed, dt, validate) / steps; };
        auto bare = [&]
        {
            const Clock::time_point start = Clock::now();
            for (const StepPair &pair : pairs)
            {
                environment.placeBodies(pair.states);
                environment.applyControl(pair.force.data());
                // ODE hands its callback's data over as a plain void *
                dSpaceCollide(environment.collisionSpaces_.front(),
                              const_cast<void *>(static_cast<const void *>(&environment)),
                              createPeerContacts);
                dWorldQuickStep(environment.world_, dt);
                dJointGroupEmpty(environment.contactGroup_);
            }
            return secondsSince(start) / steps;
        };
        return {fastest([&] { return propagated(false); }), fastest([&] { return propagated(true); }),
                fastest(bare)};
    }

    /** The label of a replay: empty when it is clean, else its first fault (or "missed the goal") and
        whether the robot ends in the goal disc anyway. */
    std::string replayVerdict(const std::string &firstFault, const ompl_phys::GoalDisc &goal,
                              const ompl_phys::BodyStates &last)
    {
        const bool inGoal = (last[0].position.head<2>() - goal.centre).norm() <= goal.radius;
        if (firstFault.empty())
            return inGoal ? "" : "missed the goal";
        return firstFault + (inGoal ? ", yet ends in the goal" : ", ends outside the goal");
    }

    /** Replays path's controls from the start in a fresh PhysicsSetup through simulatePath (which
        stops at the first broken rule of ours) and judges every state it passes. */
    std::string replayOurs(const ompl_phys::PhysicsScenePtr &scene, const oc::PathControl &path,
                           const opende_peer::ReplayJudge &judge)
    {
        ompl_phys::PhysicsSetup fresh(scene);
        oc::PathControl replayed(fresh.getSpaceInformation());
        replayed.append(fresh.getProblemDefinition()->getStartState(0));
        for (std::size_t i = 0; i < path.getControlCount(); ++i)
            replayed.append(path.getState(i + 1), path.getControl(i), path.getControlDuration(i));
        const ompl_phys::SimulatedPath simulated = ompl_phys::simulatePath(fresh, replayed);
        std::string fault;
        for (std::size_t i = 0; i < simulated.states.size() && fault.empty(); ++i)
            fault = judge.fault(simulated.states[i]);
        if (fault.empty() && simulated.violation != ompl_phys::Violation::None)
            fault = std::string("broke its rule: ") + ompl_phys::violationName(simulated.violation);
        return replayVerdict(fault, scene->goal, simulated.states.back());
    }

    /** Replays path's controls from the start to their end in a fresh PeerSetup, one ODE step at a
        time through its propagator as its planners propagate, and judges the state after every
        step by the geometric rule and by the peer's own validity. */
    std::string replayPeer(const ompl_phys::PhysicsScenePtr &scene, const oc::PathControl &path,
                           const opende_peer::ReplayJudge &judge)
    {
        opende_peer::PeerSetup fresh(scene);
        const oc::SpaceInformationPtr &si = fresh.getSpaceInformation();
        const auto &space = *si->getStateSpace()->as<oc::OpenDEStateSpace>();
        const double step = fresh.environment().stepSize_;
        ob::ScopedState<oc::OpenDEStateSpace> current = fresh.getCurrentState();
        ob::ScopedState<oc::OpenDEStateSpace> next(si->getStateSpace());
        std::string fault;
        for (std::size_t i = 0; i < path.getControlCount(); ++i)
        {
            const long steps = std::lround(path.getControlDuration(i) / step);
            for (long k = 0; k < steps; ++k)
            {
                si->getStatePropagator()->propagate(current.get(), path.getControl(i), step, next.get());
                current = next;
                if (!fault.empty())
                    continue;
                fault = judge.fault(fresh.bodyStates(next.get()));
                if (fault.empty() && !si->isValid(next.get()))
                    fault = space.satisfiesBoundsExceptRotation(next.get())
                                ? "broke its rule: robot touched a fixed body"
                                : "broke its rule: out of bounds (a region or a speed limit)";
            }
        }
        return replayVerdict(fault, scene->goal, fresh.bodyStates(current.get()));
    }

    /** One planning run of one side. */
    struct Run
    {
        bool solved{false};       ///< an exact solution
        double seconds{0.0};      ///< planning time
        std::string replayFault;  ///< for a solved run: its replay's verdict, empty when clean

        /** One line for the progress log. */
        std::string summary() const
        {
            std::ostringstream line;
            line << (solved ? "solved" : "not solved") << " in " << seconds << " s";
            if (!replayFault.empty())
                line << ", replay: " << replayFault;
            return line.str();
        }
    };

    /** Plans as the app does, seeded before the setup is made and again right before solving, and
        replays an exact solution with replay(path). */
    template <typename Setup, typename Replay>
    Run plan(const ompl_phys::PhysicsScenePtr &scene, const std::string &planner, std::uint32_t seed,
             double timeLimit, Replay &&replay)
    {
        ompl_core::reseedOmpl(seed);
        Setup setup(scene);
        setup.setPlannerByName(planner);
        setup.setup();
        ompl_core::reseedOmpl(seed);
        setup.solve(timeLimit);
        Run run;
        run.solved = setup.getProblemDefinition()->hasExactSolution();
        run.seconds = setup.getLastPlanComputationTime();
        if (run.solved)
            run.replayFault = replay(setup.getSolutionPath());
        return run;
    }

    /** The runs of one side with one planner on one scene. */
    struct Tally
    {
        std::vector<double> seconds;
        int solved{0};
        int clean{0};                       ///< solved runs whose replay is clean
        std::map<std::string, int> faults;  ///< solved runs whose replay is not, by first fault

        void add(const Run &run)
        {
            seconds.push_back(run.seconds);
            if (!run.solved)
                return;
            ++solved;
            if (run.replayFault.empty())
                ++clean;
            else
                ++faults[run.replayFault];
        }

        /** Median planning time over every run, solved or not. */
        double median() const
        {
            std::vector<double> sorted = seconds;
            std::sort(sorted.begin(), sorted.end());
            const std::size_t n = sorted.size();
            return n % 2 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
        }
    };

    struct Options
    {
        std::vector<std::string> scenes;
        long long seeds{10};  // signed, so that a negative count is caught rather than wrapped
        double timeLimit{60.0};
        std::string planners{"rrt,kpiece,sycloprrt"};
        std::vector<std::string> plannerList;  ///< planners split and checked
    };

    /** Reads the command line into options; false when the program should exit with exitCode
        instead (after --help).
        @throws boost::program_options::error for a malformed command line or no scene,
        ompl_core::InputError for a value out of range or an unknown planner. */
    bool parseOptions(int argc, char **argv, Options &options, int &exitCode)
    {
        po::options_description named("Options");
        named.add_options()("help,h", "print this help and exit")(
            "seeds", po::value(&options.seeds)->default_value(options.seeds)->value_name("N"),
            "runs per scene, planner and side, with seeds 1..N (at least 1)")(
            "time-limit", po::value(&options.timeLimit)->default_value(options.timeLimit)->value_name("S"),
            "planning time per run, seconds (positive)")(
            "planners", po::value(&options.planners)->default_value(options.planners)->value_name("LIST"),
            "comma-separated planners: rrt, kpiece, sycloprrt");
        if (!benchmarks::parseSceneFilesCommandLine(
                argc, argv, named,
                "Usage: bench_opende_peer SCENE.xml... [options]\n"
                "Ours (ompl_phys) beside OMPL's own ODE extension on physics scenes: time per ODE "
                "step,\nplanning with RRT, KPIECE1 and SyclopRRT, and open-loop replays of the "
                "solutions.\nExit status: 0 done, 2 bad input.",
                options.scenes))
        {
            exitCode = 0;
            return false;
        }
        if (options.seeds < 1)
            throw ompl_core::InputError("--seeds must be at least 1, got " + std::to_string(options.seeds));
        if (!(options.timeLimit > 0.0) || !std::isfinite(options.timeLimit))
            throw ompl_core::InputError("--time-limit must be a positive number of seconds, got " +
                                        ompl_core::exactText(options.timeLimit));
        const std::vector<std::string> &known = opende_peer::PeerSetup::plannerNames();
        std::stringstream list(options.planners);
        for (std::string name; std::getline(list, name, ',');)
        {
            if (std::find(known.begin(), known.end(), name) == known.end())
            {
                std::string names;
                for (const std::string &k : known)
                    names += (names.empty() ? "" : ", ") + k;
                throw ompl_core::InputError("--planners: unknown planner '" + name + "' (known: " + names +
                                            ")");
            }
            options.plannerList.push_back(name);
        }
        if (options.plannerList.empty())
            throw ompl_core::InputError("--planners names no planner");
        return true;
    }

    void printStepCosts(const std::vector<ompl_phys::PhysicsScenePtr> &scenes,
                        const std::vector<StepCost> &ours, const std::vector<StepCost> &peer)
    {
        std::cout << "\n## Cost per ODE step (" << STEP_PAIRS << " pairs, best of " << TIMING_REPEATS
                  << ")\n\n| scene | side | propagate [µs] | propagate + validity [µs] | bare ODE loop [µs] "
                     "| propagate / bare | with validity / bare |\n|---|---|---|---|---|---|---|\n";
        for (std::size_t s = 0; s < scenes.size(); ++s)
            for (const auto &[side, cost] : {std::pair{"ours", ours[s]}, std::pair{"peer", peer[s]}})
                std::cout << std::fixed << std::setprecision(2) << "| " << scenes[s]->name << " | " << side
                          << " | " << 1e6 * cost.propagate << " | " << 1e6 * cost.validated << " | "
                          << 1e6 * cost.bare << " | " << cost.propagate / cost.bare << " | "
                          << cost.validated / cost.bare << " |\n";
    }

    /** One scene and planner: both sides' runs. */
    struct Row
    {
        std::string scene;
        std::string planner;
        Tally ours;
        Tally peer;
    };

    void printPlanning(const std::vector<Row> &rows, const Options &options)
    {
        std::cout << "\n## Planning (" << options.seeds << " seeds, " << options.timeLimit
                  << " s each; median over all runs; clean replays of the solved)\n\n"
                     "| scene | planner | solved, ours | solved, peer | median [s], ours | median [s], peer "
                     "| clean replays, ours | clean replays, peer |\n|---|---|---|---|---|---|---|---|\n";
        for (const Row &row : rows)
            std::cout << std::fixed << std::setprecision(2) << "| " << row.scene << " | " << row.planner
                      << " | " << row.ours.solved << "/" << options.seeds << " | " << row.peer.solved << "/"
                      << options.seeds << " | " << row.ours.median() << " | " << row.peer.median() << " | "
                      << row.ours.clean << "/" << row.ours.solved << " | " << row.peer.clean << "/"
                      << row.peer.solved << " |\n";
        std::cout
            << "\n## Replays that fail, by first fault\n\n| scene | planner | side | fault | replays |\n"
               "|---|---|---|---|---|\n";
        for (const Row &row : rows)
            for (const auto &[side, tally] : {std::pair{"ours", &row.ours}, std::pair{"peer", &row.peer}})
                for (const auto &[fault, count] : tally->faults)
                    std::cout << "| " << row.scene << " | " << row.planner << " | " << side << " | " << fault
                              << " | " << count << " |\n";
    }

    void printNotes(const std::vector<ompl_phys::PhysicsScenePtr> &scenes)
    {
        std::cout
            << "\n## Notes\n\n- Replays are judged at every state they pass (ours: every scene step, "
               "whose ODE sub-steps its propagator judges by its own rules, up to the first broken one; "
               "the peer: every ODE step, to the end) with a tolerance of "
            << std::defaultfloat << 1000.0 * opende_peer::PENETRATION_TOLERANCE << " mm for penetration and "
            << opende_peer::TIP_TOLERANCE * 180.0 / M_PI
            << " degrees for tipping; a failed replay is listed by its first fault.\n";
        for (const ompl_phys::PhysicsScenePtr &scene : scenes)
        {
            std::string constrained;
            for (const ompl_phys::PhysicsBody &body : scene->bodies)
                if (body.kind == ompl_phys::BodyKind::Constrained)
                    constrained += (constrained.empty() ? "" : ", ") + body.name;
            if (!constrained.empty())
                std::cout << "- " << scene->name << ": the peer plans with the constraint-oriented "
                          << constrained << " free (see below).\n";
        }
        std::cout << "- How the peer differs from ours (what OMPL's ODE extension cannot express or does its "
                     "own way):\n";
        for (const std::string &difference : opende_peer::peerDifferences())
            std::cout << "  - " << difference << '\n';
    }

    int run(const Options &options)
    {
        ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
        const OdeLibrary ode;
        // load every scene first: a bad file should not cost the measurements before it
        std::vector<ompl_phys::PhysicsScenePtr> scenes;
        for (const std::string &file : options.scenes)
            scenes.push_back(
                std::make_shared<const ompl_phys::PhysicsScene>(ompl_phys::loadPhysicsScene(file)));

        std::vector<StepCost> oursCosts, peerCosts;
        std::vector<Row> rows;
        for (const ompl_phys::PhysicsScenePtr &scene : scenes)
        {
            {
                ompl_phys::PhysicsSetup ours(scene);
                opende_peer::PeerSetup peer(scene);
                const std::vector<StepPair> pairs = randomTreePairs(ours, STEP_PAIRS);
                oursCosts.push_back(oursStepCost(ours, pairs));
                peerCosts.push_back(peerStepCost(peer, pairs));
            }
            const opende_peer::ReplayJudge judge(scene);
            const auto replayOursJudged = [&](const oc::PathControl &path)
            { return replayOurs(scene, path, judge); };
            const auto replayPeerJudged = [&](const oc::PathControl &path)
            { return replayPeer(scene, path, judge); };
            for (const std::string &planner : options.plannerList)
            {
                Row row{scene->name, planner, {}, {}};
                for (long long seed = 1; seed <= options.seeds; ++seed)
                {
                    const auto s = static_cast<std::uint32_t>(seed);
                    const Run ours =
                        plan<ompl_phys::PhysicsSetup>(scene, planner, s, options.timeLimit, replayOursJudged);
                    const Run peer =
                        plan<opende_peer::PeerSetup>(scene, planner, s, options.timeLimit, replayPeerJudged);
                    row.ours.add(ours);
                    row.peer.add(peer);
                    std::cerr << scene->name << ' ' << planner << " seed " << seed << ": ours "
                              << ours.summary() << "; peer " << peer.summary() << '\n';
                }
                rows.push_back(std::move(row));
            }
        }
        printStepCosts(scenes, oursCosts, peerCosts);
        printPlanning(rows, options);
        printNotes(scenes);
        return 0;
    }
}  // namespace

int main(int argc, char **argv)
{
    return ompl_core::exitStatusOf<po::error>(
        "bench_opende_peer",
        [&]
        {
            Options options;
            int exitCode = 0;
            return parseOptions(argc, argv, options, exitCode) ? run(options) : exitCode;
        });
}
