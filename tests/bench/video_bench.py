#!/usr/bin/env python3
"""Benchmark behind docs/performance.md's video section: what writing the
frames costs, as a PNG sequence and as each video container (ffmpeg fed on a
pipe), for a cheap scene and a marched one at 1280x720.

  video_bench.py RAYMARCHING_BINARY SCENE...

The cost of a frame is the wall clock of `render --frames 61` less that of
`--frames 1`, over 60: start-up and the first frame's compile drop out.
Each is the lowest of 3 runs. Prints a markdown table.
"""
import subprocess
import sys
import tempfile
import time
from pathlib import Path

FRAMES = 60
SIZE = "1280x720"
OUTPUTS = [("PNG sequence", "frame_%04d.png"), ("H.264 .mp4", "out.mp4"), ("VP9 .webm", "out.webm"),
           ("GIF", "out.gif")]


def wall(binary, scene, out, frames):
    best = 1e30
    for _ in range(3):
        with tempfile.TemporaryDirectory() as tmp:
            start = time.monotonic()
            subprocess.run([binary, "render", scene, "-o", str(Path(tmp) / out), "--frames", str(frames), "--size", SIZE],
                           check=True, stderr=subprocess.DEVNULL)
            best = min(best, time.monotonic() - start)
    return best


def main():
    binary, scenes = sys.argv[1], sys.argv[2:]
    print(f"| scene | {' | '.join(label + ' ms/frame' for label, _ in OUTPUTS)} |")
    print("|---|" + "---|" * len(OUTPUTS))
    for scene in scenes:
        cells = []
        png = None
        for label, out in OUTPUTS:
            per_frame = (wall(binary, scene, out, FRAMES + 1) - wall(binary, scene, out, 1)) * 1000.0 / FRAMES
            png = per_frame if png is None else png
            cells.append(f"{per_frame:.1f}" + ("" if out.endswith(".png") else f" ({per_frame - png:+.1f})"))
        print(f"| {Path(scene).stem} | {' | '.join(cells)} |")


if __name__ == "__main__":
    main()
