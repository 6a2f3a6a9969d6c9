"""Tests for the Python module ompl_mm: plan() gives what ompl_mm_plan gives for the same scene,
planner, seed and time limit (record and path file), its arrays have the right shapes and values,
runs are deterministic, bad input raises ompl_core.InputError with file and line, planning
releases the GIL and Ctrl-C ends it. Run by ctest with the build tree's python folder on PYTHONPATH; the app's and
scenes' locations come from OMPL_MM_PLAN and OMPL_MM_SCENES."""
import json
import os
import subprocess
import threading
import time

import numpy
import pytest

import ompl_core
import ompl_mm
from ompl_core import without_times
from signal_support import interrupted

SCENES = os.environ["OMPL_MM_SCENES"]
APP = os.environ["OMPL_MM_PLAN"]


def scene_path(name):
    return os.path.join(SCENES, name + ".xml")


def app_run(tmp_path, scene, seed, planner="mopl", time_limit=60.0):
    """The app's JSON record and path file rows for the same run."""
    record, path = tmp_path / "app.json", tmp_path / "app.txt"
    subprocess.run([APP, scene_path(scene), "--seed", str(seed), "--planner", planner, "--time-limit",
                    str(time_limit), "--json", str(record), "--path", str(path)],
                   check=False, capture_output=True)
    with open(record, encoding="utf-8") as f:
        return json.load(f), path


@pytest.mark.parametrize("scene,seed", [("mobile_blocked", 3), ("kuka_table", 2)])
def test_plan_gives_the_apps_record_and_path_for_the_same_seed(tmp_path, scene, seed):
    result = ompl_mm.plan(ompl_mm.load_scene(scene_path(scene)), seed=seed)
    app_record, app_path = app_run(tmp_path, scene, seed)
    assert result.solved and app_record["solved"]
    assert without_times(result.record) == without_times(app_record)
    assert list(result.record) == list(app_record), "the keys in the app's order"
    ours = tmp_path / "ours.txt"
    result.write_path(ours)
    assert ours.read_text() == app_path.read_text()


def test_the_paths_arrays_match_the_path_file(tmp_path):
    scene = ompl_mm.load_scene(scene_path("mobile_blocked"))
    result = ompl_mm.plan(scene, seed=5)
    path = result.path
    n = result.record["path_vertices"]
    assert path.states.shape[0] == n and path.tool.shape == (n, 3)
    assert len(path.labels) == n - 1
    assert set(path.objects) == set(scene.objects)
    file = tmp_path / "path.txt"
    result.write_path(file)
    rows = numpy.loadtxt(file, usecols=range(2, 2 + 3 + 2 + 4 * len(scene.objects)), ndmin=2)
    numpy.testing.assert_allclose(path.tool, rows[:, 0:3], atol=1e-8)
    numpy.testing.assert_allclose(path.states[:, 0:2], rows[:, 3:5], atol=1e-8)  # the base's x, y
    for i, name in enumerate(scene.objects):
        numpy.testing.assert_allclose(path.objects[name], rows[:, 5 + 4 * i:9 + 4 * i], atol=1e-8)
    kinds = {kind for kind, _ in path.labels}
    assert kinds <= {"transit", "push", "pickup", "transfer"} and "push" in kinds
    # the tool path length of the record is the length of the tool's polyline
    assert numpy.isclose(numpy.linalg.norm(numpy.diff(path.tool, axis=0), axis=1).sum(),
                         result.record["path_length_m"])


def test_the_same_seed_gives_the_same_result():
    scene = ompl_mm.load_scene(scene_path("mobile_blocked"))
    first, second = ompl_mm.plan(scene, seed=7), ompl_mm.plan(scene, seed=7)
    assert without_times(first.record) == without_times(second.record)
    assert numpy.array_equal(first.path.states, second.path.states)


def test_a_race_of_two_searches_gives_the_same_result_twice():
    scene = ompl_mm.load_scene(scene_path("mobile_blocked"))
    first, second = ompl_mm.plan(scene, seed=87, threads=2), ompl_mm.plan(scene, seed=87, threads=2)
    assert first.solved and first.record["path_valid"]
    assert without_times(first.record) == without_times(second.record)
    assert numpy.array_equal(first.path.states, second.path.states)
    with pytest.raises(ompl_core.InputError) as error:
        ompl_mm.plan(scene, threads=0)
    assert "threads must be 1 to 64" in str(error.value)


