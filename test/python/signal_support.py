"""What the Python modules' tests share: a Ctrl-C sent to a Python program while it works."""
import os
import subprocess
import time


def interrupted(statement, seconds, prelude="pass"):
    """Runs `prelude` and then `statement` in a new interpreter, sends it SIGINT `seconds` after the
    statement starts, and returns its exit status and standard output: 3 and "interrupted\\n" at the
    end when the statement raised KeyboardInterrupt."""
    script = ("import sys\n"
              f"{prelude}\n"
              "print('started', flush=True)\n"
              "try:\n"
              f"    {statement}\n"
              "except KeyboardInterrupt:\n"
              "    print('interrupted', flush=True)\n"
              "    sys.exit(3)\n")
    process = subprocess.Popen([os.environ.get("PYTHON", "/usr/bin/python3"), "-c", script],
                               stdout=subprocess.PIPE, text=True)
    assert process.stdout.readline() == "started\n"
    time.sleep(seconds)
    process.send_signal(subprocess.signal.SIGINT)
    try:
        out, _ = process.communicate(timeout=60)
    finally:
        process.kill()
    return process.returncode, out
