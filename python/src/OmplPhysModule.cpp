// The C++ side of the Python module ompl_phys (python/ompl_phys/__init__.py adds plan() and its
// result): physics scenes, planning runs as ompl_phys_plan makes them, their controls and their
// re-simulation as numpy arrays.
#include "ModuleSupport.h"
#include "ompl_phys/io/PhysicsPathFile.h"
#include "ompl_phys/io/PhysicsPlanningRun.h"
#include "ompl_phys/io/PhysicsSceneHtml.h"
#include "ompl_phys/io/PhysicsSceneSvg.h"
#include "ompl_phys/scene/PhysicsSceneLoader.h"

#include <ompl/control/PathControl.h>

#include <ompl/control/spaces/RealVectorControlSpace.h>

#include <cmath>

namespace py = pybind11;
using namespace ompl_phys;

namespace
{
    /** The run's re-simulated solution. @throws ompl::Exception when there is none. */
    const SimulatedPath &simulated(const PhysicsPlanningRun &run)
    {
        if (!run.simulated())
            throw ompl::Exception("PhysicsPlanningRun", "the run has no solution");
        return *run.simulated();
    }

    /** The path's controls, one row each: force x, force y and duration. */
    py::array_t<double> controlRows(const ompl::control::PathControl &path)
    {
        return ompl_python::rows(
            path.getControlCount(), 3,
            [&](std::size_t i, double *out)
            {
                const auto *force =
                    path.getControl(i)->as<ompl::control::RealVectorControlSpace::ControlType>();
                out[0] = force->values[0];
                out[1] = force->values[1];
                out[2] = path.getControlDuration(i);
            });
    }

    /** Yaw of a body orientation (about the world z axis). */
    double yawOf(const Eigen::Quaterniond &q)
    {
        return std::atan2(2.0 * (q.w() * q.z() + q.x() * q.y()), 1.0 - 2.0 * (q.y() * q.y() + q.z() * q.z()));
    }
}  // namespace