def test_a_scene_path_may_be_given_as_text():
    assert ompl_mm.plan(scene_path("mobile_blocked"), seed=1).solved


def test_pictures_are_written(tmp_path):
    result = ompl_mm.plan(scene_path("mobile_blocked"), seed=1)
    result.write_svg(tmp_path / "plan.svg")
    result.write_html(tmp_path / "plan.html")
    assert (tmp_path / "plan.svg").read_text().startswith("<?xml") or "<svg" in (tmp_path / "plan.svg").read_text()
    assert "mobile_blocked · mopl · seed 1" in (tmp_path / "plan.html").read_text()


def test_a_missing_scene_file_raises_input_error_naming_it():
    with pytest.raises(ompl_core.InputError) as error:
        ompl_mm.load_scene("/no/such/scene.xml")
    assert "/no/such/scene.xml" in str(error.value)


def test_a_malformed_scene_raises_input_error_with_file_and_line(tmp_path):
    text = open(scene_path("mobile_blocked"), encoding="utf-8").read().replace(
        '<origin xyz="-1 0 0.5"/>', '<origin xyz="-1 0 0.5abc"/>', 1).replace(
        'urdf="robots/', f'urdf="{SCENES}/robots/', 1)
    bad = tmp_path / "bad.xml"
    bad.write_text(text)
    line = text[:text.index("0.5abc")].count("\n") + 1
    with pytest.raises(ompl_core.InputError) as error:
        ompl_mm.load_scene(str(bad))
    assert error.value.file == str(bad) and error.value.line == line
    assert str(error.value).startswith(f"{bad}:{line}: ")


def test_a_bad_parameter_raises_input_error_naming_it():
    scene = ompl_mm.load_scene(scene_path("mobile_blocked"))
    with pytest.raises(ompl_core.InputError) as error:
        ompl_mm.plan(scene, params={"vertex_stride": 1})
    assert "vertex_stride" in str(error.value)
    with pytest.raises(ompl_core.InputError) as error:
        ompl_mm.plan(scene, params={"connect_step": -1})
    assert "connect_step" in str(error.value)
    with pytest.raises(ompl_core.InputError):
        ompl_mm.plan(scene, planner="no_such_planner")


def test_bad_seeds_and_time_limits_raise_value_error():
    scene = ompl_mm.load_scene(scene_path("mobile_blocked"))
    for seed in (0, -1, 2**32):
        with pytest.raises(ValueError):
            ompl_mm.plan(scene, seed=seed)
    with pytest.raises(ValueError):
        ompl_mm.plan(scene, time_limit=0)


def test_a_parameter_set_from_python_reaches_the_planner():
    scene = ompl_mm.load_scene(scene_path("mobile_blocked"))
    default, changed = ompl_mm.plan(scene, seed=2), ompl_mm.plan(scene, seed=2, params={"connect_step": 0.1})
    assert without_times(default.record) != without_times(changed.record)


def test_planning_releases_the_gil():
    """While a 2 s plan runs in another thread (MEKA CLEAN-UP, not solved that soon), this thread
    keeps running: no pause in its loop comes near the plan's length, as one would if the plan
    held the GIL."""
    scene = ompl_mm.load_scene(scene_path("meka_cleanup"))
    started, results = threading.Event(), []

    def plan():
        started.set()
        results.append(ompl_mm.plan(scene, seed=1, time_limit=2.0))

    thread = threading.Thread(target=plan)
    thread.start()
    started.wait()
    longest_pause, last = 0.0, time.perf_counter()
    while thread.is_alive():
        now = time.perf_counter()
        longest_pause, last = max(longest_pause, now - last), now
    thread.join()
    assert results and results[0].time_s > 1.5, "the plan ran most of its 2 s"
    assert longest_pause < 1.0, f"this thread stopped for {longest_pause:.2f} s while the plan ran"


