// The C++ side of the Python module ompl_mm (python/ompl_mm/__init__.py adds plan() and its result):
// scenes, planning runs as ompl_mm_plan makes them, and their paths as numpy arrays.
#include "ModuleSupport.h"
#include "ompl_mm/io/PathFile.h"
#include "ompl_mm/io/PlanningRun.h"
#include "ompl_mm/io/SceneHtml.h"
#include "ompl_mm/io/SceneSvg.h"
#include "ompl_mm/scene/SceneLoader.h"
#include "ompl_mm/setup/ManipulationSetup.h"
#include "ompl_mmphys/io/PhysicsCheckRecord.h"
#include "ompl_mmphys/primitives/PhysicsPrimitives.h"

#include <pybind11/numpy.h>

namespace py = pybind11;
using namespace ompl_mm;

namespace
{
    /** The run's solution. @throws ompl::Exception when there is none. */
    const ManipulationPath &solution(const PlanningRun &run)
    {
        if (!run.solved())
            throw ompl::Exception("PlanningRun", "the run has no solution");
        return run.setup().manipulationPath();
    }

    /** Writes pose as x y z yaw to out[0..3]. */
    void writePose(const ObjectPose &pose, double *out)
    {
        out[0] = pose.position.x();
        out[1] = pose.position.y();
        out[2] = pose.position.z();
        out[3] = pose.yaw;
    }

    /** The path as numpy arrays, in one pass over its states: "states" (n x the space's values),
        "labels" (per segment: kind, object name or ''), "tool" (n x 3) and "objects" (name -> n x 4:
        x y z yaw). */
    py::dict pathArrays(const ManipulationPath &path)
    {
        const auto &space = *path.getSpaceInformation()->getStateSpace()->as<ManipulationStateSpace>();
        const std::vector<MovableObject> &objects = space.model()->scene().objects;
        const std::size_t count = path.getStateCount();
        py::array_t<double> tool({count, std::size_t{3}});
        auto toolOut = tool.mutable_unchecked<2>();
        std::vector<py::array_t<double>> tracks;
        std::vector<py::detail::unchecked_mutable_reference<double, 2>> tracksOut;
        for (std::size_t object = 0; object < objects.size(); ++object)
        {
            tracks.emplace_back(std::vector<std::size_t>{count, 4});
            tracksOut.push_back(tracks.back().mutable_unchecked<2>());
        }
        for (std::size_t i = 0; i < count; ++i)
        {
            const Eigen::Vector3d position = space.toolPosition(path.getState(i));
            for (int k = 0; k < 3; ++k)
                toolOut(i, k) = position[k];
            for (std::size_t object = 0; object < objects.size(); ++object)
            {
                writePose(space.objectPose(path.getState(i), static_cast<unsigned int>(object)),
                          &tracksOut[object](i, 0));
            }
        }
        py::list labels;
        for (const SegmentLabel &label : path.labels())
            labels.append(py::make_tuple(
                primitiveKindName(label.kind),
                label.object >= 0 ? objects[static_cast<std::size_t>(label.object)].name : std::string()));
        py::dict tracksByName;
        for (std::size_t object = 0; object < objects.size(); ++object)
            tracksByName[py::str(objects[object].name)] = tracks[object];
        py::dict arrays;
        arrays["states"] =
            ompl_python::stateRows(space, count, [&](std::size_t i) { return path.getState(i); });
        arrays["labels"] = labels;
        arrays["tool"] = tool;
        arrays["objects"] = tracksByName;
        return arrays;
    }
}  // namespace

