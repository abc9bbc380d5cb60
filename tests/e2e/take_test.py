#!/usr/bin/env python3
"""Takes end to end: recorded in a real window under Xvfb, driven by
xdotool, and replayed by `render --take`.
Run as: xvfb-run -a python3 take_test.py RAYMARCHING

A project that reads the clock, the mouse and the keyboard is recorded with
F9: a left drag across the picture, the A key held in the middle of it, and
an F12 shot while both are down; F9 again writes the take. Checks: the take
has the drag and the key; two replays of it give identical frames, and
identical videos; the frame the shot names (raymarching:take_frame) matches
the shot; a replay at another rate and size has the frames that rate asks
for; a take whose source changed since renders with one warning naming it;
a take does not load the image module; SIGTERM while a take records closes
the window with the take written, and so does the X server going away; the
X server going away while the window opens is one line too.
"""
import filecmp
import glob
import json
import math
import os
import re
import shutil
import subprocess
import sys
import time

import harness
from harness import (check, first_frame_window, mean_colour, metadata, open_window, pixels_over, save_by_rename, summary,
                     take_screenshot, wait_for, xdotool)

BINARY = os.path.abspath(sys.argv[1])

# Moves with the clock, shows where the mouse is held and whether A is down.
# The window runs it with -U DARK, which the take must carry to the replay.
SCENE = """// take: clock, drag and key
#pragma channel0 keyboard
#define DARK
void mainImage(out vec4 c, in vec2 f) {
  vec2 uv = f / iResolution.xy;
  float held = iMouse.z > 0.0 ? 1.0 : 0.3;
  float spot = smoothstep(24.0, 0.0, length(f - iMouse.xy)) * held;
  float a = texelFetch(iChannel0, ivec2(65, 0), 0).x;
  c = vec4(0.5 + 0.5 * sin(iTime * 3.0 + uv.x * 6.0), spot, a * uv.y, 1.0);
#ifdef DARK
  c.rgb *= 0.25;
#endif
}
"""


def render(*args):
    return subprocess.run([BINARY, "render", *args], capture_output=True, text=True, timeout=300)