PYBIND11_MODULE(_ompl_phys, m)
{
    m.doc() = "Physics-based planning (ODE): the C++ classes under ompl_phys's Python functions.";
    ompl_python::translateErrors();

    py::class_<PhysicsScene>(m, "Scene", "A physics scene, as load_scene() reads it.")
        .def_readonly("name", &PhysicsScene::name)
        .def_readonly("file", &PhysicsScene::file)
        .def_readonly("time_limit", &PhysicsScene::timeLimit, "the scene's time limit, seconds")
        .def_property_readonly("movable_bodies",
                               [](const PhysicsScene &scene)
                               {
                                   std::vector<std::string> names;
                                   for (std::size_t body : scene.movableBodies())
                                       names.push_back(scene.bodies[body].name);
                                   return names;
                               })
        .def("__repr__", [](const PhysicsScene &scene) { return "<ompl_phys.Scene '" + scene.name + "'>"; });

    m.def("load_scene", &loadPhysicsScene, py::arg("path"),
          "Reads a physics scene file. Raises ompl_core.InputError at the faulty line.");

    ompl_python::bindOmplGlobals(m);
    ompl_python::bindPlanner(m);
    ompl_python::bindPlannerStatus(m);

    py::class_<ompl::control::PathControl>(
        m, "PathControl", "A solution: OMPL's control path (a copy, independent of its setup).")
        .def("getStateCount", &ompl::control::PathControl::getStateCount)
        .def("getControlCount", &ompl::control::PathControl::getControlCount)
        .def("__len__", &ompl::control::PathControl::getStateCount)
        .def("length", &ompl::control::PathControl::length, "The total duration of the controls, seconds.")
        .def("check", &ompl::control::PathControl::check,
             "Whether every state is valid (PathControl::check).")
        .def("controls", &controlRows, "One row per control: force x, force y (N) and duration (s).")
        .def(
            "states",
            [](const ompl::control::PathControl &path)
            {
                return ompl_python::stateRows(*path.getSpaceInformation()->getStateSpace(),
                                              path.getStateCount(),
                                              [&](std::size_t i) { return path.getState(i); });
            },
            "One row per state: per moving body (the robot first, then the movable bodies in scene order) "
            "position x y z, orientation quaternion x y z w, linear and angular velocity.");

    py::class_<PhysicsSetup> setup(
        m, "PhysicsSetup", "OMPL's control SimpleSetup for a physics scene (C++ ompl_phys::PhysicsSetup).");
    setup
        .def(py::init<const PhysicsScene &>(), py::arg("scene"),
             "Builds the ODE world, the propagator with its manipulation knowledge and KPIECE1; "
             "ompl_core.InputError at a faulty line of the scene.")
        .def(
            "getSolutionPath",
            [](const PhysicsSetup &s)
            {
                if (!s.haveSolutionPath())
                    throw ompl::Exception("PhysicsSetup", "the setup has no solution");
                return ompl::control::PathControl(s.getSolutionPath());
            },
            "A copy of the solution as a PathControl; RuntimeError when there is none.");
    ompl_python::bindSetupMethods(setup, &ompl_core::applyParameters);

    ompl_python::bindPlanningRun<PhysicsPlanningRun, PhysicsPlanningRequest, PhysicsScene>(
        m, "One planning run as ompl_phys_plan makes it: same seed, same path and record.")
        .def(
            "path",
            [](const PhysicsPlanningRun &run)
            {
                simulated(run);
                return ompl::control::PathControl(run.setup().getSolutionPath());
            },
            "A copy of the solution (ompl_phys.PathControl); RuntimeError when there is none.")
        .def(
            "robot",
            [](const PhysicsPlanningRun &run)
            {
                const std::vector<Eigen::Vector3d> &positions = simulated(run).robot.positions;
                return ompl_python::rows(positions.size(), 3,
                                         [&](std::size_t i, double *out)
                                         { std::copy(positions[i].data(), positions[i].data() + 3, out); });
            },
            "The re-simulated robot centre at every propagation step (n x 3, metres).")
        .def(
            "body_track",
            [](const PhysicsPlanningRun &run, std::size_t movingIndex)
            {
                const std::vector<BodyStates> &states = simulated(run).states;
                if (movingIndex >= run.setup().world().movingBodyCount())
                    throw py::index_error("no moving body " + std::to_string(movingIndex));
                return ompl_python::rows(states.size(), 4,
                                         [&](std::size_t i, double *out)
                                         {
                                             const BodyState &body = states[i][movingIndex];
                                             std::copy(body.position.data(), body.position.data() + 3, out);
                                             out[3] = yawOf(body.orientation);
                                         });
            },
            py::arg("moving_index"),
            "Moving body number moving_index (0 the robot, then the movable bodies in scene order): x y z "
            "yaw at every re-simulated step (n x 4).")
        .def("moving_body_name", [](const PhysicsPlanningRun &run, std::size_t movingIndex)
             { return run.setup().world().movingBodyName(movingIndex); })
        .def("moving_body_count",
             [](const PhysicsPlanningRun &run) { return run.setup().world().movingBodyCount(); })
        .def(
            "write_svg",
            [](const PhysicsPlanningRun &run, const std::string &file, const std::string &title)
            {
                ompl_python::writeFile(file, [&](std::ostream &out)
                                       { writePhysicsSceneSvg(out, run.setup(), run.simulated(), title); });
            },
            py::arg("file"), py::arg("title"))
        .def(
            "write_html",
            [](const PhysicsPlanningRun &run, const std::string &file, const std::string &title)
            {
                ompl_python::writeFile(file, [&](std::ostream &out)
                                       { writePhysicsSceneHtml(out, run.setup(), run.simulated(), title); });
            },
            py::arg("file"), py::arg("title"))
        .def(
            "write_path",
            [](const PhysicsPlanningRun &run, const std::string &file)
            {
                ompl_python::writeFile(file, [&](std::ostream &out)
                                       { writeSimulatedPathFile(out, run.setup(), simulated(run)); });
            },
            py::arg("file"));
}
