"""Multi-modal manipulation planning (MOPL) from Python.

    import ompl_mm
    scene = ompl_mm.load_scene("scenes/mobile_blocked.xml")
    result = ompl_mm.plan(scene, seed=3)
    result.path.tool            # numpy array, n x 3

plan() makes the run ompl_mm_plan makes: the same scene, planner, seed and time limit give the
same path and the same record. Bad input raises ompl_core.InputError, naming the file and line.
"""
import json

from ompl_core import InputError
from ._ompl_mm import PlanningRun, Scene, load_scene

__all__ = ["InputError", "Path", "PlanResult", "PlanningRun", "Scene", "load_scene", "plan"]

SEED_RANGE = (1, 2**32 - 1)


class Path:
    """A solution path as numpy arrays: `states` (one row per state), `labels` (per segment: the
    primitive kind and the object it moved, '' for none), `tool` (n x 3, metres) and `objects`
    (object name -> n x 4 array of x, y, z, yaw)."""

    def __init__(self, run, scene):
        self.states = run.states()
        self.labels = run.labels()
        self.tool = run.tool()
        self.objects = {name: run.object_track(i) for i, name in enumerate(scene.objects)}


class PlanResult:
    """What plan() gives: `solved`, `time_s` (the planner's time), `record` (a dict equal to what
    `ompl_mm_plan --json` writes), `path` (a Path, None when not solved), and the app's files."""

    def __init__(self, run, scene, title):
        self.run = run
        self.record = json.loads(run.record_json())
        self.solved = run.solved
        self.time_s = self.record["time_s"]
        self.path = Path(run, scene) if run.solved else None
        self._title = title

    def write_svg(self, file):
        """The picture ompl_mm_plan --svg writes."""
        self.run.write_svg(str(file))

    def write_html(self, file):
        """The 3-D page ompl_mm_plan --html writes."""
        self.run.write_html(str(file), self._title)

    def write_path(self, file):
        """The path file ompl_mm_plan --path writes (only for a solved run)."""
        self.run.write_path(str(file))


def plan(scene, planner="mopl", seed=1, time_limit=60.0, params=None):
    """Plans scene with the registered planner (MOPL by default), random seed `seed` and
    `time_limit` seconds; `params` maps planner parameter names to values. The GIL is released
    while planning; Ctrl-C stops the planner and raises KeyboardInterrupt."""
    if isinstance(scene, str):
        scene = load_scene(scene)
    if not SEED_RANGE[0] <= seed <= SEED_RANGE[1]:
        raise ValueError(f"seed must be in [{SEED_RANGE[0]}, {SEED_RANGE[1]}], got {seed}")
    if not time_limit > 0:
        raise ValueError(f"time_limit must be positive, got {time_limit}")
    texts = {name: str(value) for name, value in (params or {}).items()}
    run = PlanningRun(scene, planner, seed, float(time_limit), texts)
    run.solve()
    return PlanResult(run, scene, f"{scene.name} · {planner} · seed {seed}")
