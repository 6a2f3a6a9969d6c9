"""What the Python modules ompl_mm, ompl_phys and ompl_bench share: the exception for bad input, a
planning run started from plan()'s arguments, and records compared without their times."""
import json

SEED_RANGE = (1, 2**32 - 1)


class InputError(ValueError):
    """Bad input (a scene, URDF or config file, a planner parameter): the message starts with
    "file:line: " when the place is known; `file` and `line` name it (None and 0 when unknown)."""

    def __init__(self, message, file=None, line=0):
        super().__init__(message)
        self.file = file
        self.line = line


def solved_run(make_run, scene, planner, seed, time_limit, params):
    """make_run(scene, planner, seed, time_limit, params) checked, made and solved. Raises
    ValueError for a seed outside SEED_RANGE or a time limit that is not positive."""
    if not SEED_RANGE[0] <= seed <= SEED_RANGE[1]:
        raise ValueError(f"seed must be in [{SEED_RANGE[0]}, {SEED_RANGE[1]}], got {seed}")
    if not time_limit > 0:
        raise ValueError(f"time_limit must be positive, got {time_limit}")
    run = make_run(scene, planner, seed, float(time_limit), dict(params or {}))
    run.solve()
    return run


class RunResult:
    """What both modules' plan() give: `run` (the C++ run), `solved`, `time_s` (the planner's time),
    `record` (a dict equal to what the app's --json writes) and the app's 3-D page and path file."""

    def __init__(self, run, title):
        self.run = run
        self.record = json.loads(run.record_json())
        self.solved = run.solved
        self.time_s = self.record["time_s"]
        self.title = title

    def write_html(self, file):
        """The 3-D page the app's --html writes."""
        self.run.write_html(str(file), self.title)

    def write_path(self, file):
        """The path file the app's --path writes (only for a solved run)."""
        self.run.write_path(str(file))


def without_times(record):
    """A run's record (plan()'s `record`, the apps' --json) without what differs from run to run of
    the same seed: every key starting with "time" and the phases, at any depth. Two runs of the
    same scene, planner and seed have equal records without_times."""
    if isinstance(record, dict):
        return {key: without_times(value) for key, value in record.items()
                if not key.startswith("time") and key != "phases_s"}
    return record
