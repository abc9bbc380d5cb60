#!/usr/bin/env python3
"""Reload latency of every example, as a person editing it sees it.
Run as: xvfb-run -a python3 reload_examples.py RAYMARCHING CSV_PATH SCENE...

Each scene's folder is copied to a temporary one, and the copy opens in an
800x450 window (the default size; interface hidden, -v). Then edits are
saved by rename, as editors save:
- five number edits, each appending a digit to the scene's last decimal
  number (1.0 becomes 1.0001, then 1.0002: the same picture), shown by the
  scene's twin (core/tweak.h) when that number is one it reads;
- five code edits, each appending a new line of code (a global const): a
  compile from scratch;
- three saves back to a text saved before (Mesa's cache and the scene's).
Between saves it waits for the background builds (the twins, a tweak's
exact program) to end, as a person pausing to look lets them. A scene
with no number of its own (default.frag, an #include of tori.frag) is
skipped. Mesa's shader cache starts empty for each scene
(MESA_SHADER_CACHE_DIR), so a fresh edit is compiled from scratch, as a
real one is. Per save, from the -v log (CLOCK_MONOTONIC times): the first
present of the new program (its first tiles) and its first whole picture;
for the code edits, where the time went: preprocess, glslang, the driver's
compile and link, the warm-up draw (on the builder's thread, with those
three: llvmpipe generates the machine code in it), the window's own first
draw (which loads that code from the cache: the only stage the window
waits for).
Prints a Markdown table of medians; writes the code edits' stages as
CSV_PATH, and each scene's number edit and code edit (save to whole
picture) as edits.csv beside it.
"""
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "e2e"))
from harness import save_by_rename, wait_for  # noqa: E402

FRESH, BACK = 5, 3
RELOAD = re.compile(r"reload ok generation (\d+) \((rebuilt|tweaked):[^;]*; preprocess ([0-9.e-]+) ms, glslang ([0-9.e-]+) ms, "
                    r"driver compile\+link ([0-9.e-]+) ms, warm-up ([0-9.e-]+) ms[,;)]")
LAST_NUMBER = re.compile(r"\b(\d+\.\d+)(?!.*\b\d+\.\d+)", re.S)
FIRST_DRAW = re.compile(r"first draw of generation (\d+): a \d+x\d+ tile, ([0-9.e-]+) ms")
PRESENTED = re.compile(r"presented generation (\d+) at (\d+)")
PICTURE = re.compile(r"picture \d+x\d+ scale [0-9.e-]+ in \d+ tiles?, [0-9.e-]+ ms, done at (\d+)")


def log(path):
    return open(path).read()


def reload_of(err, generation, saved):
    """The stages of the reload to `generation`, once its whole picture is done."""
    text = log(err)
    reload = next((m for m in RELOAD.finditer(text) if int(m.group(1)) == generation), None)
    present = next((m for m in PRESENTED.finditer(text) if int(m.group(1)) == generation), None)
    if not reload or not present:
        return None
    # The new program's first picture: the first one done after its first
    # draw (one of the old program's may finish after the build). It is on
    # screen at the present that follows it, which -v logs only for a
    # generation's first: so the later of the two. (This searched from the
    # first present on, and took the picture after a first picture drawn in
    # one turn: a frame too late, 15-20 ms.)
    first = next((m for m in FIRST_DRAW.finditer(text) if int(m.group(1)) == generation), None) or reload
    done = next((int(m.group(1)) / 1e9 for m in PICTURE.finditer(text, first.end())), None)
    if done is None:
        return None
    whole = max(done, int(present.group(2)) / 1e9)
    draw = float(first.group(2)) if first is not reload else 0.0
    return {"present": int(present.group(2)) / 1e9 - saved, "whole": whole - saved,
            "tweaked": reload.group(2) == "tweaked",
            "preprocess": float(reload.group(3)), "glslang": float(reload.group(4)),
            "driver": float(reload.group(5)), "warm": float(reload.group(6)), "draw": draw}


def latest_generation(err):
    return max([1] + [int(g) for g in re.findall(r"reload ok generation (\d+)", log(err))])


def settled(err):
    """Whether the builds that follow the latest swap in the background are
    over: the window has looked at its twins (after a tweak, the exact
    program's swap comes first)."""
    return re.search(rf"(twins built|no new twins) for generation {latest_generation(err)} ", log(err)) is not None


