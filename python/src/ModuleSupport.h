/* What the Python modules share: C++ input errors as ompl_core.InputError (with file and line), a
   stop for planning that watches Python's signals, so that Ctrl-C ends a plan cleanly, numpy arrays
   filled row by row, and the apps' files written from Python. */
#pragma once

#include "ompl_core/io/InputError.h"
#include "ompl_core/io/OutputFile.h"
#include "ompl_core/run/RunRecord.h"

#include <ompl/base/PlannerTerminationCondition.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <sstream>
#include <string>

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

    /** A count x columns array whose row i row(i, out) fills (out: its `columns` values). */
    template <typename Row>
    pybind11::array_t<double> rows(std::size_t count, std::size_t columns, Row row)
    {
        pybind11::array_t<double> array({count, columns});
        auto out = array.mutable_unchecked<2>();
        for (std::size_t i = 0; i < count; ++i)
            row(i, &out(i, 0));
        return array;
    }

    /** Writes file with write, all or nothing (ompl_core::OutputFile). @throws ompl_core::InputError
        when it cannot be written. */
    inline void writeFile(const std::string &file, const std::function<void(std::ostream &)> &write)
    {
        ompl_core::OutputFile out(file);
        write(out.stream());
        out.commit();
    }

    /** Binds Run, the planning run of one library (built from a Scene and a Request), as the class
        PlanningRun of module m, with what the runs of both libraries have: the constructor from
        (scene, planner, seed, time_limit, params: name -> value as text, named "params['name']" in
        errors), solve() without the GIL (Ctrl-C raises KeyboardInterrupt once the planner has
        stopped), solved and record_json() (the record as the app's --json writes it). Returns the
        class, for the library's own methods. */
    template <typename Run, typename Request, typename Scene>
    pybind11::class_<Run> bindPlanningRun(pybind11::module_ &m, const char *doc)
    {
        namespace py = pybind11;
        return py::class_<Run>(m, "PlanningRun", doc)
            .def(py::init(
                     [](const Scene &scene, const std::string &planner, std::uint32_t seed, double timeLimit,
                        const std::map<std::string, std::string> &params)
                     {
                         Request request;
                         request.planner = planner;
                         request.seed = seed;
                         request.timeLimit = timeLimit;
                         for (const auto &[name, value] : params)
                             request.parameters.push_back({name, value, {"params['" + name + "']", 0}});
                         return std::make_unique<Run>(scene, std::move(request));
                     }),
                 py::arg("scene"), py::arg("planner"), py::arg("seed"), py::arg("time_limit"),
                 py::arg("params"))
            .def(
                "solve",
                [](Run &run)
                {
                    PythonSignalStop stop;
                    {
                        const py::gil_scoped_release release;
                        run.solve(stop.condition());
                    }
                    stop.raiseIfInterrupted();
                },
                "Plans without the GIL until solved, the time limit or Ctrl-C (which raises "
                "KeyboardInterrupt once the planner has stopped).")
            .def_property_readonly("solved", &Run::solved)
            .def(
                "record_json",
                [](const Run &run)
                {
                    std::ostringstream out;
                    ompl_core::writeRunJson(out, run.record());
                    return out.str();
                },
                "The record as the app's --json writes it.");
    }
}  // namespace ompl_python
