#!/usr/bin/env python3
"""What a scene costs llvmpipe, in instructions executed: a measure that does
not move with the machine's load, for A/B comparisons of shaderlib changes
that wall-clock benchmarks on a shared 2-core machine cannot resolve (their
rounds differ by 10 to 30%).

  instruction_count.py RAYMARCHING_BINARY SCENE... [-- RENDER_OPTION...]

Each scene is drawn once by `render` at 160x90 (time 1.3) under callgrind,
with Mesa's shader cache off and llvmpipe drawing on the calling thread, and
callgrind's instruction counts are split by where they ran:
  draw       the shader's machine code (JIT code: no shared object);
  codegen    libLLVM, llvmpipe's compile of the shader to machine code;
  mesa       the rest of Mesa (its GLSL compiler and NIR, and llvmpipe's own
             set-up and rasterisation).
A project with feedback draws every frame up to that time, as `render`
does. The same binary and scene give the same counts, run after run (the
draw's exactly, LLVM's within 0.3%). Prints a markdown table, millions of
instructions; a scene takes one to two minutes.
"""
import os
import re
import subprocess
import sys
import tempfile
from pathlib import Path

SIZE, TIME = "160x90", "1.3"
ROW = re.compile(r"^\s*([\d,]+) \(\s*[\d.]+%\)\s+.*\[(.*)\]\s*$")


def buckets(annotated):
    counts = {"draw": 0, "codegen": 0, "mesa": 0}
    for line in annotated.splitlines():
        match = ROW.match(line)
        if not match:
            continue
        n, where = int(match.group(1).replace(",", "")), match.group(2)
        if where == "???":
            counts["draw"] += n
        elif "libLLVM" in where:
            counts["codegen"] += n
        elif "_dri.so" in where:
            counts["mesa"] += n
    return counts


def measure(binary, scene, options):
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "callgrind.out"
        env = dict(os.environ, MESA_SHADER_CACHE_DISABLE="true", LP_NUM_THREADS="0")
        subprocess.run(["valgrind", "--tool=callgrind", f"--callgrind-out-file={out}", binary, "render", scene,
                        "--size", SIZE, "--time", TIME, "-o", str(Path(tmp) / "picture.png"), *options],
                       check=True, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        annotated = subprocess.run(["callgrind_annotate", "--inclusive=no", "--threshold=100", str(out)], check=True,
                                   capture_output=True, text=True).stdout
    return buckets(annotated)


def label(scene):
    """A project by its folder (paint/image.frag), a single scene by its file."""
    path = Path(scene)
    return f"{path.parent.name}/{path.name}" if path.name == "image.frag" else path.name


def main():
    args = sys.argv[1:]
    options = args[args.index("--") + 1:] if "--" in args else []
    args = args[:args.index("--")] if "--" in args else args
    if len(args) < 2:
        sys.exit(__doc__)
    binary, scenes = args[0], args[1:]
    print(f"| scene | draw at {SIZE}, M | per pixel | codegen, M | mesa, M |")
    print("|---|---:|---:|---:|---:|")
    width, height = (int(n) for n in SIZE.split("x"))
    pixels = width * height
    for scene in scenes:
        c = measure(binary, scene, options)
        print(f"| {label(scene)} | {c['draw'] / 1e6:.1f} | {c['draw'] / pixels:.0f} | {c['codegen'] / 1e6:.0f} | "
              f"{c['mesa'] / 1e6:.0f} |", flush=True)


if __name__ == "__main__":
    main()
