#include "ompl_core/bench/BenchmarkRunner.h"

#include "ompl_core/io/InputFile.h"
#include "ompl_core/io/OutputFile.h"
#include "ompl_core/run/Fnv1aHash.h"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <map>
#include <sstream>

namespace ompl_core
{
    namespace
    {
        /** How often Benchmark samples a planner's progress properties, seconds (OMPL's default). */
        constexpr double PROGRESS_INTERVAL = 0.05;

        std::string shardSuffix(const Shard &shard)
        {
            if (shard.count == 1)
                return "";
            return ".shard-" + std::to_string(shard.index) + "-of-" + std::to_string(shard.count);
        }

        /** "<output>/<cfg name>[.<problem>]<shard>" without an extension. */
        std::string outputStem(const BenchmarkConfig &config, const BenchmarkProblem &problem,
                               const Shard &shard)
        {
            std::string stem = std::filesystem::path(config.file).stem().string();
            if (config.problems.size() > 1)
                stem += "." + problem.name;
            return (std::filesystem::path(config.output) / (stem + shardSuffix(shard))).string();
        }

        void writeFile(const std::string &path, const std::string &text)
        {
            OutputFile file(path);
            file.stream() << text;
            file.commit();
        }

        /** The experiment's parameters (columns of the database's experiments table): the config,
            the scene file and a hash of its bytes (FNV-1a, 64 bits, hexadecimal), and the shard. */
        void describeExperiment(BenchmarkLog &log, const BenchmarkConfig &config,
                                const BenchmarkProblem &problem, const Shard &shard)
        {
            std::ostringstream hash;
            hash << std::hex << std::setw(16) << std::setfill('0')
                 << fnv1a64(readInputFile(problem.scene, "scene file"));
            log.addExperimentParameter("config", "TEXT", config.file);
            log.addExperimentParameter("scene", "TEXT", problem.scene);
            log.addExperimentParameter("scene_hash", "TEXT", hash.str());
            log.addExperimentParameter("shard", "TEXT",
                                       std::to_string(shard.index) + "/" + std::to_string(shard.count));
        }

        /** Prints a line per finished run: which, how it went, and how the whole benchmark stands. */
        class ProgressReport
        {
        public:
            ProgressReport(std::ostream *out, std::size_t total) : out_(out), total_(total) {}

            void finished(const std::string &problem, const std::string &planner, unsigned int index,
                          unsigned int runCount, const SceneRun &run)
            {
                ++done_;
                solved_ += run.solved ? 1 : 0;
                if (!out_)
                    return;
                const double elapsed =
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
                const double left =
                    elapsed / static_cast<double>(done_) * static_cast<double>(total_ - done_);
                *out_ << std::fixed << std::setprecision(1) << "[" << done_ << "/" << total_ << "] "
                      << problem << " " << planner << " run " << index + 1 << " of " << runCount << ": "
                      << (run.solved ? "solved" : "not solved") << "; " << solved_ << " solved so far, "
                      << elapsed << " s elapsed, about " << left << " s left" << std::endl;
            }

            /** The runs finished so far. */
            std::size_t done() const { return done_; }

        private:
            std::ostream *out_;
            std::size_t total_;
            std::size_t done_{0};
            std::size_t solved_{0};
            std::chrono::steady_clock::time_point start_{std::chrono::steady_clock::now()};
        };
    }  // namespace

    std::string benchmarkLogPath(const BenchmarkConfig &config, const BenchmarkProblem &problem,
                                 const Shard &shard)
    {
        return outputStem(config, problem, shard) + ".log";
    }

    std::vector<std::string> runBenchmark(const BenchmarkConfig &config, const Shard &shard,
                                          const BenchmarkSceneLoader &load, std::ostream *progress,
                                          const BenchmarkStop &stop)
    {
        std::vector<std::unique_ptr<BenchmarkScene>> scenes;
        for (const BenchmarkProblem &problem : config.problems)
        {
            scenes.push_back(load(problem));
            scenes.back()->checkPlanners(config.planners, problem);
        }
        std::filesystem::create_directories(config.output);

        const std::vector<ScheduledRun> runs = scheduleRuns(config, shard);
        ProgressReport report(progress, runs.size());
        std::vector<std::string> written;
        for (std::size_t p = 0; p < config.problems.size(); ++p)
        {
            const BenchmarkProblem &problem = config.problems[p];
            BenchmarkScene &scene = *scenes[p];
            const double timeLimit = problem.timeLimit.value_or(config.timeLimit.value_or(scene.timeLimit()));
            const ompl::tools::Benchmark::Request request(timeLimit, config.memoryLimit, 1, PROGRESS_INTERVAL,
                                                          false, false, config.simplify);
            std::unique_ptr<BenchmarkLog> log = scene.makeLog(problem.name);
            log->describe(timeLimit, config.memoryLimit, config.runCount, config.seed);
            describeExperiment(*log, config, problem, shard);
            std::map<std::size_t, SceneRun> shortest;  // per planner
            for (const ScheduledRun &scheduled : runs)
            {
                if (scheduled.problem != p)
                    continue;
                if (stop && stop())
                    throw BenchmarkInterrupted("benchmark stopped after " + std::to_string(report.done()) +
                                               " of " + std::to_string(runs.size()) + " runs");
                const BenchmarkPlanner &planner = config.planners[scheduled.planner];
                SceneRun run = scene.run(planner, problem, scheduled.seed, request,
                                         config.savedPaths != SavedPaths::None);
                log->addRuns(run.experiment);
                report.finished(problem.name, planner.label, scheduled.index, config.runCount, run);
                if (!run.solved)
                    continue;
                if (config.savedPaths == SavedPaths::All)
                {
                    written.push_back(outputStem(config, problem, shard) + "." + planner.label + ".run" +
                                      std::to_string(scheduled.index + 1) + ".path");
                    writeFile(written.back(), run.pathText);
                }
                auto best = shortest.find(scheduled.planner);
                if (best == shortest.end() || run.pathLength < best->second.pathLength)
                    shortest[scheduled.planner] = std::move(run);
            }
            if (config.savedPaths == SavedPaths::Shortest)
                for (const auto &[planner, run] : shortest)
                {
                    written.push_back(outputStem(config, problem, shard) + "." +
                                      config.planners[planner].label + ".shortest.path");
                    writeFile(written.back(), run.pathText);
                }
            if (log->getRecordedExperimentData().planners.empty())
                continue;  // this shard holds no run of the problem
            OutputFile file(benchmarkLogPath(config, problem, shard));
            log->saveResultsToStream(file.stream());
            file.commit();
            written.push_back(benchmarkLogPath(config, problem, shard));
        }
        return written;
    }
}  // namespace ompl_core
