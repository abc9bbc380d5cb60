#!/usr/bin/env python3
"""Benchmark behind docs/farm.md: a frame sequence rendered in one run, and in
slices at once by scripts/farm/parallel-render (GNU parallel) on this machine.

  farm_bench.py RAYMARCHING_BINARY SCENE FRAMES SIZE

Prints a markdown table: wall clock (the lowest of 2 runs) and the speed-up
over one run.
"""
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

SCRIPT = Path(__file__).resolve().parents[2] / "scripts" / "farm" / "parallel-render"


def wall(command, env):
    best = 1e30
    for _ in range(2):
        with tempfile.TemporaryDirectory() as tmp:
            start = time.monotonic()
            subprocess.run([part.replace("OUT", tmp) for part in command], check=True, env=env,
                           stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
            best = min(best, time.monotonic() - start)
    return best


def main():
    binary, scene, frames, size = sys.argv[1:5]
    render = [scene, "-o", "OUT/f_%04d.png", "--frames", frames, "--size", size]
    env = dict(os.environ, RAYMARCHING=binary)
    one_thread = dict(env, LP_NUM_THREADS="1")
    runs = [
        ("one run (llvmpipe's 2 threads)", [binary, "render", *render], env),
        ("2 slices at once", [str(SCRIPT), "--slices", "2", "--jobs", "2", *render], env),
        ("2 slices at once, 1 llvmpipe thread each", [str(SCRIPT), "--slices", "2", "--jobs", "2", *render], one_thread),
        ("4 slices, 2 at once", [str(SCRIPT), "--slices", "4", "--jobs", "2", *render], env),
    ]
    print(f"| {Path(scene).stem}, {frames} frames at {size} | s | speed-up |")
    print("|---|---|---|")
    base = None
    for label, command, run_env in runs:
        seconds = wall(command, run_env)
        base = base or seconds
        print(f"| {label} | {seconds:.2f} | {base / seconds:.2f}x |")


if __name__ == "__main__":
    main()
