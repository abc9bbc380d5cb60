#!/usr/bin/env python3
"""How often the window's first draw of a new program generates its code
itself, instead of finding it in Mesa's shader cache (a stall of the
window as long as the compile). Run as:
    xvfb-run -a python3 cache_race.py RAYMARCHING SCENE [EDITS] [--busy N]

The scene's folder is copied, the copy opens in a 320x180 window with
Mesa's cache empty, and EDITS (default 12) code edits are saved by rename,
1.5 s apart (after each, the twin is built in the background). --busy N
runs N busy loops beside it, as a loaded machine has (the race is lost
under load: docs/performance-history.md). Prints the window's first draw
of each new program (its 4x4 tile) and the builder's warm-up stage, and
how many first draws took over 20 ms: those compiled in the window.
"""
import argparse
import os
import shutil
import subprocess
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "e2e"))
from harness import save_by_rename, scene_copy, wait_for  # noqa: E402
from reload_examples import FIRST_DRAW, RELOAD  # noqa: E402  the -v lines it reads too

COMPILED_MS = 20  # a first draw that finds the code takes 2 to 12 ms here


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("binary")
    parser.add_argument("scene")
    parser.add_argument("edits", type=int, nargs="?", default=12)
    parser.add_argument("--busy", type=int, default=0)
    args = parser.parse_args()
    work, copy, original, err, env = scene_copy(args.scene, "rm-cache-race-")
    busy = [subprocess.Popen(["sh", "-c", "while :; do :; done"]) for _ in range(args.busy)]
    with open(err, "w") as e:
        window = subprocess.Popen([os.path.abspath(args.binary), copy, "--no-ui", "-v", "--size", "320x180"],
                                  stdout=subprocess.DEVNULL, stderr=e, env=env)
    log = lambda: open(err).read()  # noqa: E731
    firsts = []
    try:
        if not wait_for(lambda: "presented generation 1 " in log(), timeout=60):
            sys.exit("cache_race: the window never drew its first program")
        for i in range(args.edits):
            generation = i + 2
            save_by_rename(copy, original + f"const float rm_cache_race_{i} = {i}.5;\n")
            first = wait_for(lambda: next((m for m in FIRST_DRAW.finditer(log()) if int(m.group(1)) == generation),
                                          None), timeout=60, step=0.02)
            if not first:
                sys.exit(f"cache_race: generation {generation} was never drawn")
            firsts.append(float(first.group(2)))
            time.sleep(1.5)
    finally:
        window.terminate()
        window.wait(timeout=30)
        for b in busy:
            b.kill()
    warms = [float(m.group(6)) for m in RELOAD.finditer(log()) if int(m.group(1)) > 1 and m.group(2) == "rebuilt"]
    print("the window's first draws, ms:", " ".join(f"{ms:.1f}" for ms in sorted(firsts)))
    print("the builder's warm-up, ms:", " ".join(f"{ms:.0f}" for ms in sorted(warms)))
    print(f"compiled in the window (over {COMPILED_MS} ms): {sum(ms > COMPILED_MS for ms in firsts)} of {len(firsts)}")
    shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
