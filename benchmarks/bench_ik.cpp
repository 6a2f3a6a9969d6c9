// Inverse kinematics on the protocol IK libraries publish: random joint configurations uniformly within
// the limits, their tool poses by forward kinematics, then full 6-D IK of each pose to 1e-5, seeded from
// the middle of the joint ranges, at most 5 ms per query. Reports the solve rate and the mean time per
// query (failures included) for our IkSolver and, on the same poses, Orocos KDL's ChainIkSolverPos_NR_JL
// and ChainIkSolverPos_LMA (KDL chains built from the same RobotModel).
//
// Usage: bench_ik [URDF] [--queries N] [--tip LINK] [--seed S] [--iterations N] [--stall N]
// [--damping D] [--posture G]   (default: scenes/robots/kuka_lwr.urdf, 10000 queries, tip "tool", seed 1, the
// solver's own iterations, damping and posture gain). Exit status: 0 done, 2 bad input.
#include "ompl_core/io/InputError.h"
#include "ompl_core/run/CommandLine.h"
#include "ompl_core/run/ExitStatus.h"
#include "ompl_mm/robot/IkSolver.h"
#include "ompl_mm/robot/RobotModel.h"

#include <kdl/chain.hpp>
#include <kdl/chainfksolverpos_recursive.hpp>
#include <kdl/chainiksolverpos_lma.hpp>
#include <kdl/chainiksolverpos_nr_jl.hpp>
#include <kdl/chainiksolvervel_pinv.hpp>

#include <ompl/util/RandomNumbers.h>

#include <boost/program_options.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace po = boost::program_options;

namespace
{
    constexpr double TOLERANCE = 1e-5;
    constexpr double TIME_LIMIT = 0.005;

    KDL::Frame kdlFrame(const Eigen::Isometry3d &pose)
    {
        const Eigen::Matrix3d r = pose.linear();
        return KDL::Frame(
            KDL::Rotation(r(0, 0), r(0, 1), r(0, 2), r(1, 0), r(1, 1), r(1, 2), r(2, 0), r(2, 1), r(2, 2)),
            KDL::Vector(pose.translation().x(), pose.translation().y(), pose.translation().z()));
    }

    /** The same chain for KDL: a fixed segment to the first joint, then one segment per joint that
        carries the fixed transform to the next joint (or the tool). */
    KDL::Chain kdlChain(const ompl_mm::KinematicChain &chain)
    {
        KDL::Chain kdl;
        kdl.addSegment(KDL::Segment(KDL::Joint(KDL::Joint::None), kdlFrame(chain.before(0))));
        for (unsigned int i = 0; i < chain.size(); ++i)
        {
            const Eigen::Vector3d &a = chain.axis(i);
            const KDL::Joint joint("j" + std::to_string(i), KDL::Vector::Zero(),
                                   KDL::Vector(a.x(), a.y(), a.z()),
                                   chain.prismatic(i) ? KDL::Joint::TransAxis : KDL::Joint::RotAxis);
            kdl.addSegment(
                KDL::Segment(joint, kdlFrame(i + 1 < chain.size() ? chain.before(i + 1) : chain.after())));
        }
        return kdl;
    }

    struct Result
    {
        unsigned int solved{0};
        double seconds{0.0};
    };

    /** Times solve on every target; it says whether it reached the target within the limit. */
    Result measure(const std::vector<Eigen::Isometry3d> &targets,
                   const std::function<bool(const Eigen::Isometry3d &)> &solve)
    {
        Result result;
        for (const Eigen::Isometry3d &target : targets)
        {
            const auto start = std::chrono::steady_clock::now();
            const bool ok = solve(target);
            const double seconds =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            result.seconds += seconds;
            result.solved += ok && seconds <= TIME_LIMIT ? 1 : 0;
        }
        return result;
    }

    void print(const char *name, const Result &result, std::size_t queries)
    {
        std::printf("| %-32s | %8.2f %% | %8.3f ms |\n", name,
                    100.0 * result.solved / static_cast<double>(queries),
                    1000.0 * result.seconds / static_cast<double>(queries));
    }

