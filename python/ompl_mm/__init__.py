"""Multi-modal manipulation planning (MOPL) from Python.

    import ompl_mm
    scene = ompl_mm.load_scene("scenes/mobile_blocked.xml")
    result = ompl_mm.plan(scene, seed=3)
    result.path.tool            # numpy array, n x 3

plan() makes the run ompl_mm_plan makes: the same scene, planner, seed and time limit give the
same path and the same record. Bad input raises ompl_core.InputError, naming the file and line.

For a loop of one's own, the OMPL-level objects, named as in C++:

    ompl_mm.set_seed(1)
    setup = ompl_mm.ManipulationSetup(scene)
    setup.getPlanner().setParam("vertex_step", 0.3)
    if setup.solve(10.0):
        path = ompl_mm.Path(setup.getSolutionPath())
"""
import copy
import functools

from ompl_core import InputError, RunResult, solved_run
from ._ompl_mm import (ManipulationPath, ManipulationSetup, Planner, PlannerStatus, PlanningRun, Scene, load_scene,
                       set_log_level, set_seed)

__all__ = ["InputError", "ManipulationPath", "ManipulationSetup", "Path", "PlanResult", "Planner", "PlannerStatus",
           "PlanningRun", "Scene", "load_scene", "plan", "set_log_level", "set_seed"]


class Path:
    """A solution path (a ManipulationPath, from a PlanResult or ManipulationSetup.getSolutionPath())
    as numpy arrays: `states` (one row per state: the robot's joints, then x y z yaw per object),
    `labels` (per segment: the primitive kind and the object it moved, '' for none), `tool` (n x 3,
    metres) and `objects` (object name -> n x 4 array of x, y, z, yaw); `ompl_path` is the
    ManipulationPath itself."""

    def __init__(self, path):
        self.ompl_path = path
        arrays = path.arrays()
        self.states = arrays["states"]
        self.labels = arrays["labels"]
        self.tool = arrays["tool"]
        self.objects = arrays["objects"]


class PlanResult(RunResult):
    """What plan() gives: `solved`, `time_s` (the planner's time), `record` (a dict equal to what
    `ompl_mm_plan --json` writes, with "physics_check" when simulated), `path` (a Path, None when not
    solved), `simulated` (when simulated: object name -> n x 4 array of the simulated x, y, z, yaw
    at every waypoint; else None), and the app's files."""

    def __init__(self, run, title, simulate):
        self.simulated = run.simulate() if simulate and run.solved else None
        super().__init__(run, title)
        self.path = Path(run.path()) if run.solved else None

    def write_svg(self, file):
        """The picture ompl_mm_plan --svg writes."""
        self.run.write_svg(str(file))


def plan(scene, planner="mopl", seed=1, time_limit=60.0, params=None, simulate=False, push_model=None,
         threads=1):
    """Plans scene (a Scene or a scene file's path) with the registered planner (MOPL by default),
    random seed `seed` and `time_limit` seconds; `params` maps planner parameter names to values;
    `simulate` executes a solution in physics as ompl_mm_plan --simulate does; `push_model`
    ('kinematic' or 'physics', None: the scene's) is the model of every push, as ompl_mm_plan
    --push-model gives it (a Scene passed in is left as it is); `threads` MOPL searches race, as
    ompl_mm_plan --threads (the same plan per seed and thread count). The GIL is released while
    planning; Ctrl-C stops the planner and raises KeyboardInterrupt."""
    if isinstance(scene, str):
        scene = load_scene(scene)
    if push_model is not None:
        scene = copy.copy(scene)
        scene.set_push_model(push_model)
    run = solved_run(functools.partial(PlanningRun, threads=threads), scene, planner, seed, time_limit, params)
    return PlanResult(run, f"{scene.name} · {planner} · seed {seed}", simulate)
