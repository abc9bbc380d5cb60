"""Shared by the scripts that render pictures into the repository."""
import shutil
import subprocess
from pathlib import Path


def keep_unless_changed(fresh, target):
    """Moves `fresh` onto `target` unless their pixels are the same (within one
    8-bit step). The files differ in metadata (the render time) every time,
    and git should show only pictures that really changed."""
    same = Path(target).exists() and subprocess.run(["idiff", "-fail", "0.005", str(fresh), str(target)],
                                                      capture_output=True).returncode == 0
    if same:
        Path(fresh).unlink()
    else:
        shutil.move(str(fresh), str(target))
