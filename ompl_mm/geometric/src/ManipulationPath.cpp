#include "ompl_mm/geometric/ManipulationPath.h"

#include <cassert>

#include <ompl/base/SpaceInformation.h>

namespace ompl_mm
{
    ManipulationPath::ManipulationPath(const ompl::base::SpaceInformationPtr &si)
        : ompl::geometric::PathGeometric(si)
    {
    }

    void ManipulationPath::appendFirst(const ompl::base::State *state)
    {
        if (!states_.empty())
            throw ompl::Exception("ManipulationPath::appendFirst on a path that has states");
        append(state);
    }

    void ManipulationPath::appendLabelled(const ompl::base::State *state, SegmentLabel label)
    {
        if (states_.empty())
            throw ompl::Exception("ManipulationPath::appendLabelled on an empty path");
        append(state);
        labels_.push_back(label);
        assert(labels_.size() + 1 == states_.size());  // one label per segment
    }

    void ManipulationPath::shortcut(std::size_t first, std::size_t last)
    {
        if (last <= first + 1)
            return;
        for (std::size_t i = first + 1; i < last; ++i)
            si_->freeState(states_[i]);
        states_.erase(states_.begin() + first + 1, states_.begin() + last);
        labels_.erase(labels_.begin() + first + 1, labels_.begin() + last);
        assert(labels_.size() + 1 == states_.size());
    }

    void ManipulationPath::removeRepeatedStates()
    {
        for (std::size_t i = 1; i < states_.size();)
        {
            if (si_->getStateSpace()->equalStates(states_[i - 1], states_[i]))
            {
                si_->freeState(states_[i]);
                states_.erase(states_.begin() + i);
                labels_.erase(labels_.begin() + i - 1);
            }
            else
                ++i;
        }
    }

    double ManipulationPath::toolPathLength() const
    {
        const auto *space = si_->getStateSpace()->as<ManipulationStateSpace>();
        double length = 0.0;
        ompl::base::State *between = si_->allocState();
        for (std::size_t i = 0; i + 1 < states_.size(); ++i)
        {
            const unsigned int steps = std::max(1u, space->validSegmentCount(states_[i], states_[i + 1]));
            Eigen::Vector3d previous = space->toolPosition(states_[i]);
            for (unsigned int k = 1; k <= steps; ++k)
            {
                space->interpolate(states_[i], states_[i + 1], static_cast<double>(k) / steps, between);
                const Eigen::Vector3d tool = space->toolPosition(between);
                length += (tool - previous).norm();
                previous = tool;
            }
        }
        si_->freeState(between);
        return length;
    }

    std::map<std::string, unsigned int> ManipulationPath::primitiveCounts() const
    {
        std::map<std::string, unsigned int> counts{
            {"transit", 0}, {"push", 0}, {"pickup", 0}, {"transfer", 0}};
        for (std::size_t i = 0; i < labels_.size(); ++i)
            if (i == 0 || labels_[i] != labels_[i - 1])
                ++counts[primitiveKindName(labels_[i].kind)];
        return counts;
    }

    std::string ManipulationPath::checkLabels() const
    {
        const auto *space = si_->getStateSpace()->as<ManipulationStateSpace>();
        for (std::size_t i = 0; i < labels_.size(); ++i)
            for (unsigned int o = 0; o < space->objectCount(); ++o)
                if (space->objectMoves(states_[i], states_[i + 1], o) &&
                    labels_[i].object != static_cast<int>(o))
                    return "segment " + std::to_string(i) + " (" + primitiveKindName(labels_[i].kind) +
                           ") moves object '" + space->model()->scene().objects[o].name + "'";
        return {};
    }
}  // namespace ompl_mm