def main():
    work = harness.work_dir("rm-take-")
    scene = os.path.join(work, "take.frag")
    with open(scene, "w") as f:
        f.write(SCENE)
    out, err = os.path.join(work, "stdout.txt"), os.path.join(work, "stderr.txt")
    proc = open_window([BINARY, scene, "--size", "320x180", "--no-ui", "-v", "-U", "DARK"], out, err, work)
    window = first_frame_window(proc, "take.frag", err)
    check("the window opens", window is not None)
    if not window:
        return summary()

    def said(pattern):
        return re.findall(pattern, open(out).read(), re.M)

    xdotool("key", "--window", window, "F9")
    check("F9 starts a take", wait_for(lambda: said(r"^take: recording$"), timeout=10) is not None)
    xdotool("mousemove", "--window", window, 60, 90)
    time.sleep(0.3)
    xdotool("mousedown", "--window", window, 1)
    for x in range(70, 181, 10):
        xdotool("mousemove", "--window", window, x, 90)
        time.sleep(0.05)
    xdotool("keydown", "--window", window, "a")
    time.sleep(0.3)
    shot = take_screenshot(window, out)
    check("F12 takes a shot while the take records", shot is not None)
    xdotool("keyup", "--window", window, "a")
    for x in range(190, 261, 10):
        xdotool("mousemove", "--window", window, x, 100)
        time.sleep(0.05)
    xdotool("mouseup", "--window", window, 1)
    time.sleep(0.3)
    xdotool("key", "--window", window, "F9")
    written = wait_for(lambda: said(r"^take: (.*) \((\d+) frames\)$"), timeout=10)
    check("F9 again writes the take beside the scene", written is not None and
          os.path.dirname(written[0][0]) == work and written[0][0].endswith(".take.json"), str(written))
    xdotool("key", "--window", window, "Escape")
    try:
        proc.wait(timeout=30)
    except subprocess.TimeoutExpired:
        proc.kill()
    if not written or not shot:
        return summary()
    take_path, frames = written[0][0], int(written[0][1])
    shot = os.path.join(work, shot)  # named as the window's working directory sees it

    take = json.load(open(take_path))
    lines = take["frames"]
    check("the take holds every frame it says", len(lines) == frames and frames > 5, f"{len(lines)} vs {frames}")
    held = [l["m"] for l in lines if "m" in l and l["m"][2] > 0]
    check("the take has the drag", len(held) >= 3 and held[-1][0] > held[0][0] + 50, str(held[:2] + held[-2:]))
    keys = [k for l in lines for k in l.get("k", [])]
    check("the take has A down and up", [65, 1] in keys and [65, 0] in keys, str(keys))
    check("the take names its scene and sources", take["scene"] == "take.frag" and
          "take.frag" in take["events"][0]["hashes"], str(take["events"]))
    check("the take records the window's -U", take.get("undefines") == ["DARK"], str(take.get("undefines")))

    # Two replays, frame by frame as recorded: the same files.
    runs = []
    for name in ("one", "two"):
        os.mkdir(os.path.join(work, name))
        r = render("--take", take_path, "-o", os.path.join(work, name, "f_%04d.png"))
        check(f"replay {name} renders", r.returncode == 0, r.stderr)
        runs.append(sorted(glob.glob(os.path.join(work, name, "f_*.png"))))
    check("a replay has one frame per recorded frame", len(runs[0]) == frames, f"{len(runs[0])} vs {frames}")
    check("two replays give identical frames", len(runs[0]) == len(runs[1]) and
          all(filecmp.cmp(a, b, shallow=False) for a, b in zip(*runs)))

    # The shot's frame of the take, drawn again: the same picture.
    k = metadata(shot).get("raymarching:take_frame")
    check("the shot names its frame of the take", k is not None and 0 <= int(k) < frames, str(metadata(shot)))
    if k is not None and int(k) < len(runs[0]):
        replayed = runs[0][int(k)]
        check("frame K of the replay matches the shot taken at frame K",
              pixels_over(shot, replayed, 1.5 / 255, work) == 0, f"{shot} vs {replayed}")
        # The match means something: the shot shows A down (blue) and the button held (a bright spot).
        colour, _ = mean_colour(shot)
        mouse = metadata(replayed).get("raymarching:iMouse", "")
        check("the shot shows the key down and the drag", colour is not None and colour[2] > 0.05 and
              float(mouse.split(",")[2]) > 0, f"{colour} {mouse}")

    if shutil.which("ffmpeg"):
        videos = []
        for name in ("one.mp4", "two.mp4"):
            path = os.path.join(work, name)
            r = render("--take", take_path, "-o", path, "--fps", "30", "--size", "160x90")
            check(f"a video of the take at 30 fps ({name})", r.returncode == 0, r.stderr)
            videos.append(path)
        check("two video replays are identical files", all(map(os.path.exists, videos)) and
              filecmp.cmp(*videos, shallow=False))

    # At another rate: as many frames as the take's span asks for, the last at its end or just past it.
    span = lines[-1]["w"]
    os.mkdir(os.path.join(work, "rate"))
    r = render("--take", take_path, "-o", os.path.join(work, "rate", "f_%04d.png"), "--fps", "10", "--size", "80x45")
    resampled = glob.glob(os.path.join(work, "rate", "f_*.png"))
    check("--fps resamples the take", r.returncode == 0 and len(resampled) == math.ceil(span * 10 - 1e-9) + 1,
          f"{len(resampled)} frames for {span} s; {r.stderr}")

    # The scene saved since: still renders, with one warning that names it.
    save_by_rename(scene, SCENE.replace("* 3.0", "* 2.0"))
    os.mkdir(os.path.join(work, "changed"))
    r = render("--take", take_path, "-o", os.path.join(work, "changed", "f_%04d.png"), "--fps", "5")
    warnings = [l for l in r.stderr.splitlines() if "warning" in l]
    check("a take of a changed scene renders with one warning naming the file",
          r.returncode == 0 and len(warnings) == 1 and "take.frag" in warnings[0], r.stderr)
    killed_while_recording(work, scene)
    display_lost_while_recording(work, scene)
    display_lost_while_opening(scene)
    return summary()


def ended_with_take(proc, out, work, recording, name):
    """Waits for the window to end, and checks (as `name`) that it wrote the
    take it was `recording`. Its exit status; None if it had to be killed."""
    try:
        status = proc.wait(timeout=30)
    except subprocess.TimeoutExpired:
        proc.kill()
        status = None
    written = re.findall(r"^take: (.*) \((\d+) frames\)$", open(out).read(), re.M)
    check(name, recording and written and os.path.exists(os.path.join(work, written[0][0])) and
          int(written[0][1]) > 0, open(out).read())
    return status


