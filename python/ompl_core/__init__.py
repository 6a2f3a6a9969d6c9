"""What the Python modules ompl_mm and ompl_phys share: the exception for bad input."""


class InputError(ValueError):
    """Bad input (a scene, URDF or config file, a planner parameter): the message starts with
    "file:line: " when the place is known; `file` and `line` name it (None and 0 when unknown)."""

    def __init__(self, message, file=None, line=0):
        super().__init__(message)
        self.file = file
        self.line = line
