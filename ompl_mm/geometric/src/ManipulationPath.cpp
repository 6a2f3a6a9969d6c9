#include "ompl_mm/geometric/ManipulationPath.h"

#include "ompl_mm/geometric/ManipulationMotionValidator.h"

#include <algorithm>
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
        rememberLabelledStates();
    }

    void ManipulationPath::appendLabelled(const ompl::base::State *state, SegmentLabel label)
    {
        if (states_.empty())
            throw ompl::Exception("ManipulationPath::appendLabelled on an empty path");
        labels();  // relabels changed states before the new segment joins them
        append(state);
        labels_.push_back(label);
        assert(labels_.size() + 1 == states_.size());  // one label per segment
        rememberLabelledStates();
    }

    const std::vector<SegmentLabel> &ManipulationPath::labels() const
    {
        if (labelsFitStates())
            return labels_;
        const auto *validator =
            dynamic_cast<const ManipulationMotionValidator *>(si_->getMotionValidator().get());
        if (!validator)
            throw ompl::Exception(
                "ManipulationPath: its states changed since they were labelled and the space "
                "information has no ManipulationMotionValidator to relabel them");
        std::vector<SegmentLabel> relabelled;
        for (std::size_t i = 0; i + 1 < states_.size(); ++i)
        {
            const std::optional<SegmentLabel> label = validator->explain(states_[i], states_[i + 1]);
            if (!label)
                throw ompl::Exception("ManipulationPath: segment " + std::to_string(i) +
                                      " of the changed path is no motion of any primitive");
            relabelled.push_back(*label);
        }
        labels_ = std::move(relabelled);
        rememberLabelledStates();
        return labels_;
    }

    bool ManipulationPath::labelsFitStates() const
    {
        if (states_.empty())
            return labels_.empty();
        const ompl::base::StateSpace &space = *si_->getStateSpace();
        space.copyToReals(values_, states_[0]);
        const std::size_t dimension = values_.size();
        if (labels_.size() + 1 != states_.size() || labelledValues_.size() != dimension * states_.size())
            return false;
        for (std::size_t i = 0; i < states_.size(); ++i)
        {
            space.copyToReals(values_, states_[i]);
            if (!std::equal(values_.begin(), values_.end(), labelledValues_.begin() + i * dimension))
                return false;
        }
        return true;
    }

    void ManipulationPath::rememberLabelledStates() const
    {
        labelledValues_.clear();
        for (const ompl::base::State *state : states_)
        {
            si_->getStateSpace()->copyToReals(values_, state);
            labelledValues_.insert(labelledValues_.end(), values_.begin(), values_.end());
        }
    }

    void ManipulationPath::replace(std::size_t first, std::size_t last, const Trajectory &trajectory)
    {
        if (last <= first || last >= states_.size() || trajectory.size() < 2 ||
            !si_->getStateSpace()->equalStates(trajectory.state(0), states_[first]))
            throw ompl::Exception(
                "ManipulationPath::replace: the trajectory must start at state 'first' and "
                "first < last < getStateCount()");
        labels();
        for (std::size_t i = first + 1; i <= last; ++i)
            si_->freeState(states_[i]);
        states_.erase(states_.begin() + first + 1, states_.begin() + last + 1);
        labels_.erase(labels_.begin() + first, labels_.begin() + last);
        for (std::size_t k = 1; k < trajectory.size(); ++k)
        {
            states_.insert(states_.begin() + first + k, si_->cloneState(trajectory.state(k)));
            labels_.insert(labels_.begin() + first + k - 1, trajectory.label(k - 1));
        }
        assert(labels_.size() + 1 == states_.size());
        rememberLabelledStates();
    }

    void ManipulationPath::removeRepeatedStates()
    {
        labels();
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
        rememberLabelledStates();
    }

    double ManipulationPath::toolPathLength() const
    {
        return states_.empty() ? 0.0 : toolPathLength(0, states_.size() - 1);
    }

    double ManipulationPath::toolPathLength(std::size_t first, std::size_t last) const
    {
        const auto *space = si_->getStateSpace()->as<ManipulationStateSpace>();
        double length = 0.0;
        for (std::size_t i = first; i < last; ++i)
            length += space->toolTravel(states_[i], states_[i + 1]);
        return length;
    }

    std::map<std::string, unsigned int> ManipulationPath::primitiveCounts() const
    {
        std::map<std::string, unsigned int> counts{
            {"transit", 0}, {"push", 0}, {"pickup", 0}, {"transfer", 0}};
        const std::vector<SegmentLabel> &segments = labels();
        for (std::size_t i = 0; i < segments.size(); ++i)
            if (i == 0 || segments[i] != segments[i - 1])
                ++counts[primitiveKindName(segments[i].kind)];
        return counts;
    }

    std::vector<ManipulationPath::PushReversal> ManipulationPath::pushReversals() const
    {
        const std::vector<SegmentLabel> &segments = labels();
        const auto *space = si_->getStateSpace()->as<ManipulationStateSpace>();
        std::vector<PushReversal> reversals;
        for (unsigned int object = 0; object < space->objectCount(); ++object)
        {
            // the object's last push segment and its direction, while nothing else has moved it
            // since (none: past the end)
            const std::size_t none = segments.size();
            std::size_t previous = none;
            Eigen::Vector3d previousDirection = Eigen::Vector3d::Zero();
            for (std::size_t i = 0; i < segments.size(); ++i)
            {
                if (segments[i].kind != PrimitiveKind::Push || segments[i].object != static_cast<int>(object))
                {
                    if (space->objectMoves(states_[i], states_[i + 1], object))
                        previous = none;
                    continue;
                }
                const Eigen::Vector3d moved =
                    space->objectPosition(states_[i + 1], object) - space->objectPosition(states_[i], object);
                if (moved.norm() == 0.0)
                    continue;
                if (previous != none && moved.dot(previousDirection) < -REVERSAL_TOLERANCE)
                    reversals.push_back({object, previous, i});
                previous = i;
                previousDirection = moved.normalized();
            }
        }
        std::sort(reversals.begin(), reversals.end(),
                  [](const PushReversal &a, const PushReversal &b) { return a.earlier < b.earlier; });
        return reversals;
    }

    std::string ManipulationPath::checkLabels() const
    {
        try
        {
            labels();
        }
        catch (const ompl::Exception &e)
        {
            return e.what();
        }
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
