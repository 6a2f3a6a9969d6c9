"""Multi-modal manipulation planning (MOPL) from Python.

    import ompl_mm
    scene = ompl_mm.load_scene("scenes/mobile_blocked.xml")
    result = ompl_mm.plan(scene, seed=3)
    result.path.tool            # numpy array, n x 3

plan() makes the run ompl_mm_plan makes: the same scene, planner, seed and time limit give the
same path and the same record. Bad input raises ompl_core.InputError, naming the file and line.
"""
from ompl_core import InputError, RunResult, solved_run
from ._ompl_mm import PlanningRun, Scene, load_scene

__all__ = ["InputError", "Path", "PlanResult", "PlanningRun", "Scene", "load_scene", "plan"]


class Path:
    """A solution path as numpy arrays: `states` (one row per state), `labels` (per segment: the
    primitive kind and the object it moved, '' for none), `tool` (n x 3, metres) and `objects`
    (object name -> n x 4 array of x, y, z, yaw)."""

    def __init__(self, run, scene):
        self.states = run.states()
        self.labels = run.labels()
        self.tool = run.tool()
        self.objects = {name: run.object_track(i) for i, name in enumerate(scene.objects)}


class PlanResult(RunResult):
    """What plan() gives: `solved`, `time_s` (the planner's time), `record` (a dict equal to what
    `ompl_mm_plan --json` writes), `path` (a Path, None when not solved), and the app's files."""

    def __init__(self, run, scene, title):
        super().__init__(run, title)
        self.path = Path(run, scene) if run.solved else None

    def write_svg(self, file):
        """The picture ompl_mm_plan --svg writes."""
        self.run.write_svg(str(file))


def plan(scene, planner="mopl", seed=1, time_limit=60.0, params=None):
    """Plans scene (a Scene or a scene file's path) with the registered planner (MOPL by default),
    random seed `seed` and `time_limit` seconds; `params` maps planner parameter names to values.
    The GIL is released while planning; Ctrl-C stops the planner and raises KeyboardInterrupt."""
    if isinstance(scene, str):
        scene = load_scene(scene)
    run = solved_run(PlanningRun, scene, planner, seed, time_limit, params)
    return PlanResult(run, scene, f"{scene.name} · {planner} · seed {seed}")
