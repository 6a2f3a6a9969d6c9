/* Where a planning run spends its wall time: loading the scene, setting up the problem, solving
   (the planner's time limit applies here) and the checks and outputs after it, reported in the
   apps' JSON ("phases_s") and with --verbose. */
#pragma once

#include "ompl_core/run/RunRecord.h"

#include <chrono>
#include <iomanip>
#include <ostream>

namespace ompl_core
{
    /** Wall-clock seconds of the phases of one run, each measured by lap() from the end of the
        one before (the first from construction). */
    class PhaseTimes
    {
    public:
        double load{0.0};    ///< reading the scene (and robot files the loader reads), seconds
        double setup{0.0};   ///< building the setup and planner, opening the outputs, setup(), seconds
        double solve{0.0};   ///< solve() with the time limit, smoothing included, seconds
        double checks{0.0};  ///< what follows solving: the path re-check, summary and output files, seconds

        /** Seconds since construction or the last lap(); starts the next lap. */
        double lap()
        {
            const Clock::time_point now = Clock::now();
            const double seconds = std::chrono::duration<double>(now - lapStart_).count();
            lapStart_ = now;
            return seconds;
        }
        /** Seconds since construction or the last lap(), without starting a new one. */
        double sinceLap() const { return std::chrono::duration<double>(Clock::now() - lapStart_).count(); }

        /** The phases as the JSON's "phases_s" record: load, setup, solve, checks. */
        RunRecord record() const
        {
            RunRecord phases;
            phases.addNumber("load", load)
                .addNumber("setup", setup)
                .addNumber("solve", solve)
                .addNumber("checks", checks);
            return phases;
        }

        /** One summary line: "  phases: load L s, setup S s, solve V s, checks C s". */
        void print(std::ostream &out) const
        {
            out << std::fixed << std::setprecision(3) << "  phases: load " << load << " s, setup " << setup
                << " s, solve " << solve << " s, checks " << checks << " s\n";
        }

    private:
        using Clock = std::chrono::steady_clock;
        Clock::time_point lapStart_{Clock::now()};
    };
}  // namespace ompl_core
