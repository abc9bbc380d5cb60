#!/usr/bin/env python3
"""A project's first load: how long its passes take to build, and what
building them side by side saves.
Run as: xvfb-run -a python3 first_load.py RAYMARCHING CSV_PATH PROJECT...

Each PROJECT (an example project's image.frag, or a Shadertoy JSON) opens
in an 800x450 window (the default size; interface hidden, -v) with Mesa's
shader cache empty (MESA_SHADER_CACHE_DIR), as for a person opening it the
first time, RUNS times. A JSON with one pass (Common aside) is skipped:
there is nothing to build side by side. From the -v log (CLOCK_MONOTONIC
times), per run: the passes built and on how many threads; the build, from
its start to its swap; its stages (preprocess and glslang, one pass after
another; the driver's compile and link and the warm-up draw, summed over the
threads that ran them); and the time from spawning the process to the first
whole picture. Prints a Markdown table of medians, then a line for each
Shadertoy JSON measured that says where it comes from, and writes CSV_PATH: for
each project a bar of its stages summed and a bar of the build's wall
clock, which is shorter where two threads built.
"""
import json
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "e2e"))
from harness import wait_for  # noqa: E402
from reload_examples import FIRST_DRAW, PICTURE, PRESENTED  # noqa: E402  the -v lines it reads too

RUNS = 3
BUILDING = re.compile(r"building generation 1 at (\d+)")
BUILT = re.compile(r"reload ok generation 1 \(rebuilt:([^;]*); preprocess ([0-9.e-]+) ms, glslang ([0-9.e-]+) ms, "
                   r"driver compile\+link ([0-9.e-]+) ms, warm-up ([0-9.e-]+) ms"
                   r"(?:, the last two summed over (\d+) threads)?(?:; built in [0-9.e-]+ ms)?\) at (\d+)")


def shader_of(path):
    """A Shadertoy export, in either form the host reads: {"Shader": {...}}
    as the site's API gives it, or the shader itself."""
    with open(path) as f:
        doc = json.load(f)
    return doc.get("Shader", doc)


def passes_of_json(path):
    """How many passes a Shadertoy JSON draws (Common is none)."""
    return sum(1 for p in shader_of(path).get("renderpass", []) if p.get("type") != "common")


def first_load(binary, project, work):
    """The stages of one first load, or None where it never drew."""
    cache = tempfile.mkdtemp(prefix="mesa-cache-", dir=work)
    err = os.path.join(work, "stderr.txt")
    env = dict(os.environ, MESA_SHADER_CACHE_DIR=cache)
    with open(err, "w") as e, open(os.devnull, "w") as out:
        spawned = time.monotonic()
        proc = subprocess.Popen([binary, project, "--no-ui", "-v"], stdout=out, stderr=e,
                                cwd=os.path.dirname(project), env=env)

    def stages():
        text = open(err).read()
        building, built = BUILDING.search(text), BUILT.search(text)
        present = next((m for m in PRESENTED.finditer(text) if m.group(1) == "1"), None)
        first = next((m for m in FIRST_DRAW.finditer(text) if m.group(1) == "1"), None)
        done = PICTURE.search(text, first.end()) if first else None
        if not (building and built and present and done):
            return None
        whole = max(int(done.group(1)), int(present.group(2))) / 1e9
        return {"passes": len(built.group(1).split()), "threads": int(built.group(6) or 1),
                "build": (int(built.group(7)) - int(building.group(1))) / 1e6,
                "preprocess": float(built.group(2)), "glslang": float(built.group(3)),
                "driver": float(built.group(4)), "warm": float(built.group(5)),
                "picture": (whole - spawned) * 1000}

    try:
        return wait_for(stages, timeout=120, step=0.02)
    finally:
        proc.terminate()
        proc.wait(timeout=30)
        shutil.rmtree(cache, ignore_errors=True)


def name_of(project):
    if project.endswith(".json"):
        return os.path.basename(project)
    return os.path.basename(os.path.dirname(project)) + "/" + os.path.basename(project)


def main():
    binary, csv_path, projects = os.path.abspath(sys.argv[1]), sys.argv[2], sys.argv[3:]
    work = tempfile.mkdtemp(prefix="rm-first-load-")
    sources = []  # where each public project measured comes from
    print("| project | passes built | threads | the build, ms | preprocess + glslang | driver compile+link, summed | "
          "warm-up draw, summed | the stages summed, ms | spawn to the first whole picture, ms |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|")
    with open(csv_path, "w") as csv:
        csv.write("run,preprocess + glslang,driver compile+link,warm-up draw,the build: start to swap\n")
        for project in map(os.path.abspath, projects):
            name = name_of(project)
            if project.endswith(".json") and passes_of_json(project) < 2:
                print(f"{name}: one pass; skipped", file=sys.stderr)
                continue
            runs = [r for r in (first_load(binary, project, work) for _ in range(RUNS)) if r]
            if len(runs) < RUNS:
                print(f"{name}: {RUNS - len(runs)} of {RUNS} first loads never drew", file=sys.stderr)
            if not runs:
                continue
            med = {k: statistics.median(r[k] for r in runs) for k in runs[0]}
            front = med["preprocess"] + med["glslang"]
            summed = front + med["driver"] + med["warm"]
            threads = "/".join(sorted({str(r["threads"]) for r in runs}))
            print(f"| {name} | {med['passes']:.0f} | {threads} | {med['build']:.0f} | {front:.1f} | "
                  f"{med['driver']:.1f} | {med['warm']:.1f} | {summed:.0f} | {med['picture']:.0f} |")
            csv.write(f"{name}: stages summed,{front:.1f},{med['driver']:.1f},{med['warm']:.1f},\n")
            csv.write(f"{name}: the build,,,,{med['build']:.1f}\n")
            if project.endswith(".json"):
                info = shader_of(project).get("info", {})
                sources.append(f"- {name}: \"{info.get('name', '?')}\" by {info.get('username', '?')}, "
                               f"https://www.shadertoy.com/view/{info.get('id', '?')}")
            print(f"{name}: done", file=sys.stderr)
    for line in sources:
        print(line)
    shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