    struct Options
    {
        std::string urdf{std::string(OMPL_MM_SCENES_DIR) + "/robots/kuka_lwr.urdf"};
        std::string tip{"tool"};
        long long queries{10000};  // signed, so that a negative count is caught rather than wrapped
        long long seed{1};
        long long iterations{0};                 ///< 0: the solver's default
        std::optional<long long> stall;          ///< unset: the solver's default
        std::optional<double> damping, posture;  ///< unset: the solver's defaults
    };

    /** @throws ompl_core::InputError with message unless ok. */
    void require(bool ok, const std::string &message)
    {
        if (!ok)
            throw ompl_core::InputError(message);
    }

    /** The value of option name when given, checked to be finite and not negative. */
    std::optional<double> nonNegative(const po::variables_map &vm, const char *name)
    {
        if (!vm.count(name))
            return std::nullopt;
        const double value = vm[name].as<double>();
        std::ostringstream text;
        text << value;
        require(std::isfinite(value) && value >= 0.0,
                std::string("--") + name + " must be a finite number of at least 0, got " + text.str());
        return value;
    }

    /** Reads the command line into options; false when the program should exit with exitCode
        instead (after --help).
        @throws boost::program_options::error for a malformed command line, ompl_core::InputError for
        a value out of range. */
    bool parseOptions(int argc, char **argv, Options &options, int &exitCode)
    {
        po::options_description named("Options");
        named.add_options()("help,h", "print this help and exit")(
            "queries", po::value(&options.queries)->default_value(options.queries)->value_name("N"),
            "random reachable poses to solve (at least 1)")(
            "tip", po::value(&options.tip)->default_value(options.tip)->value_name("LINK"),
            "the link whose pose is solved for")(
            "seed", po::value(&options.seed)->default_value(options.seed)->value_name("S"),
            "random seed of the poses, in [1, 4294967295]")(
            "iterations", po::value(&options.iterations)->value_name("N"),
            "iterations of one IkSolver attempt (0 or unset: the solver's default)")(
            "stall", po::value<long long>()->value_name("N"),
            "IkSolver's ik_stall_iterations, 0 for never (unset: the solver's default)")(
            "damping", po::value<double>()->value_name("D"),
            "IkSolver's damping, at least 0 (unset: the solver's default)")(
            "posture", po::value<double>()->value_name("G"),
            "IkSolver's gain towards mid-range joints, at least 0 (unset: the solver's default)");
        const po::variables_map vm = ompl_core::parseCommandLine(argc, argv, named, "urdf", options.urdf);
        if (vm.count("help"))
        {
            std::cout << "Usage: bench_ik [URDF] [options]\n"
                         "Full 6-D inverse kinematics of random reachable poses of a URDF robot's tip link "
                         "(default URDF:\n"
                         "scenes/robots/kuka_lwr.urdf) with ompl_mm's IkSolver and Orocos KDL's NR_JL and "
                         "LMA solvers.\n"
                         "Exit status: 0 done, 2 bad input.\n\n"
                      << named;
            exitCode = 0;
            return false;
        }
        require(options.queries >= 1, "--queries must be at least 1, got " + std::to_string(options.queries));
        require(options.seed >= 1 && options.seed <= 4294967295LL,
                "--seed must be in [1, 4294967295], got " + std::to_string(options.seed));
        require(options.iterations >= 0 && options.iterations <= 4294967295LL,
                "--iterations must be in [0, 4294967295], got " + std::to_string(options.iterations));
        if (vm.count("stall"))
        {
            options.stall = vm["stall"].as<long long>();
            require(*options.stall >= 0 && *options.stall <= 4294967295LL,
                    "--stall must be in [0, 4294967295], got " + std::to_string(*options.stall));
        }
        options.damping = nonNegative(vm, "damping");
        options.posture = nonNegative(vm, "posture");
        return true;
    }

