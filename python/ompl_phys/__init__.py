"""Physics-based planning (pushing with ODE) from Python.

    import ompl_phys
    scene = ompl_phys.load_scene("scenes/physics/scene2.xml")
    result = ompl_phys.plan(scene, planner="kpiece", seed=1)
    result.controls               # numpy array: force x, force y, duration per control
    result.record["action"]       # the re-simulated path's action, power, smoothness

plan() makes the run ompl_phys_plan makes: the same scene, planner, seed and time limit give the
same path and the same record. Bad input raises ompl_core.InputError, naming the file and line.

For a loop of one's own, the OMPL-level objects, named as in C++:

    ompl_phys.set_seed(1)
    setup = ompl_phys.PhysicsSetup(scene)
    setup.setPlannerByName("rrt")
    setup.getPlanner().setParam("goal_bias", 0.1)
    if setup.solve(30.0):
        controls = setup.getSolutionPath().controls()
"""
from ompl_core import InputError, RunResult, solved_run
from ._ompl_phys import (PathControl, PhysicsSetup, Planner, PlannerStatus, PlanningRun, Scene, load_scene,
                         set_log_level, set_seed)

__all__ = ["InputError", "Path", "PathControl", "PhysicsSetup", "PlanResult", "Planner", "PlannerStatus",
           "PlanningRun", "Scene", "load_scene", "plan", "set_log_level", "set_seed"]


class Path:
    """A solution's re-simulation as numpy arrays, one row per propagation step from the start:
    `tool` (the robot's centre, n x 3, metres: the sphere robot pushes with its whole body) and
    `objects` (movable body name -> n x 4 array of x, y, z, yaw)."""

    def __init__(self, run):
        self.tool = run.robot()
        self.objects = {run.moving_body_name(i): run.body_track(i) for i in range(1, run.moving_body_count())}


class PlanResult(RunResult):
    """What plan() gives: `solved`, `time_s` (the planner's time), `record` (a dict equal to what
    `ompl_phys_plan --json` writes, with the metrics action, power and smoothness), `controls`
    (force x, force y, duration per control; None when not solved), `path` (a Path, None when not
    solved), and the app's files."""

    def __init__(self, run, title):
        super().__init__(run, title)
        self.controls = run.path().controls() if run.solved else None
        self.path = Path(run) if run.solved else None

    def write_svg(self, file):
        """The picture ompl_phys_plan --svg writes."""
        self.run.write_svg(str(file), self.title)


def plan(scene, planner="kpiece", seed=1, time_limit=60.0, params=None):
    """Plans scene (a Scene or a scene file's path) with the registered control planner (KPIECE1
    by default), random seed `seed` and `time_limit` seconds; `params` maps planner parameter names
    to values. The GIL is released while planning; Ctrl-C stops the planner and raises
    KeyboardInterrupt."""
    if isinstance(scene, str):
        scene = load_scene(scene)
    run = solved_run(PlanningRun, scene, planner, seed, time_limit, params)
    return PlanResult(run, f"{scene.name} · {planner} · seed {seed}")