def session(binary, scene, work):
    """Times of each fresh save and of each save back to an older text."""
    folder = os.path.join(work, os.path.basename(os.path.dirname(scene)) + "-copy")
    shutil.rmtree(folder, ignore_errors=True)
    shutil.copytree(os.path.dirname(scene), folder, symlinks=True)
    copy = os.path.join(folder, os.path.basename(scene))
    original = log(copy)
    if not LAST_NUMBER.search(original):  # default.frag: only an #include of tori.frag
        print(f"{scene}: no number to edit; skipped", file=sys.stderr)
        return None
    err = os.path.join(work, "stderr.txt")
    env = dict(os.environ, MESA_SHADER_CACHE_DIR=os.path.join(folder, ".mesa-cache"))
    with open(err, "w") as e, open(os.devnull, "w") as out:
        proc = subprocess.Popen([binary, copy, "--no-ui", "-v"], stdout=out, stderr=e, cwd=folder, env=env)
    try:
        if not wait_for(lambda: "presented generation 1 " in log(err), timeout=60):
            return None
        numbers, code, back, texts = [], [], [], []
        for i in range(2 * FRESH + BACK):
            if not wait_for(lambda: settled(err), timeout=60):
                print(f"{scene}: the background builds never ended", file=sys.stderr)
                return None
            time.sleep(0.3)
            if i < FRESH:
                text, into = LAST_NUMBER.sub(lambda m: f"{m.group(1)}{i + 1:03d}", original), numbers
            elif i < 2 * FRESH:
                text, into = original + f"const float rm_bench_edit_{i} = {i}.5;\n", code
                texts.append(text)
            else:  # back to a text the window has built before (its cache)
                text, into = (texts[-2] if (i - 2 * FRESH) % 2 == 0 else texts[-1]), back
            generation = latest_generation(err) + 1
            saved = time.monotonic()
            save_by_rename(copy, text)
            times = wait_for(lambda: reload_of(err, generation, saved), timeout=60, step=0.01)
            if not times:
                print(f"{scene}: save {i + 1} never drew", file=sys.stderr)
                return None
            into.append(times)
        return numbers, code, back
    finally:
        proc.terminate()
        proc.wait(timeout=30)


def main():
    binary, csv_path, scenes = os.path.abspath(sys.argv[1]), sys.argv[2], sys.argv[3:]
    work = tempfile.mkdtemp(prefix="rm-reload-")
    print("| scene | a number edit: save to whole picture, ms | tweaked | "
          "a code edit: save to first present, ms | save to whole picture, ms | preprocess | glslang | "
          "driver compile+link | warm-up draw | the window's first draw (its first tile) | "
          "a text built before: save to whole picture, ms |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    edits_path = os.path.join(os.path.dirname(os.path.abspath(csv_path)), "edits.csv")
    with open(csv_path, "w") as csv, open(edits_path, "w") as edits:
        edits.write("edit,save to whole picture\n")
        csv.write("scene,preprocess,glslang,driver compile+link,warm-up draw,the window's first draw,"
                  "the rest: watcher + tiles + present\n")
        for scene in scenes:
            name = os.path.basename(os.path.dirname(scene)) + "/" + os.path.basename(scene) \
                if os.path.basename(scene) == "image.frag" else os.path.basename(scene)
            result = session(binary, os.path.abspath(scene), work)
            if not result:
                continue
            numbers, fresh, back = result
            med = {k: statistics.median(t[k] for t in fresh) for k in fresh[0]}
            back_whole = statistics.median(t["whole"] for t in back)
            number_whole = statistics.median(t["whole"] for t in numbers)
            tweaked = sum(t["tweaked"] for t in numbers)
            print(f"| {name} | {number_whole * 1000:.0f} | {tweaked} of {len(numbers)} | {med['present'] * 1000:.0f} | {med['whole'] * 1000:.0f} | {med['preprocess']:.1f} | "
                  f"{med['glslang']:.1f} | {med['driver']:.1f} | {med['warm']:.1f} | {med['draw']:.1f} | "
                  f"{back_whole * 1000:.0f} |")
            edits.write(f"{name}: number,{number_whole * 1000:.0f}\n{name}: code,{med['whole'] * 1000:.0f}\n")
            stages = med["preprocess"] + med["glslang"] + med["driver"] + med["warm"] + med["draw"]
            csv.write(f"{name},{med['preprocess']:.1f},{med['glslang']:.1f},{med['driver']:.1f},{med['warm']:.1f},"
                      f"{med['draw']:.1f},"
                      f"{max(0.0, med['whole'] * 1000 - stages):.1f}\n")
            print(f"{name}: done", file=sys.stderr)
    shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
