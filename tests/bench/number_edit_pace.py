#!/usr/bin/env python3
"""Number edits saved at a person's pace: each one PAUSE seconds after the
last is on screen, as someone nudging a value and looking does. Run as:
    xvfb-run -a python3 number_edit_pace.py RAYMARCHING SCENE [EDITS] [--pause S] [--code]

The scene's folder is copied, and the copy opens in an 800x450 window (the
default size) with Mesa's cache empty. After its twin is built, EDITS
(default 8) number edits are saved by rename, each appending a digit to
the scene's last decimal number (reload_examples.py's number edit), PAUSE
(default 1.2) seconds after the last one was presented. A second after
each tweak is shown, the window builds its exact program in the
background, which takes as long as a compile: at this pace the next save
comes during that build. --code: code edits instead (reload_examples.py's
fresh edit, a new declaration each time), which need a compile; the twins
of each new program are built a second after it is shown, in the
background too. Prints each save's time to its first present and their
median.
"""
import argparse
import os
import re
import statistics
import subprocess
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "e2e"))
from harness import save_by_rename, scene_copy, wait_for  # noqa: E402
from reload_examples import LAST_NUMBER  # noqa: E402  the same number edit

TWEAKED = re.compile(r"reload ok generation (\d+) \(tweaked:[^\n]* at (\d+)")
REBUILT = re.compile(r"reload ok generation (\d+) \(rebuilt:[^\n]* at (\d+)")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("binary")
    parser.add_argument("scene")
    parser.add_argument("edits", type=int, nargs="?", default=8)
    parser.add_argument("--pause", type=float, default=1.2)
    parser.add_argument("--code", action="store_true", help="code edits, which need a compile")
    args = parser.parse_args()
    work, copy, original, err, env = scene_copy(args.scene, "rm-number-pace-")
    with open(err, "w") as e:
        proc = subprocess.Popen([os.path.abspath(args.binary), copy, "--no-ui", "-v"], stdout=subprocess.DEVNULL, stderr=e,
                                cwd=os.path.dirname(copy), env=env)
    log = lambda: open(err).read()  # noqa: E731
    times = []
    try:
        if not wait_for(lambda: "twins built for generation 1 " in log(), timeout=120):
            sys.exit(f"number_edit_pace: no twin for {args.scene}; see {err}")
        for i in range(args.edits):
            time.sleep(args.pause)
            saved = time.monotonic_ns()  # the clock of the -v log's stamps
            if args.code:
                save_by_rename(copy, original + f"const float rm_bench_edit_{i} = {i}.5;\n")
            else:
                save_by_rename(copy, LAST_NUMBER.sub(lambda m: f"{m.group(1)}{i + 1:03d}", original))
            # Its tweak's (or program's) first present, not the exact program
            # of the last tweak, which the window may show before it.
            kind = REBUILT if args.code else TWEAKED
            tweak = wait_for(lambda: next((g for g, t in kind.findall(log()) if int(t) > saved), None), timeout=60)
            shown = tweak and wait_for(lambda: re.search(rf"presented generation {tweak} at (\d+)", log()), timeout=60)
            if not shown:
                sys.exit(f"number_edit_pace: save {i + 1} never shown; see {err}")
            times.append((int(shown.group(1)) - saved) / 1e6)
    finally:
        proc.terminate()
        proc.wait(timeout=30)
    print(f"{os.path.basename(args.scene)}: save to first present, ms: " + " ".join(f"{t:.0f}" for t in times) +
          f"; median {statistics.median(times):.0f}")


if __name__ == "__main__":
    main()
