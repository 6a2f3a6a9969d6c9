"""What the Python modules' tests share: records compared without their times."""


def without_times(value):
    """value with every key that starts with "time" and the phases left out, recursively."""
    if isinstance(value, dict):
        return {k: without_times(v) for k, v in value.items() if not k.startswith("time") and k != "phases_s"}
    return value
