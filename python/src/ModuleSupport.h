/* What the Python modules share: C++ input errors as ompl_core.InputError (with file and line), a
   stop for planning that watches Python's signals, so that Ctrl-C ends a plan cleanly, numpy arrays
   filled row by row, and the apps' files written from Python. */
#pragma once

#include "ompl_core/io/InputError.h"
#include "ompl_core/io/OutputFile.h"
#include "ompl_core/run/GlobalSeed.h"
#include "ompl_core/run/ParameterSetting.h"
#include "ompl_core/run/RunRecord.h"

#include <ompl/base/Planner.h>
#include <ompl/base/PlannerStatus.h>
#include <ompl/base/PlannerTerminationCondition.h>
#include <ompl/util/Console.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace ompl_python
{
    /** Raises ompl_core.InputError (message, file, line) for every ompl_core::InputError thrown
        through the module's functions, and OSError for an ompl_core::OutputError (a file that
        could not be written). */
    inline void translateErrors()
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
                catch (const ompl_core::OutputError &error)
                {
                    PyErr_SetString(PyExc_OSError, error.what());
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
            return ompl::base::PlannerTerminationCondition([this] { return requested(); });
        }

        /** Raises the exception a signal handler raised during the plan, if any. @pre holds the GIL. */
        void raiseIfInterrupted() const
        {
            if (interrupted_)
                throw pybind11::error_already_set();
        }

        /** True once a signal handler raised; asks Python at most every 50 ms. @pre runs without
            the GIL. */
        bool requested()
        {
            const auto now = std::chrono::steady_clock::now();
            if (interrupted_ || now - lastPoll_ < std::chrono::milliseconds(50))
                return interrupted_;
            lastPoll_ = now;
            const pybind11::gil_scoped_acquire gil;
            interrupted_ = PyErr_CheckSignals() != 0;  // the exception stays set for raiseIfInterrupted()
            return interrupted_;
        }

    private:
        bool interrupted_{false};
        std::chrono::steady_clock::time_point lastPoll_{std::chrono::steady_clock::now()};
    };

    /** Runs plan(condition) without the GIL, condition ending it when Python has a signal to
        handle; raises that signal's exception (Ctrl-C's KeyboardInterrupt) once plan has returned.
        @pre holds the GIL. */
    template <typename Plan>
    void planWithoutGil(Plan plan)
    {
        PythonSignalStop stop;
        {
            const pybind11::gil_scoped_release release;
            plan(stop.condition());
        }
        stop.raiseIfInterrupted();
    }

    /** A planner parameter's value as ompl_core::ParameterSetting takes it: "true" or "false" for a
        bool, else str(value). */
    inline std::string parameterText(const pybind11::handle &value)
    {
        if (pybind11::isinstance<pybind11::bool_>(value))
            return value.cast<bool>() ? "true" : "false";
        return pybind11::str(value).cast<std::string>();
    }

    /** The planner of a setup, with the way that setup's library checks and sets parameters. */
    struct PlannerHandle
    {
        /** How the library sets parameters (ompl_core::applyParameters, plus its own rules). */
        using ApplyParameters = void (*)(ompl::base::Planner &,
                                         const std::vector<ompl_core::ParameterSetting> &);

        ompl::base::PlannerPtr planner;  ///< the setup's planner, shared with it
        ApplyParameters apply;           ///< checks and sets parameters on planner
    };

    /** Binds PlannerHandle as class Planner of m (module-local, so both modules can have one):
        getName, params (name -> value), getParam, setParam (checked as on the command line:
        ompl_core.InputError naming "setParam('name')" with the parameter's range or the planner's
        parameters), paramRanges, and repr. */
    inline void bindPlanner(pybind11::module_ &m)
    {
        namespace py = pybind11;
        py::class_<PlannerHandle>(
            m, "Planner", py::module_local(),
            "A setup's planner: its name and its declared parameters (OMPL's ParamSet).")
            .def("getName", [](const PlannerHandle &handle) { return handle.planner->getName(); })
            .def(
                "params",
                [](const PlannerHandle &handle)
                {
                    std::map<std::string, std::string> values;
                    handle.planner->params().getParams(values);
                    return values;
                },
                "Every declared parameter's current value, as text, by name.")
            .def(
                "getParam",
                [](const PlannerHandle &handle, const std::string &name)
                {
                    std::string value;
                    if (!handle.planner->params().getParam(name, value))
                        throw py::key_error("planner " + handle.planner->getName() + " has no parameter '" +
                                            name + "'");
                    return value;
                },
                py::arg("name"), "The parameter's current value, as text; KeyError for an unknown name.")
            .def(
                "setParam",
                [](const PlannerHandle &handle, const std::string &name, const py::object &value) {
                    handle.apply(*handle.planner,
                                 {{name, parameterText(value), {"setParam('" + name + "')", 0}}});
                },
                py::arg("name"), py::arg("value"),
                "Sets a parameter (value: a number, bool or text), checked as on the command line: "
                "ompl_core.InputError for an unknown name or a value outside its range.")
            .def(
                "paramRanges",
                [](const PlannerHandle &handle)
                {
                    std::map<std::string, std::string> ranges;
                    for (const auto &[name, parameter] : handle.planner->params().getParams())
                        ranges[name] = parameter->getRangeSuggestion();
                    return ranges;
                },
                "Each parameter's range suggestion ('LOW:STEP:HIGH', 'LOW:HIGH', 'A,B,C' or '').")
            .def("__repr__",
                 [](const PlannerHandle &handle) { return "<Planner '" + handle.planner->getName() + "'>"; });
    }

    /** Binds ompl::base::PlannerStatus as class PlannerStatus of m (module-local): true when solved
        (exactly or approximately, as in C++), str() as OMPL names it, `exact`. */
    inline void bindPlannerStatus(pybind11::module_ &m)
    {
        namespace py = pybind11;
        py::class_<ompl::base::PlannerStatus>(m, "PlannerStatus", py::module_local(),
                                              "What solve() returned.")
            .def("__bool__",
                 [](const ompl::base::PlannerStatus &status) { return static_cast<bool>(status); })
            .def("__str__", &ompl::base::PlannerStatus::asString)
            .def("__repr__", [](const ompl::base::PlannerStatus &status)
                 { return "<PlannerStatus '" + status.asString() + "'>"; })
            .def_property_readonly("exact", [](const ompl::base::PlannerStatus &status)
                                   { return status == ompl::base::PlannerStatus::EXACT_SOLUTION; });
    }

    /** Binds what OMPL keeps for the whole process, as functions of m: set_seed(seed) and
        set_log_level(name); OMPL's messages start at warning level, as in the apps. */
    inline void bindOmplGlobals(pybind11::module_ &m)
    {
        namespace py = pybind11;
        m.def("set_seed", &ompl_core::reseedOmpl, py::arg("seed"),
              "Seeds OMPL's random numbers (ompl::RNG::setSeed, for all modules): call it before making a "
              "setup and before its solve() to plan reproducibly.");
        static const std::map<std::string, ompl::msg::LogLevel> levels{{"debug", ompl::msg::LOG_DEBUG},
                                                                       {"info", ompl::msg::LOG_INFO},
                                                                       {"warn", ompl::msg::LOG_WARN},
                                                                       {"error", ompl::msg::LOG_ERROR},
                                                                       {"none", ompl::msg::LOG_NONE}};
        m.def(
            "set_log_level",
            [](const std::string &name)
            {
                const auto level = levels.find(name);
                if (level == levels.end())
                    throw py::value_error("log level must be debug, info, warn, error or none, got '" + name +
                                          "'");
                ompl::msg::setLogLevel(level->second);
            },
            py::arg("name"),
            "Which of OMPL's messages are printed (for all modules): 'debug', 'info', 'warn' (the "
            "default, as in the apps), 'error' or 'none'.");
        if (ompl::msg::getLogLevel() < ompl::msg::LOG_WARN)
            ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    }

    /** Binds what the setups of both libraries share as methods of cls, OMPL's names: setPlannerByName,
        getPlanner, solve (without the GIL; Ctrl-C stops it and raises KeyboardInterrupt),
        goal_fault, haveSolutionPath, haveExactSolutionPath, getLastPlanComputationTime, clear, setup, and the
        static planners() (registered name -> description). */
    template <typename Setup, typename... Options>
    void bindSetupMethods(pybind11::class_<Setup, Options...> &cls, PlannerHandle::ApplyParameters apply)
    {
        namespace py = pybind11;
        cls.def("setPlannerByName", &Setup::setPlannerByName, py::arg("name"),
                "Makes the registered planner `name` this setup's planner (ompl_core.InputError for an "
                "unknown name).")
            .def(
                "getPlanner",
                [apply](const Setup &setup)
                {
                    if (!setup.getPlanner())
                        throw ompl::Exception("getPlanner", "the setup has no planner");
                    return PlannerHandle{setup.getPlanner(), apply};
                },
                "The current planner, to read and set its parameters.")
            .def(
                "solve",
                [](Setup &setup, double seconds)
                {
                    if (!(seconds > 0.0))
                        throw py::value_error("solve needs a positive time, got " + std::to_string(seconds));
                    ompl::base::PlannerStatus status;
                    planWithoutGil(
                        [&](const ompl::base::PlannerTerminationCondition &stop)
                        {
                            status = setup.solve(ompl::base::plannerOrTerminationCondition(
                                ompl::base::timedPlannerTerminationCondition(seconds), stop));
                        });
                    return status;
                },
                py::arg("time") = 1.0,
                "Plans for at most `time` seconds without the GIL; Ctrl-C stops the planner and raises "
                "KeyboardInterrupt. Returns the PlannerStatus.")
            .def_property_readonly(
                "goal_fault",
                [](const Setup &setup) {
                    return setup.goalFault() ? std::optional<std::string>(setup.goalFault()->what())
                                             : std::nullopt;
                },
                "Why the scene's goal cannot be reached (solve() then returns at once), or None.")
            .def("haveSolutionPath", &Setup::haveSolutionPath)
            .def("haveExactSolutionPath", &Setup::haveExactSolutionPath)
            .def("getLastPlanComputationTime", &Setup::getLastPlanComputationTime)
            .def("clear", &Setup::clear,
                 "Forgets the solutions and the planner's data (keeps its parameters).")
            .def("setup", &Setup::setup, "Sets up the planner (solve() does it when needed).")
            .def_static(
                "planners",
                []
                {
                    std::map<std::string, std::string> planners;
                    for (const std::string &name : Setup::plannerRegistry().names())
                        planners[name] = Setup::plannerRegistry().description(name);
                    return planners;
                },
                "The registered planners: name -> description.");
    }

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

    /** The states state(0) … state(count - 1) of space, one row each: their values as
        StateSpace::copyToReals gives them. */
    template <typename StateAt>
    pybind11::array_t<double> stateRows(const ompl::base::StateSpace &space, std::size_t count, StateAt state)
    {
        const std::size_t columns = space.getValueLocations().size();
        std::vector<double> reals;
        return rows(count, columns,
                    [&](std::size_t i, double *out)
                    {
                        space.copyToReals(reals, state(i));
                        std::copy(reals.begin(), reals.end(), out);
                    });
    }

    /** Writes file with write, all or nothing (ompl_core::OutputFile). @throws ompl_core::InputError
        when it cannot be written. */
    inline void writeFile(const std::string &file, const std::function<void(std::ostream &)> &write)
    {
        ompl_core::OutputFile out(file);
        write(out.stream());
        out.commit();
    }

    /** The Request of a planning run from Python's arguments: planner, seed, time limit and the
        parameters (name -> value, named "params['name']" in errors). */
    template <typename Request>
    Request requestOf(const std::string &planner, std::uint32_t seed, double timeLimit,
                      const std::map<std::string, pybind11::object> &params)
    {
        Request request;
        request.planner = planner;
        request.seed = seed;
        request.timeLimit = timeLimit;
        for (const auto &[name, value] : params)
            request.parameters.push_back({name, parameterText(value), {"params['" + name + "']", 0}});
        return request;
    }

    /** Binds Run, the planning run of one library (built from a Scene and a Request), as the class
        PlanningRun of module m, with what the runs of both libraries have: the constructor from
        (scene, planner, seed, time_limit, params: name -> value, named "params['name']" in errors), solve()
       without the GIL (Ctrl-C raises KeyboardInterrupt once the planner has stopped), solved and
       record_json() (the record as the app's --json writes it). Returns the class, for the library's own
       methods. Runs are made by makeRun(scene, request) (say, with the library's primitive factory). */
    template <typename Run, typename Request, typename Scene>
    pybind11::class_<Run> bindPlanningRun(
        pybind11::module_ &m, const char *doc,
        std::function<std::unique_ptr<Run>(const Scene &, Request)> makeRun =
            [](const Scene &scene, Request request)
        { return std::make_unique<Run>(scene, std::move(request)); })
    {
        namespace py = pybind11;
        return py::class_<Run>(m, "PlanningRun", doc)
            .def(py::init([makeRun](const Scene &scene, const std::string &planner, std::uint32_t seed,
                                    double timeLimit, const std::map<std::string, py::object> &params)
                          { return makeRun(scene, requestOf<Request>(planner, seed, timeLimit, params)); }),
                 py::arg("scene"), py::arg("planner"), py::arg("seed"), py::arg("time_limit"),
                 py::arg("params"))
            .def(
                "solve", [](Run &run) { planWithoutGil([&](const auto &stop) { run.solve(stop); }); },
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
