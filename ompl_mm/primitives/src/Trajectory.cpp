#include "ompl_mm/primitives/Trajectory.h"

namespace ompl_mm
{
    const char *primitiveKindName(PrimitiveKind kind)
    {
        switch (kind)
        {
            case PrimitiveKind::Transit:
                return "transit";
            case PrimitiveKind::Push:
                return "push";
            case PrimitiveKind::Pickup:
                return "pickup";
            case PrimitiveKind::Transfer:
                return "transfer";
        }
        return "unknown";
    }

    Trajectory::Trajectory(const ManipulationStateSpace *space) : space_(space) {}

    Trajectory::Trajectory(Trajectory &&other) noexcept
        : space_(other.space_),
          states_(std::move(other.states_)),
          labels_(std::move(other.labels_)),
          branchable_(std::move(other.branchable_))
    {
        other.states_.clear();
        other.labels_.clear();
        other.branchable_.clear();
    }

    Trajectory::~Trajectory()
    {
        truncate(0);
    }

    void Trajectory::reset(const ompl::base::State *state)
    {
        truncate(0);
        states_.push_back(space_->cloneState(state));
        branchable_.push_back(1);
    }

    void Trajectory::append(const ompl::base::State *state, SegmentLabel label, bool branchable)
    {
        states_.push_back(space_->cloneState(state));
        labels_.push_back(label);
        branchable_.push_back(branchable ? 1 : 0);
    }

    void Trajectory::truncate(std::size_t count)
    {
        if (count >= states_.size())
            return;
        while (states_.size() > count)
        {
            space_->freeState(states_.back());
            states_.pop_back();
        }
        labels_.resize(count > 0 ? count - 1 : 0);
        branchable_.resize(states_.size());
    }
}  // namespace ompl_mm
