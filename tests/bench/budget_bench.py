#!/usr/bin/env python3
"""The frame budget measured in the window, side by side with it off.
Run as: xvfb-run -a -s "-screen 0 1920x1080x24" python3 budget_bench.py RAYMARCHING CSV_DIR SCENE...

For each scene, a 1280x720 window (interface hidden, -v) runs with
--target-fps 30 and with --target-fps 0. After a second to settle, 4 s of
pictures are read from the -v log, whose lines carry the CLOCK_MONOTONIC
time each picture was done. Then Space pauses, and the time to the first
full-size picture after the key is the time to a still, and to the 16th
supersample (--refine's default) the time to a refined still; then Space again,
and a second later Esc (as Q, but a project that reads the keyboard does
not take it): the time to the window's hiding (from the -v log) is the
input latency while the picture moves, and the time to the process's exit
follows (the window reads keys between pictures, or between
slices of tiles). Prints a Markdown table; writes
CSV_DIR/budget_trace.csv, the first pictures of the heaviest scene, both ways.
A SCENE may be a Shadertoy JSON export: a list of where each came from
follows the table.
"""
import json
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "e2e"))
from harness import first_frame_window, open_window, wait_for, xdotool  # noqa: E402

BUDGET_MS = 1000.0 / 30.0
PICTURE = re.compile(r"picture (\d+)x(\d+) scale ([0-9.e-]+) in (\d+) tiles?, ([0-9.e-]+) ms, done at (\d+)")
HIDDEN = re.compile(r"window hidden at (\d+)")
REFINED = re.compile(r"sample 16 of 16 in \d+ tiles?, [0-9.e-]+ ms, done at (\d+)")


def pictures(path):
    out = []
    for m in PICTURE.finditer(open(path).read()):
        out.append({"scale": float(m.group(3)), "tiles": int(m.group(4)), "ms": float(m.group(5)),
                    "done": int(m.group(6)) / 1e9, "full": (int(m.group(1)), int(m.group(2))) == (1280, 720)})
    return out


def session(binary, scene, budget_on, work):
    name = os.path.basename(os.path.dirname(scene)) + "/" + os.path.basename(scene) \
        if os.path.basename(scene) == "image.frag" else os.path.basename(scene)
    err = os.path.join(work, "stderr.txt")
    args = [binary, scene, "--size", "1280x720", "--no-ui", "-v", "--target-fps", "30" if budget_on else "0"]
    proc = open_window(args, os.path.join(work, "stdout.txt"), err, os.path.dirname(scene))
    window = first_frame_window(proc, os.path.basename(scene), err, timeout=60)
    if not window:
        return None
    start = time.monotonic()
    time.sleep(5.0)
    # The measured span: the last 4 s.
    span = [p for p in pictures(err) if start + 1.0 <= p["done"] <= start + 5.0]
    paused = time.monotonic()
    xdotool("key", "--window", window, "space")
    still = wait_for(lambda: [p for p in pictures(err) if p["done"] > paused and p["full"]], timeout=60, step=0.01)
    still_s = still[0]["done"] - paused if still else None
    refined = wait_for(lambda: [int(m.group(1)) / 1e9 for m in REFINED.finditer(open(err).read())
                                if int(m.group(1)) / 1e9 > paused], timeout=120, step=0.02)
    refined_s = refined[0] - paused if refined else None
    xdotool("key", "--window", window, "space")  # running again: Q must come through the pictures
    time.sleep(1.0)
    pressed = time.monotonic()
    xdotool("key", "--window", window, "Escape")  # Q would go to a project that reads the keyboard
    try:
        proc.wait(timeout=60)
        quit_s = time.monotonic() - pressed
    except subprocess.TimeoutExpired:
        proc.kill()
        quit_s = None
    hidden = HIDDEN.search(open(err).read())
    hidden_s = int(hidden.group(1)) / 1e9 - pressed if hidden else None
    intervals = [(b["done"] - a["done"]) * 1000 for a, b in zip(span, span[1:])]
    return {"name": name, "intervals": intervals, "scales": [p["scale"] for p in span],
            "pictures": span, "still_s": still_s, "refined_s": refined_s, "quit_s": quit_s, "hidden_s": hidden_s, "trace": pictures(err)[:120]}