    int run(const Options &options)
    {
        const std::string &urdf = options.urdf, &tip = options.tip;
        const auto queries = static_cast<std::size_t>(options.queries);
        const auto seed = static_cast<std::uint_fast32_t>(options.seed);
        const ompl_mm::RobotModel robot = ompl_mm::RobotModel::fromUrdfFile(urdf);
        const ompl_mm::KinematicChain chain(robot, robot.linkIndex(tip));
        const Eigen::Isometry3d base = Eigen::Isometry3d::Identity();
        const unsigned int n = chain.size();
        require(n > 0, "no moving joint between the root of robot '" + robot.name() + "' and link '" + tip +
                           "': nothing to solve");  // kdlChain needs a joint

        ompl::RNG rng(seed);
        std::vector<double> middle(robot.dof(), 0.0);
        for (unsigned int i = 0; i < n; ++i)
            middle[chain.variable(i)] = 0.5 * (chain.lower(i) + chain.upper(i));
        std::vector<Eigen::Isometry3d> targets;
        for (std::size_t k = 0; k < queries; ++k)
        {
            std::vector<double> q = middle;
            for (unsigned int i = 0; i < n; ++i)
                q[chain.variable(i)] = rng.uniformReal(chain.lower(i), chain.upper(i));
            targets.push_back(chain.toolPose(q.data(), base));
        }
        std::printf(
            "%s, tip %s: %u joints, %zu random reachable poses, full 6-D pose to %g, %g ms per query\n\n",
            urdf.c_str(), tip.c_str(), n, queries, TOLERANCE, 1000 * TIME_LIMIT);
        std::printf("| solver                           | solved     | mean time   |\n|---|---|---|\n");

        ompl_mm::IkSolver ours(chain, base);
        ours.tolerance = TOLERANCE;
        ours.timeLimit = TIME_LIMIT;
        if (options.iterations > 0)
            ours.iterations = static_cast<unsigned int>(options.iterations);
        if (options.stall)
            ours.stallIterations = static_cast<unsigned int>(*options.stall);
        if (options.damping)
            ours.damping = *options.damping;
        if (options.posture)
            ours.postureGain = *options.posture;
        ompl::RNG restarts(seed +
                           1000003);  // not the poses' sequence: a restart must not draw a target's joints
        print("ompl_mm IkSolver",
              measure(targets,
                      [&](const Eigen::Isometry3d &target)
                      {
                          std::vector<double> q = middle;
                          return ours.solve(target, ompl_mm::IkTask::Pose6D, q.data(), restarts);
                      }),
              queries);

        const KDL::Chain kdl = kdlChain(chain);
        KDL::JntArray lower(n), upper(n), seedValues(n), solution(n);
        for (unsigned int i = 0; i < n; ++i)
        {
            lower(i) = chain.lower(i);
            upper(i) = chain.upper(i);
            seedValues(i) = middle[chain.variable(i)];
        }
        KDL::ChainFkSolverPos_recursive fk(kdl);
        KDL::ChainIkSolverVel_pinv velocity(kdl);
        KDL::ChainIkSolverPos_NR_JL newton(kdl, lower, upper, fk, velocity, 100, TOLERANCE);
        print("KDL ChainIkSolverPos_NR_JL",
              measure(targets, [&](const Eigen::Isometry3d &target)
                      { return newton.CartToJnt(seedValues, kdlFrame(target), solution) >= 0; }),
              queries);
        KDL::ChainIkSolverPos_LMA lma(kdl, TOLERANCE);
        print(
            "KDL ChainIkSolverPos_LMA",
            measure(targets,
                    [&](const Eigen::Isometry3d &target)
                    {
                        if (lma.CartToJnt(seedValues, kdlFrame(target), solution) < 0)
                            return false;
                        for (unsigned int i = 0; i < n; ++i)
                            if (solution(i) < lower(i) || solution(i) > upper(i))
                                return false;  // LMA knows no limits: a solution outside them is no solution
                        return true;
                    }),
            queries);
        return 0;
    }
}  // namespace

int main(int argc, char **argv)
{
    return ompl_core::exitStatusOf<po::error>(
        "bench_ik",
        [&]
        {
            Options options;
            int exitCode = 0;
            return parseOptions(argc, argv, options, exitCode) ? run(options) : exitCode;
        });
}