def test_ctrl_c_stops_the_plan_and_raises_keyboard_interrupt():
    """SIGINT during a long plan (MEKA CLEAN-UP, seconds) ends it soon, as KeyboardInterrupt."""
    status, out = interrupted(
        f"import ompl_mm; ompl_mm.plan({scene_path('meka_cleanup')!r}, seed=1, time_limit=600)", 1.0)
    assert status == 3 and out.endswith("interrupted\n"), out  # OMPL logs to stdout before


def test_plans_in_threads_leave_the_interpreter_free():
    """Two 1 s plans (MEKA CLEAN-UP, not solved that soon) in two threads while this thread keeps
    running Python: it is never held up for anywhere near a plan's second, as it would be while a
    plan held the GIL (a measure of the interpreter's freedom, not of the machine's speed)."""
    scene = ompl_mm.load_scene(scene_path("meka_cleanup"))
    results = []
    threads = [threading.Thread(target=lambda: results.append(ompl_mm.plan(scene, seed=1, time_limit=1.0)))
               for _ in range(2)]
    for thread in threads:
        thread.start()
    longest_wait, last = 0.0, time.perf_counter()
    while any(thread.is_alive() for thread in threads):
        now = time.perf_counter()
        longest_wait, last = max(longest_wait, now - last), now
    assert len(results) == 2 and all(result.time_s > 0.9 for result in results)
    assert longest_wait < 0.5, f"this thread waited {longest_wait:.2f} s at once"


def plan_with_setup(scene, seed, vertex_step=None):
    """A custom loop's plan: seed, setup, a parameter, solve; the status and the Path."""
    ompl_mm.set_seed(seed)
    setup = ompl_mm.ManipulationSetup(scene)
    if vertex_step is not None:
        setup.getPlanner().setParam("vertex_step", vertex_step)
    status = setup.solve(30.0)
    return setup, status, ompl_mm.Path(setup.getSolutionPath())


def test_a_custom_loop_solves_changes_a_parameter_and_solves_again():
    scene = ompl_mm.load_scene(scene_path("mobile_blocked"))
    setup, status, path = plan_with_setup(scene, seed=4)
    assert status and status.exact and str(status) == "Exact solution"
    assert setup.haveExactSolutionPath() and setup.getLastPlanComputationTime() > 0
    assert path.ompl_path.check() and len(path.ompl_path) == path.states.shape[0] == path.tool.shape[0]
    assert len(path.labels) == len(path.ompl_path) - 1 and set(path.objects) == set(scene.objects)
    assert numpy.isclose(numpy.linalg.norm(numpy.diff(path.tool, axis=0), axis=1).sum(),
                         path.ompl_path.toolPathLength())
    planner = setup.getPlanner()
    assert planner.getName() == "MOPL" and "vertex_step" in planner.params()
    setup.clear()
    planner.setParam("vertex_step", 0.5)
    assert planner.getParam("vertex_step") == "0.5"
    assert setup.solve(30.0) and ompl_mm.Path(setup.getSolutionPath()).ompl_path.check()


def test_a_custom_loop_is_deterministic():
    scene = ompl_mm.load_scene(scene_path("mobile_blocked"))
    _, _, first = plan_with_setup(scene, seed=6, vertex_step=0.3)
    _, _, second = plan_with_setup(scene, seed=6, vertex_step=0.3)
    assert numpy.array_equal(first.states, second.states) and first.labels == second.labels


def test_another_registered_planner_can_be_chosen_by_name():
    scene = ompl_mm.load_scene(scene_path("mobile_blocked"))
    assert set(ompl_mm.ManipulationSetup.planners()) >= {"mopl", "rrtconnect", "rrt", "est"}
    setup = ompl_mm.ManipulationSetup(scene)
    setup.setPlannerByName("rrtconnect")
    assert setup.getPlanner().getName() == "RRTConnect"
    with pytest.raises(ompl_core.InputError) as error:
        setup.setPlannerByName("no_such_planner")
    assert "no_such_planner" in str(error.value) and "mopl" in str(error.value)