def shader_info(scene):
    """The info of a Shadertoy export, in either form the host reads:
    {"Shader": {...}} as the site's API gives it, or the shader itself."""
    doc = json.load(open(scene))
    return doc.get("Shader", doc).get("info", {})


def main():
    binary, csv_dir, scenes = os.path.abspath(sys.argv[1]), sys.argv[2], sys.argv[3:]
    rows, traces = [], {}
    with tempfile.TemporaryDirectory(prefix="rm-budget-") as work:
        for scene in scenes:
            for budget_on in (True, False):
                r = session(binary, os.path.abspath(scene), budget_on, work)
                if not r:
                    print(f"{scene}: no window", file=sys.stderr)
                    continue
                r["budget_on"] = budget_on
                rows.append(r)
                traces[(r["name"], budget_on)] = r["trace"]
                print(f"{r['name']} {'on' if budget_on else 'off'}: {len(r['intervals'])} intervals", file=sys.stderr)

    def ms(s):
        return "—" if s is None else f"{s * 1000:.0f}"

    print("| scene | budget | frames in 4 s | within 33.3 ms | median frame ms | mean scale | Space to a full-size still, ms "
          "| ... to 16 samples, ms | Esc to the window gone / to exit, ms |")
    print("|---|---|---:|---:|---:|---:|---:|---:|---:|")
    for r in rows:
        n = len(r["intervals"])
        within = sum(1 for i in r["intervals"] if i <= BUDGET_MS) / n if n else 0.0
        median = statistics.median(r["intervals"]) if n else float("nan")
        scale = statistics.mean(r["scales"]) if r["scales"] else float("nan")
        print(f"| {r['name']} | {'30 fps' if r['budget_on'] else 'off'} | {n + 1 if n else len(r['pictures'])} | "
              f"{within * 100:.0f}% | {median:.1f} | {scale:.2f} | {ms(r['still_s'])} | {ms(r['refined_s'])} | "
              f"{ms(r['hidden_s'])} / {ms(r['quit_s'])} |")

    # The share of pictures within budget, the budget on, for a chart: a
    # Shadertoy export under its shader's name.
    def label(r):
        scene = next((s for s in scenes if os.path.basename(s) == r["name"] or s.endswith("/" + r["name"])), "")
        if scene.endswith(".json"):
            return shader_info(scene).get("name", r["name"]).replace(",", " ")
        return r["name"]
    with open(os.path.join(csv_dir, "budget_share.csv"), "w") as f:
        f.write("scene,within 33.3 ms,over 33.3 ms\n")
        for r in rows:
            if not r["budget_on"]:
                continue
            n = len(r["intervals"])
            within = 100.0 * sum(1 for i in r["intervals"] if i <= BUDGET_MS) / n if n else 0.0
            f.write(f"{label(r)},{within:.0f},{100 - within:.0f}\n")

    # Shadertoy exports: where each comes from (the site's id, name and author).
    for scene in scenes:
        if scene.endswith(".json"):
            info = shader_info(scene)
            print(f"- {os.path.basename(scene)}: \"{info.get('name', '?')}\" by {info.get('username', '?')}, "
                  f"https://www.shadertoy.com/view/{info.get('id', '?')}")

    # The first pictures, both ways, of the heaviest scene that the budget
    # scales (a feedback project's stay at full size): the scale finding its
    # step. Heaviest by its full-size pictures' draw time, which a scene too
    # heavy for two pictures in the measured span has too.
    scaled = {r["name"] for r in rows if r["budget_on"] and r["scales"] and statistics.mean(r["scales"]) < 1}
    heaviest = max((r for r in rows if not r["budget_on"] and r["name"] in scaled),
                   key=lambda r: statistics.median([p["ms"] for p in r["trace"]] or [0]))
    on, off = traces.get((heaviest["name"], True), []), traces.get((heaviest["name"], False), [])
    with open(os.path.join(csv_dir, "budget_trace.csv"), "w") as f:
        f.write("picture,scale x 100 (budget on),draw ms (budget on),draw ms (budget off)\n")
        for i in range(min(len(on), 60)):
            off_ms = f"{off[i]['ms']:.2f}" if i < len(off) else ""
            f.write(f"{i},{on[i]['scale'] * 100:.1f},{on[i]['ms']:.2f},{off_ms}\n")
    print(f"\n<!-- trace: {heaviest['name']} -->")


if __name__ == "__main__":
    main()