def killed_while_recording(work, scene):
    """SIGTERM (a kill; Ctrl-C's SIGINT alike) closes the window as Q does:
    the take being recorded is written, and the exit status says which
    signal (128 + 15)."""
    out, err = os.path.join(work, "kill-stdout.txt"), os.path.join(work, "kill-stderr.txt")
    proc = open_window([BINARY, scene, "--size", "160x90", "--no-ui", "-v"], out, err, work)
    window = first_frame_window(proc, "take.frag", err)
    check("a second window opens", window is not None)
    if not window:
        return
    xdotool("key", "--window", window, "F9")
    recording = wait_for(lambda: "take: recording" in open(out).read(), timeout=10)
    time.sleep(0.5)
    # A take reads and writes no picture: it must not load the image module,
    # which held the window for about 0.5 s while it loaded.
    maps = open(f"/proc/{proc.pid}/maps").read() if proc.poll() is None else ""
    check("a take does not load the image module (OpenImageIO)", recording and maps and
          "raymarching-images" not in maps and "libOpenImageIO" not in maps,
          [line.split()[-1] for line in maps.splitlines() if "OpenImageIO" in line or "raymarching-images" in line][:3])
    proc.terminate()
    status = ended_with_take(proc, out, work, recording, "SIGTERM while a take records writes the take")
    check("... and ends with status 143 and one line that names the signal",
          status == 143 and "raymarching: the window was closed by SIGTERM\n" in open(err).read(),
          f"status {status}: {open(err).read()[-300:]}")


def own_x_server(work):
    """An Xvfb of the test's own, which it may end, once it answers (a window
    opened before failed to open the display, once in a whole ctest run):
    the process, its display, an environment that names it, whether it
    answered, and its log."""
    read_end, write_end = os.pipe()
    xvfb_log = os.path.join(work, "own-xvfb.txt")
    xvfb = subprocess.Popen(["Xvfb", "-displayfd", str(write_end), "-screen", "0", "640x480x24", "-nolisten", "tcp"],
                            pass_fds=(write_end,), stderr=open(xvfb_log, "w"))
    os.close(write_end)
    display = ":" + os.read(read_end, 16).decode().strip()
    os.close(read_end)
    env = dict(os.environ, DISPLAY=display)
    answers = wait_for(lambda: xdotool("getdisplaygeometry", env=env), timeout=10)
    return xvfb, display, env, bool(answers), xvfb_log


def display_lost_while_opening(scene):
    """The X server ending while the window opens, before anything is
    recorded: in GLFW's init Xlib ended the process with status 1 ("XIO:
    fatal IO error"), and while GLFW made the window's context Mesa's GLX
    crashed on a reply it did not check (SIGSEGV, in 2 of 11 tries between
    0.14 and 0.26 s after the start here). At every moment tried, the window
    must end with status 2 and one line."""
    wrong = []
    for delay in [0.05 * i for i in range(1, 17)]:
        xvfb, display, env, answers, _ = own_x_server(os.path.dirname(scene))
        err = os.path.join(os.path.dirname(scene), "opening-stderr.txt")
        proc = subprocess.Popen([BINARY, scene, "--size", "160x90", "--no-ui"], stdout=subprocess.DEVNULL,
                                stderr=open(err, "w"), env=env)
        time.sleep(delay)
        xvfb.kill()
        xvfb.wait()
        try:
            status = proc.wait(timeout=30)
        except subprocess.TimeoutExpired:
            proc.kill()
            status = "none (killed after 30 s)"
        said = open(err).read()
        if not (status == 2 and said.count("\n") == 1 and
                (f"lost the X display {display} " in said or "cannot open a window" in said)):
            wrong.append(f"after {delay:.2f} s (answered: {answers}): status {status}, {said[-200:]!r}")
    check("the X server ending while the window opens: status 2 and one line, at each of 16 moments",
          not wrong, "; ".join(wrong))


def display_lost_while_recording(work, scene):
    """The X server going away under the window (it ended, or xkill cut the
    window off) ended the process in Xlib, with "X connection to :N broken"
    and status 1: the take being recorded was lost. The window now writes
    it first, and ends with one line and status 2. The window runs on an X
    server of its own, which the test ends."""
    xvfb, display, env, answers, xvfb_log = own_x_server(work)
    out, err = os.path.join(work, "lost-stdout.txt"), os.path.join(work, "lost-stderr.txt")
    proc = open_window([BINARY, scene, "--size", "160x90", "--no-ui", "-v"], out, err, work, env=env)
    window = wait_for(lambda: "presented generation 1" in open(err).read() and
                      xdotool("search", "--name", "take.frag", env=env))
    check("a window opens on an X server of its own", bool(window),
          f"{display} answered: {bool(answers)}; the window said: {open(err).read()[-300:]}; "
          f"Xvfb said: {open(xvfb_log).read()[-300:]}")
    recording = None
    if window:
        xdotool("key", "--window", window.splitlines()[0], "F9", env=env)
        recording = wait_for(lambda: "take: recording" in open(out).read(), timeout=10)
    time.sleep(0.5)
    xvfb.kill()
    xvfb.wait()
    status = ended_with_take(proc, out, work, recording, "the display lost while a take records: the take is written")
    check("... and the window ends with status 2 and one line that names the display",
          status == 2 and open(err).read().endswith(f"raymarching: error: lost the X display {display} (its server "
                                                    "ended, or it closed this window's connection)\n"),
          f"status {status}: {open(err).read()[-300:]}")


if __name__ == "__main__":
    sys.exit(main())
