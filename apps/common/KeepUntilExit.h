/* Planning objects the apps leave to the end of the process instead of destroying them. */
#pragma once

#include <memory>
#include <utility>
#include <vector>

namespace apps
{
    /** Takes object over for the rest of the process and returns it. It is never destroyed: freeing a
        search tree one state at a time took up to 150 ms after the results were written (PDST, 4 s on
        physics scene 2), time past the run's limit, while the end of the process frees it at once.
        The object stays reachable, so leak checkers do not report it; its destructor must not be
        needed for anything outside the process (files are written and closed by then). */
    template <typename T>
    T &keepUntilExit(std::unique_ptr<T> object)
    {
        static auto *kept = new std::vector<std::shared_ptr<void>>();  // never freed, on purpose
        T &reference = *object;
        kept->push_back(std::shared_ptr<void>(std::move(object)));
        return reference;
    }
}  // namespace apps
