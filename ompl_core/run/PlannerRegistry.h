#pragma once

#include "ompl_core/io/InputError.h"
#include "ompl_core/io/TextFormat.h"

#include <ompl/base/Planner.h>

#include <algorithm>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace ompl_core
{
    /** Planners by name: each library registers the planners that can plan on its setups, and the
        apps, the benchmark tool and user code pick one by name. A user's own planner joins with one
        add() call. Not synchronised: add planners before other threads use the registry.
        @tparam Setup the setup type the factories build planners for (ompl_phys::PhysicsSetup, for
        instance). */
    template <typename Setup>
    class PlannerRegistry
    {
    public:
        /** Makes a new planner for a setup; may also configure the setup (an optimisation
            objective, for instance). */
        using Factory = std::function<ompl::base::PlannerPtr(Setup &)>;

        /** Registers a planner; description is one line for help texts. The registry keeps a copy
            of factory.
            @throws ompl::Exception when name is empty or already registered. */
        void add(const std::string &name, const std::string &description, Factory factory)
        {
            if (name.empty() || has(name))
                throw ompl::Exception("PlannerRegistry", "planner name '" + name + "' is empty or taken");
            entries_.push_back({name, description, std::move(factory)});
        }

        /** Whether a planner of that name is registered (names are case-sensitive). */
        bool has(const std::string &name) const { return find(name) != entries_.end(); }

        /** Checks a planner name before anything is built for it.
            @throws InputError at where (no place by default) for an unknown name, listing the known ones. */
        void require(const std::string &name, const SourceLocation &where = {}) const
        {
            if (!has(name))
                throw InputError(where, "unknown planner '" + name + "' (known: " + nameList() + ")");
        }

        /** Names in registration order. */
        std::vector<std::string> names() const
        {
            std::vector<std::string> all;
            for (const Entry &entry : entries_)
                all.push_back(entry.name);
            return all;
        }

        /** "name, name, …" in registration order. */
        std::string nameList() const { return joinedNames(names(), ""); }

        /** The one-line description given to add(). @throws InputError for an unknown name. */
        const std::string &description(const std::string &name) const { return entry(name).description; }

        /** A new planner of that name for setup. @throws InputError for an unknown name. */
        ompl::base::PlannerPtr make(const std::string &name, Setup &setup) const
        {
            return entry(name).factory(setup);
        }

    private:
        struct Entry
        {
            std::string name;
            std::string description;
            Factory factory;
        };

        typename std::vector<Entry>::const_iterator find(const std::string &name) const
        {
            return std::find_if(entries_.begin(), entries_.end(),
                                [&name](const Entry &entry) { return entry.name == name; });
        }

        const Entry &entry(const std::string &name) const
        {
            require(name);
            return *find(name);
        }

        std::vector<Entry> entries_;
    };
}  // namespace ompl_core
