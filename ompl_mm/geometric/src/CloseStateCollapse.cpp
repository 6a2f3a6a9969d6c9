#include "ompl_mm/geometric/CloseStateCollapse.h"

#include <limits>
#include <vector>

namespace ompl_mm
{
    bool collapseCloseStates(ompl::geometric::PathGeometric &path,
                             const ompl::base::PlannerTerminationCondition &ptc)
    {
        std::vector<ompl::base::State *> &states = path.getStates();
        const std::size_t count = states.size();
        if (count < 3)
            return false;
        const ompl::base::SpaceInformationPtr &si = path.getSpaceInformation();
        // distances by the states' first places in the path; kept lists those still in it
        std::vector<double> distance(count * count, 0.0);
        for (std::size_t i = 0; i < count; ++i)
        {
            if (ptc)
                return false;
            for (std::size_t j = i + 2; j < count; ++j)
                distance[i * count + j] = si->distance(states[i], states[j]);
        }
        std::vector<std::size_t> kept(count);
        for (std::size_t i = 0; i < count; ++i)
            kept[i] = i;
        bool changed = false;
        // OMPL's bounds: as many steps as the path had states, and as many without a change
        std::size_t unchanged = 0;
        for (std::size_t step = 0; step < count && unchanged < count && !ptc; ++step, ++unchanged)
        {
            double least = std::numeric_limits<double>::infinity();
            std::size_t p1 = 0, p2 = 0;
            for (std::size_t i = 0; i < kept.size(); ++i)
                for (std::size_t j = i + 2; j < kept.size(); ++j)
                    if (distance[kept[i] * count + kept[j]] < least)
                    {
                        least = distance[kept[i] * count + kept[j]];
                        p1 = i;
                        p2 = j;
                    }
            if (p2 == 0)
                break;  // every pair failed
            if (si->checkMotion(states[p1], states[p2]))
            {
                for (std::size_t k = p1 + 1; k < p2; ++k)
                    si->freeState(states[k]);
                states.erase(states.begin() + static_cast<std::ptrdiff_t>(p1) + 1,
                             states.begin() + static_cast<std::ptrdiff_t>(p2));
                kept.erase(kept.begin() + static_cast<std::ptrdiff_t>(p1) + 1,
                           kept.begin() + static_cast<std::ptrdiff_t>(p2));
                changed = true;
                unchanged = 0;
            }
            else
                distance[kept[p1] * count + kept[p2]] = std::numeric_limits<double>::infinity();
        }
        return changed;
    }
}  // namespace ompl_mm
