"""Where the examples find laserwb-cli (for the simulated inputs) and their work folder."""
import os
import shutil
import subprocess
import sys
import tempfile

CLI = os.environ.get("LWB_CLI") or shutil.which("laserwb-cli") or "laserwb-cli"


def workdir():
    """The folder given as the first argument, else a new temporary one."""
    d = sys.argv[1] if len(sys.argv) > 1 else tempfile.mkdtemp(prefix="laserwb-example-")
    os.makedirs(d, exist_ok=True)
    return d


def simulate(*args):
    """Runs `laserwb-cli simulate ...` (inputs with exact truth)."""
    subprocess.run([CLI, "simulate", *map(str, args), "-q"], check=True)
