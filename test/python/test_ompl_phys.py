"""Tests for the Python module ompl_phys: plan() gives what ompl_phys_plan gives for the same scene,
planner, seed and time limit (record and path file), its arrays agree with the path file and with
the controls (durations sum to the re-simulated time), runs are deterministic, and bad input raises
ompl_core.InputError with file and line. Run by ctest with the build tree's python folder on
PYTHONPATH; the app's and scenes' locations come from OMPL_PHYS_PLAN and OMPL_MM_SCENES."""
import json
import os
import subprocess

import numpy
import pytest

import ompl_core
import ompl_phys
from ompl_core import without_times

SCENES = os.path.join(os.environ["OMPL_MM_SCENES"], "physics")
APP = os.environ["OMPL_PHYS_PLAN"]


def scene_path(name):
    return os.path.join(SCENES, name + ".xml")


@pytest.mark.parametrize("scene,planner,seed", [("scene2", "kpiece", 1), ("scene1", "rrt", 3)])
def test_plan_gives_the_apps_record_and_path_for_the_same_seed(tmp_path, scene, planner, seed):
    result = ompl_phys.plan(ompl_phys.load_scene(scene_path(scene)), planner=planner, seed=seed)
    record, path = tmp_path / "app.json", tmp_path / "app.txt"
    subprocess.run([APP, scene_path(scene), "--planner", planner, "--seed", str(seed), "--time-limit", "60",
                    "--json", str(record), "--path", str(path)], check=False, capture_output=True)
    app_record = json.loads(record.read_text())
    assert result.solved and app_record["solved"] and result.record["reaches_goal"]
    assert without_times(result.record) == without_times(app_record)
    ours = tmp_path / "ours.txt"
    result.write_path(ours)
    assert ours.read_text() == path.read_text()


def test_the_arrays_agree_with_the_controls_and_the_metrics():
    scene = ompl_phys.load_scene(scene_path("scene2"))
    result = ompl_phys.plan(scene, seed=2)
    controls, path = result.controls, result.path
    assert controls.shape == (result.record["moves"], 3)
    steps = path.tool.shape[0] - 1
    assert numpy.isclose(controls[:, 2].sum(), result.record["duration_s"])
    assert path.tool.shape == (steps + 1, 3) and set(path.objects) == set(scene.movable_bodies)
    for track in path.objects.values():
        assert track.shape == (steps + 1, 4)
    assert numpy.all(numpy.abs(controls[:, :2]) <= 1e6)


def test_the_same_seed_gives_the_same_result():
    scene = ompl_phys.load_scene(scene_path("scene1"))
    first, second = ompl_phys.plan(scene, seed=4), ompl_phys.plan(scene, seed=4)
    assert without_times(first.record) == without_times(second.record)
    assert numpy.array_equal(first.controls, second.controls)


def test_pictures_are_written(tmp_path):
    result = ompl_phys.plan(scene_path("scene1"), seed=1)
    result.write_svg(tmp_path / "plan.svg")
    result.write_html(tmp_path / "plan.html")
    assert "<svg" in (tmp_path / "plan.svg").read_text()
    assert "scene1 · kpiece · seed 1" in (tmp_path / "plan.html").read_text()


def test_bad_input_raises_input_error():
    with pytest.raises(ompl_core.InputError) as error:
        ompl_phys.load_scene("/no/such/scene.xml")
    assert "/no/such/scene.xml" in str(error.value)
    scene = ompl_phys.load_scene(scene_path("scene1"))
    with pytest.raises(ompl_core.InputError) as error:
        ompl_phys.plan(scene, params={"goal_bias": 2})
    assert "goal_bias" in str(error.value)
    with pytest.raises(ompl_core.InputError):
        ompl_phys.plan(scene, planner="no_such_planner")
    with pytest.raises(ValueError):
        ompl_phys.plan(scene, seed=0)


def test_a_custom_loop_solves_changes_a_parameter_and_solves_again():
    scene = ompl_phys.load_scene(os.path.join(SCENES, "scene2.xml"))
    ompl_phys.set_seed(1)
    setup = ompl_phys.PhysicsSetup(scene)
    assert setup.getPlanner().getName() == "KPIECE1" and setup.goal_fault is None
    assert setup.solve(60.0) and setup.haveExactSolutionPath()
    path = setup.getSolutionPath()
    controls, states = path.controls(), path.states()
    assert controls.shape == (path.getControlCount(), 3) and states.shape[0] == path.getStateCount()
    assert states.shape[1] == 13 * (1 + len(scene.movable_bodies)), "13 values per moving body"
    assert numpy.isclose(controls[:, 2].sum(), path.length()) and path.check()
    setup.setPlannerByName("rrt")
    planner = setup.getPlanner()
    planner.setParam("intermediate_states", True)
    assert planner.getParam("intermediate_states") == "1"
    with pytest.raises(ompl_core.InputError) as error:
        planner.setParam("goal_bias", 2)
    assert "goal_bias" in str(error.value) and "range" in str(error.value)
    setup.clear()
    assert setup.solve(60.0)


def test_a_custom_loop_is_deterministic():
    scene = ompl_phys.load_scene(os.path.join(SCENES, "scene2.xml"))

    def controls():
        ompl_phys.set_seed(3)
        setup = ompl_phys.PhysicsSetup(scene)
        assert setup.solve(60.0)
        return setup.getSolutionPath().controls()

    assert numpy.array_equal(controls(), controls())
