// A user's own benchmark program: a planner written here, outside the libraries, joins the physics
// planner registry, and the benchmark tool's main runs it from a cfg file like any shipped planner
// (test_ompl_mm_benchmark.py runs this program).
#include "ompl_bench/app/BenchmarkApp.h"
#include "ompl_phys/control/PhysicsSetup.h"

#include <ompl/base/Planner.h>
#include <ompl/control/PathControl.h>
#include <ompl/control/SpaceInformation.h>
#include <ompl/util/RandomNumbers.h>

#include <memory>
#include <vector>

namespace
{
    /** A random tree: grow from a random node with a random control until a state satisfies the
        goal. Declares one parameter, max_steps (the longest control, in propagation steps). */
    class RandomTree : public ompl::base::Planner
    {
    public:
        explicit RandomTree(const ompl::control::SpaceInformationPtr &si)
            : ompl::base::Planner(si, "RandomTree"), siC_(si.get())
        {
            params().declareParam<unsigned int>(
                "max_steps", [this](unsigned int steps) { maxSteps_ = steps; }, [this] { return maxSteps_; });
            params()["max_steps"].setRangeSuggestion("1:1:100");
        }

        ~RandomTree() override { clear(); }

        ompl::base::PlannerStatus solve(const ompl::base::PlannerTerminationCondition &ptc) override
        {
            checkValidity();
            while (const ompl::base::State *start = pis_.nextStart())
                nodes_.push_back({si_->cloneState(start), nullptr, 0, -1});
            if (nodes_.empty())
                return ompl::base::PlannerStatus::INVALID_START;
            ompl::control::ControlSamplerPtr sampler = siC_->allocControlSampler();
            ompl::control::Control *control = siC_->allocControl();
            ompl::base::State *end = si_->allocState();
            const ompl::base::Goal &goal = *pdef_->getGoal();
            while (!ptc)
            {
                const int from = rng_.uniformInt(0, static_cast<int>(nodes_.size()) - 1);
                sampler->sample(control);
                const int steps = rng_.uniformInt(1, static_cast<int>(maxSteps_));
                const unsigned int done = siC_->propagateWhileValid(nodes_[from].state, control, steps, end);
                if (done == 0)
                    continue;
                nodes_.push_back({si_->cloneState(end), siC_->cloneControl(control), done, from});
                if (goal.isSatisfied(end))
                {
                    addSolution(static_cast<int>(nodes_.size()) - 1);
                    break;
                }
            }
            si_->freeState(end);
            siC_->freeControl(control);
            return pdef_->hasExactSolution() ? ompl::base::PlannerStatus::EXACT_SOLUTION
                                             : ompl::base::PlannerStatus::TIMEOUT;
        }

        void clear() override
        {
            Planner::clear();
            for (Node &node : nodes_)
            {
                si_->freeState(node.state);
                if (node.control)
                    siC_->freeControl(node.control);
            }
            nodes_.clear();
        }

    private:
        struct Node
        {
            ompl::base::State *state;
            ompl::control::Control *control;  ///< applied from the parent
            unsigned int steps;
            int parent;
        };

        void addSolution(int last)
        {
            std::vector<int> chain;
            for (int n = last; n >= 0; n = nodes_[n].parent)
                chain.insert(chain.begin(), n);
            auto path = std::make_shared<ompl::control::PathControl>(si_);
            path->append(nodes_[chain.front()].state);
            for (std::size_t k = 1; k < chain.size(); ++k)
            {
                const Node &node = nodes_[chain[k]];
                path->append(node.state, node.control, node.steps * siC_->getPropagationStepSize());
            }
            pdef_->addSolutionPath(path, false, 0.0, getName());
        }

        const ompl::control::SpaceInformation *siC_;
        ompl::RNG rng_;
        std::vector<Node> nodes_;
        unsigned int maxSteps_{10};
    };
}  // namespace

int main(int argc, char **argv)
{
    ompl_phys::PhysicsSetup::plannerRegistry().add(
        "random_tree", "a random tree written by a user",
        [](ompl_phys::PhysicsSetup &setup)
        { return std::make_shared<RandomTree>(setup.getSpaceInformation()); });
    return ompl_bench::benchmarkMain(argc, argv);
}
