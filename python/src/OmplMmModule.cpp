// The C++ side of the Python module ompl_mm (python/ompl_mm/__init__.py adds plan() and its result):
// scenes, planning runs as ompl_mm_plan makes them, and their paths as numpy arrays.
#include "ModuleSupport.h"
#include "ompl_mm/io/PathFile.h"
#include "ompl_mm/io/PlanningRun.h"
#include "ompl_mm/io/SceneHtml.h"
#include "ompl_mm/io/SceneSvg.h"
#include "ompl_mm/scene/SceneLoader.h"

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

    const ManipulationStateSpace &space(const PlanningRun &run)
    {
        return *run.setup().manipulationSpace();
    }

    /** One row per state of the solution, columns from row(state, out) (columns values each). */
    template <typename Row>
    py::array_t<double> rows(const PlanningRun &run, std::size_t columns, Row row)
    {
        const ManipulationPath &path = solution(run);
        return ompl_python::rows(path.getStateCount(), columns,
                                 [&](std::size_t i, double *out) { row(path.getState(i), out); });
    }
}  // namespace

PYBIND11_MODULE(_ompl_mm, m)
{
    m.doc() = "Multi-modal manipulation planning (MOPL): the C++ classes under ompl_mm's Python functions.";
    ompl_python::translateInputErrors();

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
        .def("__repr__", [](const Scene &scene) { return "<ompl_mm.Scene '" + scene.name + "'>"; });

    m.def("load_scene", &loadScene, py::arg("path"),
          "Reads a scene file (and the robot files it names). Raises ompl_core.InputError at the "
          "faulty line.");

    ompl_python::bindPlanningRun<PlanningRun, PlanningRequest, Scene>(
        m, "One planning run as ompl_mm_plan makes it: same seed, same path and record.")
        .def(
            "states",
            [](const PlanningRun &run)
            {
                const ManipulationStateSpace &s = space(run);
                std::vector<double> reals;
                return rows(run, s.getDimension(),
                            [&](const ompl::base::State *state, double *out)
                            {
                                s.copyToReals(reals, state);
                                std::copy(reals.begin(), reals.end(), out);
                            });
            },
            "The solution's states, one row each (the robot's joints, then x y z yaw per object).")
        .def(
            "labels",
            [](const PlanningRun &run)
            {
                const std::vector<MovableObject> &objects = space(run).model()->scene().objects;
                std::vector<std::pair<std::string, std::string>> labels;
                for (const SegmentLabel &label : solution(run).labels())
                    labels.emplace_back(primitiveKindName(label.kind),
                                        label.object >= 0
                                            ? objects[static_cast<std::size_t>(label.object)].name
                                            : std::string());
                return labels;
            },
            "Per segment (state i to i + 1): the primitive kind and the object it moved ('' for none).")
        .def(
            "tool",
            [](const PlanningRun &run)
            {
                const ManipulationStateSpace &s = space(run);
                return rows(run, 3,
                            [&](const ompl::base::State *state, double *out)
                            {
                                const Eigen::Vector3d tool = s.toolPosition(state);
                                std::copy(tool.data(), tool.data() + 3, out);
                            });
            },
            "The tool point's world position at each state (n x 3, metres).")
        .def(
            "object_track",
            [](const PlanningRun &run, unsigned int object)
            {
                const ManipulationStateSpace &s = space(run);
                if (object >= s.objectCount())
                    throw py::index_error("no object " + std::to_string(object));
                return rows(run, 4,
                            [&](const ompl::base::State *state, double *out)
                            {
                                const ObjectPose pose = s.objectPose(state, object);
                                out[0] = pose.position.x();
                                out[1] = pose.position.y();
                                out[2] = pose.position.z();
                                out[3] = pose.yaw;
                            });
            },
            py::arg("object"), "Object number object's x y z yaw at each state (n x 4).")
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
