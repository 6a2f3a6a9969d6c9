/* What the Python modules share: C++ input errors as ompl_core.InputError (with file and line), and
   a stop for planning that watches Python's signals, so that Ctrl-C ends a plan cleanly. */
#pragma once

#include "ompl_core/io/InputError.h"

#include <ompl/base/PlannerTerminationCondition.h>

#include <pybind11/pybind11.h>

#include <chrono>

namespace ompl_python
{
    /** Raises ompl_core.InputError (message, file, line) for every ompl_core::InputError thrown
        through the module's functions. */
    inline void translateInputErrors()
    {
        pybind11::register_exception_translator(
            [](std::exception_ptr thrown)
            {
                try
                {
                    if (thrown)
                        std::rethrow_exception(thrown);
                }
                catch (const ompl_core::InputError &error)
                {
                    const pybind11::object type = pybind11::module_::import("ompl_core").attr("InputError");
                    const pybind11::object file = error.where().file.empty()
                                                      ? pybind11::object(pybind11::none())
                                                      : pybind11::object(pybind11::str(error.where().file));
                    const pybind11::object instance = type(error.what(), file, error.where().line);
                    PyErr_SetObject(type.ptr(), instance.ptr());
                }
            });
    }

    /** A stop for a plan made without the GIL: every 50 ms it takes the GIL and lets Python handle
        its signals; a handler that raises (Ctrl-C's KeyboardInterrupt) stops the plan, and
        raiseIfInterrupted() raises that exception once the plan has returned. */
    class PythonSignalStop
    {
    public:
        /** The stop to give the plan. @pre outlives it. */
        ompl::base::PlannerTerminationCondition condition()
        {
            return ompl::base::PlannerTerminationCondition([this] { return poll(); });
        }

        /** Raises the exception a signal handler raised during the plan, if any. @pre holds the GIL. */
        void raiseIfInterrupted() const
        {
            if (interrupted_)
                throw pybind11::error_already_set();
        }

    private:
        bool poll()
        {
            const auto now = std::chrono::steady_clock::now();
            if (interrupted_ || now - lastPoll_ < std::chrono::milliseconds(50))
                return interrupted_;
            lastPoll_ = now;
            const pybind11::gil_scoped_acquire gil;
            interrupted_ = PyErr_CheckSignals() != 0;  // the exception stays set for raiseIfInterrupted()
            return interrupted_;
        }

        bool interrupted_{false};
        std::chrono::steady_clock::time_point lastPoll_{std::chrono::steady_clock::now()};
    };
}  // namespace ompl_python
