"""Where the examples find laserwb-cli (for the simulated inputs) and their work folder."""
import atexit
import os
import shutil
import subprocess
import sys
import tempfile

CLI = os.environ.get("LWB_CLI") or shutil.which("laserwb-cli") or "laserwb-cli"


def workdir():
    """The folder given as the first argument; else (and in a notebook, whose kernel is started
    with "-f CONNECTION_FILE") a new temporary one, removed when the interpreter exits."""
    given = sys.argv[1] if len(sys.argv) > 1 and not sys.argv[1].startswith("-") else None
    if given and "ipykernel" not in sys.modules:
        os.makedirs(given, exist_ok=True)
        return given
    d = tempfile.mkdtemp(prefix="laserwb-example-")
    _made.append(d)
    atexit.register(shutil.rmtree, d, ignore_errors=True)
    return d


_made = []


def finish():
    """Removes the temporary folders workdir() made, now (a notebook kernel that is stopped
    rather than left to exit never reaches the interpreter's exit handlers)."""
    while _made:
        shutil.rmtree(_made.pop(), ignore_errors=True)


def simulate(*args):
    """Runs `laserwb-cli simulate ...` (inputs with exact truth)."""
    subprocess.run([CLI, "simulate", *map(str, args), "-q"], check=True)