PYBIND11_MODULE(_ompl_mm, m)
{
    m.doc() = "Multi-modal manipulation planning (MOPL): the C++ classes under ompl_mm's Python functions.";
    ompl_python::translateErrors();

    py::class_<Scene>(m, "Scene", "A manipulation scene, as load_scene() reads it.")
        .def_readonly("name", &Scene::name)
        .def_readonly("file", &Scene::file)
        .def_readonly("planner", &Scene::planner, "the planner the scene names")
        .def_readonly("time_limit", &Scene::timeLimit, "the scene's time limit, seconds")
        .def_property_readonly("objects",
                               [](const Scene &scene)
                               {
                                   std::vector<std::string> names;
                                   for (const MovableObject &object : scene.objects)
                                       names.push_back(object.name);
                                   return names;
                               })
        .def(
            "__copy__", [](const Scene &scene) { return Scene(scene); },
            "An independent copy (copy.copy): changing it leaves this scene as it is.")
        .def("set_push_model", &Scene::setPushModel, py::arg("model"),
             "Gives every push primitive the model 'kinematic' or 'physics' (physics-aware pushes), as "
             "if each push element said so; ompl_core.InputError for another model.")
        .def("__repr__", [](const Scene &scene) { return "<ompl_mm.Scene '" + scene.name + "'>"; });

    m.def("load_scene", &loadScene, py::arg("path"),
          "Reads a scene file (and the robot files it names). Raises ompl_core.InputError at the "
          "faulty line.");

    ompl_python::bindOmplGlobals(m);
    ompl_python::bindPlanner(m);
    ompl_python::bindPlannerStatus(m);

    py::class_<ManipulationPath>(m, "ManipulationPath",
                                 "A solution: OMPL's PathGeometric with one label per segment (a copy, "
                                 "independent of the setup it came from).")
        .def("getStateCount", &ManipulationPath::getStateCount)
        .def("__len__", &ManipulationPath::getStateCount)
        .def("length", &ManipulationPath::length, "The length in the state space's metric.")
        .def(
            "toolPathLength",
            [](const ManipulationPath &path)
            { return path.getStateCount() > 0 ? path.toolPathLength() : 0.0; },
            "The length of the tool point's path, metres.")
        .def("check", &ManipulationPath::check,
             "Whether every state and motion is valid (PathGeometric::check).")
        .def("interpolate", py::overload_cast<unsigned int>(&ManipulationPath::interpolate), py::arg("count"),
             "Inserts states along the motions until there are `count` (PathGeometric::interpolate); the "
             "labels follow from the motions.")
        .def("arrays", &pathArrays,
             "The path as numpy arrays (ompl_mm.Path reads them): a dict with 'states', 'labels', 'tool' "
             "and 'objects'.");

    py::class_<ManipulationSetup> setup(
        m, "ManipulationSetup",
        "OMPL's SimpleSetup for a manipulation scene (C++ ompl_mm::ManipulationSetup).");
    setup
        .def(py::init(
                 [](const Scene &scene) {
                     return std::make_unique<ManipulationSetup>(scene,
                                                                ompl_mmphys::physicsPrimitiveFactory());
                 }),
             py::arg("scene"),
             "Builds the problem and the scene's planner with its parameters; ompl_core.InputError at a "
             "faulty line of the scene or its robot.")
        .def("selectPlanner", &ManipulationSetup::selectPlanner, py::arg("name"),
             "setPlannerByName, then gives the planner the scene's parameters that it declares.")
        .def(
            "getSolutionPath",
            [](const ManipulationSetup &s) { return ManipulationPath(s.manipulationPath()); },
            "A copy of the solution as a ManipulationPath; RuntimeError when there is none.")
        .def("simplifySolution", py::overload_cast<double>(&ManipulationSetup::simplifySolution),
             py::arg("duration") = 0.0, "OMPL's simplifier on the solution (0: until it converges).")
        .def(
            "smoothSolution",
            [](ManipulationSetup &s, unsigned int attempts, std::uint32_t seed)
            { s.smoothSolution(attempts, seed); },
            py::arg("attempts") = 30, py::arg("seed") = 1,
            "MOPL's mode-aware smoothing of the solution, in place.");
    ompl_python::bindSetupMethods(
        setup, static_cast<ompl_python::PlannerHandle::ApplyParameters>(&ManipulationSetup::applyParameters));

    const auto makeRun = [](const Scene &scene, PlanningRequest request)
    {
        return std::make_unique<PlanningRun>(scene, std::move(request), 0.0,
                                             ompl_mmphys::physicsPrimitiveFactory());
    };
    ompl_python::bindPlanningRun<PlanningRun, PlanningRequest, Scene>(
        m, "One planning run as ompl_mm_plan makes it: same seed, same path and record.", makeRun)
        .def(py::init(
                 [makeRun](const Scene &scene, const std::string &planner, std::uint32_t seed,
                           double timeLimit, const std::map<std::string, py::object> &params,
                           unsigned int threads)
                 {
                     auto request = ompl_python::requestOf<PlanningRequest>(planner, seed, timeLimit, params);
                     request.threads = threads;
                     return makeRun(scene, std::move(request));
                 }),
             py::arg("scene"), py::arg("planner"), py::arg("seed"), py::arg("time_limit"), py::arg("params"),
             py::arg("threads"), "A run of `threads` MOPL searches racing, as ompl_mm_plan --threads.")
        .def(
            "simulate",
            [](PlanningRun &run)
            {
                ompl_mmphys::PhysicsCheck check;
                {
                    const py::gil_scoped_release release;
                    check = ompl_mmphys::checkPlan(run.setup(), solution(run));
                }
                run.addRecord("physics_check", ompl_mmphys::physicsCheckRecord(check));
                const std::vector<MovableObject> &objects = run.setup().model()->scene().objects;
                const auto &poses = check.simulation.statePoses;
                py::dict tracks;
                for (std::size_t k = 0; k < objects.size(); ++k)
                    tracks[py::str(objects[k].name)] = ompl_python::rows(
                        poses.size(), 4, [&](std::size_t i, double *out) { writePose(poses[i][k], out); });
                return tracks;
            },
            "Executes the solution in physics (ompl_mmphys::checkPlan, as ompl_mm_plan --simulate), adds "
            "'physics_check' to the record and returns each object's simulated pose at every waypoint "
            "(name -> n x 4: x, y, z, yaw).")
        .def(
            "path", [](const PlanningRun &run) { return ManipulationPath(solution(run)); },
            "A copy of the solution (ompl_mm.ManipulationPath); RuntimeError when there is none.")
        .def(
            "write_svg",
            [](const PlanningRun &run, const std::string &file)
            {
                ompl_python::writeFile(
                    file, [&](std::ostream &out)
                    { writeSceneSvg(out, run.setup(), run.solved() ? &solution(run) : nullptr); });
            },
            py::arg("file"))
        .def(
            "write_html",
            [](const PlanningRun &run, const std::string &file, const std::string &title)
            {
                ompl_python::writeFile(
                    file, [&](std::ostream &out)
                    { writeSceneHtml(out, run.setup(), run.solved() ? &solution(run) : nullptr, title); });
            },
            py::arg("file"), py::arg("title"))
        .def(
            "write_path",
            [](const PlanningRun &run, const std::string &file)
            { ompl_python::writeFile(file, [&](std::ostream &out) { writePathFile(out, solution(run)); }); },
            py::arg("file"));
}