def test_parameters_are_checked_as_on_the_command_line():
    planner = ompl_mm.ManipulationSetup(ompl_mm.load_scene(scene_path("mobile_blocked"))).getPlanner()
    assert planner.paramRanges()["vertex_step"] == "0.01:0.01:10"
    with pytest.raises(ompl_core.InputError) as error:
        planner.setParam("vertex_step", 1000)
    assert error.value.file == "setParam('vertex_step')" and "range 0.01:0.01:10" in str(error.value)
    with pytest.raises(ompl_core.InputError) as error:
        planner.setParam("vertex_stride", 1)
    assert "unknown parameter 'vertex_stride'" in str(error.value) and "vertex_step" in str(error.value)
    with pytest.raises(ompl_core.InputError):
        planner.setParam("restart_iterations", 1.5)
    with pytest.raises(ompl_core.InputError) as error:  # MOPL's rule between parameters
        planner.setParam("undefined_probability", 0.8)
    assert "undefined_probability + start_value_probability exceeds 1" in str(error.value)
    with pytest.raises(KeyError):
        planner.getParam("vertex_stride")
    assert planner.getParam("vertex_step") == "0.35", "a refused value leaves the parameter as it was"


def test_a_setup_without_a_solution_says_so():
    setup = ompl_mm.ManipulationSetup(ompl_mm.load_scene(scene_path("mobile_blocked")))
    assert not setup.haveSolutionPath() and setup.goal_fault is None
    with pytest.raises(RuntimeError):
        setup.getSolutionPath()
    with pytest.raises(ValueError):
        setup.solve(0.0)
    with pytest.raises(ValueError):
        ompl_mm.set_log_level("loud")


def test_ctrl_c_stops_a_setups_solve_and_raises_keyboard_interrupt():
    # SIGINT half a second into the solve; seeded: this seed's solve takes seconds (7.7 s at
    # f7e6b06), and the check of MEKA CLEAN-UP's goal when the setup is made depends on the seed
    setup = ("import ompl_mm; ompl_mm.set_seed(6); "
             f"setup = ompl_mm.ManipulationSetup(ompl_mm.load_scene({scene_path('meka_cleanup')!r}))")
    status, out = interrupted("setup.solve(600)", 0.5, prelude=setup)
    assert status == 3 and out.endswith("interrupted\n"), out


def test_simulate_gives_the_apps_physics_check(tmp_path):
    result = ompl_mm.plan(scene_path("mobile_blocked"), seed=3, simulate=True)
    record, path = tmp_path / "app.json", tmp_path / "app.txt"
    subprocess.run([APP, scene_path("mobile_blocked"), "--seed", "3", "--simulate", "--json", str(record),
                    "--path", str(path)], check=True, capture_output=True)
    with open(record, encoding="utf-8") as f:
        app_check = json.load(f)["physics_check"]
    assert without_times(result.record["physics_check"]) == without_times(app_check)
    names = open(path, encoding="utf-8").readline().split()[1:]
    rows = numpy.loadtxt(path, usecols=range(2, len(names)), ndmin=2)
    for name, track in result.simulated.items():
        assert track.shape == (len(result.path.states), 4)
        first = names.index(f"sim.{name}.x") - 2
        numpy.testing.assert_allclose(track, rows[:, first:first + 4], atol=1e-8)
    assert ompl_mm.plan(scene_path("mobile_blocked"), seed=3).simulated is None


def test_push_model_physics_plans_as_the_apps_push_model_option(tmp_path):
    scene = ompl_mm.load_scene(scene_path("mobile_blocked"))
    result = ompl_mm.plan(scene, seed=2, simulate=True, push_model="physics")
    record = tmp_path / "app.json"
    subprocess.run([APP, scene_path("mobile_blocked"), "--seed", "2", "--simulate", "--push-model", "physics",
                    "--json", str(record)], check=True, capture_output=True)
    with open(record, encoding="utf-8") as f:
        app_check = json.load(f)["physics_check"]
    assert result.record["physics_check"]["confirmed"]
    assert without_times(result.record["physics_check"]) == without_times(app_check)
    # the scene passed in keeps its kinematic pushes: the same seed plans as before
    kinematic = ompl_mm.plan(scene, seed=2, simulate=True)
    assert not kinematic.record["physics_check"]["confirmed"]
    with pytest.raises(ompl_mm.InputError, match="push model must be kinematic or physics, got 'exact'"):
        ompl_mm.plan(scene, push_model="exact")
