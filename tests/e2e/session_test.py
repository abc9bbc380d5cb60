#!/usr/bin/env python3
"""A long window session, as a playground is really used: under Xvfb, one
window, driven by file saves and xdotool.
Run as: xvfb-run -a python3 session_test.py RAYMARCHING [--reloads N] [--no-rss] [--trace CSV]

1. N reloads in a row (1000 by default), alternating good and broken shaders,
   each text new so every good one is compiled: the process lives, its RSS
   grows by less than 10 MB after the first 100, and the driver holds as many
   GL objects at the end as after the first 100 (counted by `-v`).
2. An autosave storm: 200 saves in 2 s, by rename and in place. F12 pressed
   during it is answered within a second, and afterwards exactly the last
   save is on screen.
3. The scene deleted for 5 s and then recreated comes back.
4. An unwritable screenshot directory gets a one-line error while the session
   goes on, and shots work again once it is writable.
5. A still minimised and restored (through twm, when installed) is shown
   again as it was kept, not drawn again.
6. Minimised and resized to the smallest size X allows, then restored: no
   GL error, and the picture is right again.
Throughout: no GL error, sanitizer report or crash.
--no-rss skips the RSS bound (sanitizer builds keep freed memory in
quarantine, so their RSS says nothing about leaks).
The window runs with one malloc arena: with glibc's default of one per
thread, the compiling threads' arenas fragment, and RSS grew by 9 MB from
reload 100 to 1000 before it levelled off at about 1600 (11 MB); with one,
it grows by 3 MB and is level by reload 400. A leak grows in either.
"""
import argparse
import os
import re
import shutil
import subprocess
import sys
import time

import harness
from harness import (check, cpu_seconds, mean_colour, save_by_rename, save_in_place, screenshots, summary,
                     take_screenshot, wait_for, xdotool)

WINDOW = (96, 54)


def solid(rgb, note="", out="c"):
    """A shader that fills the window with one 8-bit colour (exact in a PNG).
    Texts that differ only in numbers are shown by a tweak, not compiled
    (core/tweak.h); a new name `out` makes the window compile the text."""
    r, g, b = (f"{v}.0 / 255.0" for v in rgb)
    return f"// {note}\nvoid mainImage(out vec4 {out}, in vec2 f) {{ {out} = vec4({r}, {g}, {b}, 1.0); }}\n"


def broken(note):
    return f"// {note}\nvoid mainImage(out vec4 c, in vec2 f) {{ c = vec4(1.0) +; }}\n"


# Reads iTime (so it is drawn without pause) in a way no compiler can drop,
# yet always shows one colour.
ANIMATED = ("void mainImage(out vec4 c, in vec2 f) {\n"
            "  c = vec4(0.2, 0.4, 0.6, 1.0);\n  if (iTime < -1.0) c = vec4(f / iResolution.xy, 0.0, 1.0);\n}\n")

# twm places new windows itself (no click), draws no title bar, and needs no
# font packages: Xvfb has "fixed" built in.
TWMRC = "RandomPlacement\nUsePPosition \"on\"\nNoTitle\n" + "".join(
    f'{kind}Font "fixed"\n' for kind in ("Title", "Resize", "Menu", "Icon", "IconManager"))


def start_window_manager(work):
    """twm, so that minimising means what it means on a desktop; None without it."""
    if not shutil.which("twm"):
        return None
    rc = os.path.join(work, "twmrc")
    with open(rc, "w") as f:
        f.write(TWMRC)
    wm = subprocess.Popen(["twm", "-f", rc], stderr=subprocess.DEVNULL, env={**os.environ, "LANG": "C"})
    time.sleep(0.5)
    return wm


class Session:
    """One window on one scene file, with its stdout and stderr in files."""

    def __init__(self, binary, work, scene_text):
        self.scene = os.path.join(work, "scene.frag")
        self.shots = os.path.join(work, "shots")
        os.mkdir(self.shots)
        save_by_rename(self.scene, scene_text)
        self.err_path = os.path.join(work, "stderr.txt")
        self.out_path = os.path.join(work, "stdout.txt")
        self.proc = harness.open_window(
            [binary, self.scene, "--size", f"{WINDOW[0]}x{WINDOW[1]}", "--shot-dir", self.shots, "-v"],
            self.out_path, self.err_path, work, env={**os.environ, "MALLOC_ARENA_MAX": "1"})
        found = wait_for(lambda: xdotool("search", "--name", "scene.frag"), timeout=40)
        self.window = found.splitlines()[0] if found else None
        self.log, self.log_read, self.reload_lines = open(self.err_path, "rb"), b"", 0

    def stderr(self):
        with open(self.err_path, errors="replace") as f:
            return f.read()

    def reloads(self):
        """Reload lines logged so far; reads only what is new (the log grows long)."""
        self.log_read += self.log.read()
        complete = self.log_read.rfind(b"\n") + 1
        self.reload_lines += self.log_read[:complete].count(b"raymarching: reload ")
        self.log_read = self.log_read[complete:]
        return self.reload_lines

    def alive(self):
        return self.proc.poll() is None

    def rss_kb(self):
        with open(f"/proc/{self.proc.pid}/status") as f:
            return int(re.search(r"VmRSS:\s+(\d+) kB", f.read()).group(1))

    def log_size(self):
        return os.path.getsize(self.err_path)

    def census_after(self, offset):
        """The census of the first reload logged past byte `offset` (taken
        before the save), waited for: `saved` sees the reload line, and the
        census line after it may not be written yet. The previous reload's
        census may come after `offset` too, so it is the reload's own."""
        def census():
            with open(self.err_path, "rb") as f:
                f.seek(offset)
                found = re.search(rb"raymarching: reload .*\n(?:.*\n)*?.*gl objects: (.*)\n", f.read())
            return found.group(1).decode() if found else None
        return wait_for(census, timeout=20)

    def shot(self):
        """Presses F12; returns the new picture's path, or None."""
        return take_screenshot(self.window, self.out_path)

    def shows(self, rgb):
        """Takes a shot; true when its every pixel is `rgb` (mean within half a step)."""
        path = self.shot()
        colour, _ = mean_colour(path) if path else (None, None)
        return colour is not None and all(abs(c * 255 - v) < 0.5 for c, v in zip(colour, rgb)), colour

    def quit(self):
        xdotool("key", "--window", self.window, "q")
        try:
            return self.proc.wait(timeout=20)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            return None


def colour_of(i):
    return (i % 256, 255 - i % 256, (7 * i) % 256)


def object_counts(census):
    """{"programs": 9, "textures": 4, ...} from a `gl objects:` line."""
    return {name.strip(): int(n) for name, n in re.findall(r"([a-z ]+) (\d+)", census or "")}


def write_trace(path, samples, rss_warm_kb, warm):
    """The reload samples as CSV, for scripts/reliability-report's charts."""
    with open(path, "w") as f:
        f.write(f"reload,RSS (MB),bound (+10 MB),programs,all GL objects\n")
        for reload, rss_kb, census in samples:
            objects = object_counts(census)
            f.write(f"{reload},{rss_kb / 1024:.3f},{rss_warm_kb / 1024 + 10:.3f},{objects.get('programs', 0)},"
                    f"{sum(objects.values())}\n")


def saved(s, text):
    """Saves `text` and waits for its reload line; false when none came."""
    before = s.reloads()
    save_by_rename(s.scene, text)
    return wait_for(lambda: s.reloads() > before, timeout=20, step=0.005)


def census_at_rest(s, note):
    """The GL objects once the window rests, so that two counts compare like
    with like: the last good picture refined to every sample, and its twins
    built. Some objects are made lazily (the refinement's sample target with
    its second sample), and a session under load may not have reached that
    by the first count. A broken save then changes no picture and makes `-v`
    print the count."""
    def rested():
        log = s.stderr()
        since = log.rfind("raymarching: reload ok")
        return "twins built for generation" in log[since:] and refined(s, since)

    if not wait_for(rested, timeout=60):
        return None
    since = s.log_size()
    return s.census_after(since) if saved(s, broken(note)) else None


def reload_many(s, count, check_rss, trace=None):
    """count saves alternating good and broken, each waited for. With
    `trace`, RSS and GL objects every 10 reloads go to that CSV file."""
    warm = min(100, count // 2)
    rss_warm = census_warm = None
    samples = []
    start = time.monotonic()
    for i in range(count):
        text = solid(colour_of(i), f"save {i}", f"c{i}") if i % 2 == 0 else broken(f"save {i}")
        since = s.log_size()
        if not saved(s, text):
            check(f"reload {i + 1} of {count} is seen", False, s.stderr()[-2000:])
            return
        if i + 1 == warm:
            resting = time.monotonic()
            rss_warm, census_warm = s.rss_kb(), census_at_rest(s, "census after the first reloads")
            start += time.monotonic() - resting  # the reloads' time, not the wait for rest
        if trace and (i + 1) % 10 == 0:
            samples.append((i + 1, s.rss_kb(), s.census_after(since)))
    seconds = time.monotonic() - start
    if trace:
        write_trace(trace, samples, rss_warm, warm)
    last_good = count - 1 if count % 2 else count - 2
    check(f"{count} reloads alternating good and broken leave the process alive", s.alive())
    rss_end, census_end = s.rss_kb(), census_at_rest(s, "census at the end")
    growth = (rss_end - rss_warm) / 1024
    print(f"     {count} reloads in {seconds:.1f} s; RSS {rss_warm / 1024:.1f} MB after {warm}, "
          f"{rss_end / 1024:.1f} MB after {count} (+{growth:.2f} MB)")
    print(f"     GL objects after {warm}: {census_warm}\n     GL objects after {count}: {census_end}")
    if check_rss:
        check(f"RSS grows by less than 10 MB from reload {warm} to {count}", growth < 10, f"{growth:.2f} MB")
    check("no GL object leaks: the driver holds the same objects as after the first reloads",
          census_warm is not None and census_warm == census_end, f"{census_warm} vs {census_end}")
    ok, colour = s.shows(colour_of(last_good))
    check("the last good save is on screen", ok, colour)


def autosave_storm(s, saves=200, seconds=2.0):
    """`saves` writes in `seconds`, alternately in place and by rename, with
    F12 pressed every half second; each F12 must be answered within a second,
    and afterwards the last save must be on screen."""
    pressed, latencies = [], []

    def answered():
        return len(screenshots(s.out_path))

    base, reloads_before = answered(), s.reloads()
    start = time.monotonic()
    for k in range(saves):
        (save_by_rename if k % 2 else save_in_place)(s.scene, solid(colour_of(1000 + k), f"storm {k}"))
        now = time.monotonic()
        if now - start >= 0.25 + 0.5 * len(pressed):
            xdotool("key", "--window", s.window, "F12")
            pressed.append(now)
        while len(latencies) < min(len(pressed), answered() - base):
            latencies.append(time.monotonic() - pressed[len(latencies)])
        time.sleep(max(0.0, start + (k + 1) * seconds / saves - time.monotonic()))
    took = time.monotonic() - start
    wait_for(lambda: answered() - base >= len(pressed), timeout=5)
    while len(latencies) < min(len(pressed), answered() - base):
        latencies.append(time.monotonic() - pressed[len(latencies)])
    print(f"     storm: {saves} saves in {took:.2f} s, {s.reloads() - reloads_before} reloads; F12 answered after "
          f"{', '.join(f'{l * 1000:.0f}' for l in latencies)} ms")
    check(f"{saves} saves in {took:.2f} s: every F12 during the storm is answered within 1 s",
          len(latencies) == len(pressed) > 0 and max(latencies) < 1.0, latencies)
    time.sleep(0.5)  # the watcher's debounce settles
    ok, colour = s.shows(colour_of(1000 + saves - 1))
    check("after the storm exactly the last save is on screen", ok, (colour, colour_of(1000 + saves - 1)))


def delete_and_recreate(s):
    reloads = s.reloads()
    os.remove(s.scene)
    time.sleep(5.0)
    check("scene deleted for 5 s: the process lives and says why", s.alive() and
          re.search(r"cannot read scene: .*(No such file|no such file)", s.stderr()) is not None, s.stderr()[-800:])
    save_by_rename(s.scene, solid((10, 200, 30), "recreated"))
    check("recreated scene reloads", wait_for(lambda: "reload ok" in s.stderr().split("cannot read scene")[-1]),
          s.stderr()[-800:])
    ok, colour = s.shows((10, 200, 30))
    check("recreated scene is on screen", ok and s.reloads() > reloads, colour)


def unwritable_shot_dir(s):
    shutil.rmtree(s.shots)
    with open(s.shots, "w") as f:  # a file where the directory was
        f.write("not a directory")
    def shot_errors():
        return [l for l in s.stderr().splitlines() if "error: screenshot:" in l]

    errors_before = len(shot_errors())
    xdotool("key", "--window", s.window, "F12")
    line = wait_for(lambda: shot_errors()[errors_before:])
    check("unwritable shot directory: one clear line naming it", bool(line) and s.shots in line[0], line)
    check("the file where the directory was is untouched", open(s.shots).read() == "not a directory")
    os.remove(s.shots)
    os.mkdir(s.shots)
    path = s.shot()
    check("the session goes on: once writable, F12 writes again", path is not None and os.path.exists(path), path)


def cpu_over(s, seconds):
    start = cpu_seconds(s.proc.pid)
    time.sleep(seconds)
    return cpu_seconds(s.proc.pid) - start


def refined(s, since):
    """True once the picture has all its samples after stderr offset `since`."""
    return re.search(r"raymarching: sample (\d+) of \1 ", s.stderr()[since:])


def restore_still(s):
    """A still minimised and restored is shown again from the kept picture,
    not drawn and refined anew."""
    if not shutil.which("twm"):
        return
    since = len(s.stderr())
    save_by_rename(s.scene, solid((90, 60, 30), "a still to minimise", "still"))  # compiled, not a tweak
    wait_for(lambda: refined(s, since))
    since = len(s.stderr())
    xdotool("windowminimize", "--sync", s.window)
    wait_for(lambda: "raymarching: minimised" in s.stderr()[since:], timeout=5)
    xdotool("windowmap", "--sync", s.window)
    xdotool("windowfocus", "--sync", s.window)
    wait_for(lambda: "raymarching: restored" in s.stderr()[since:], timeout=5)
    time.sleep(1.0)
    later = s.stderr()[since:]
    check("a still restored is shown again, not drawn and refined anew",
          "restored" in later and not re.search(r"raymarching: (picture|sample) ", later), later)
    ok, colour = s.shows((90, 60, 30))
    check("... and it is on screen", ok, colour)


def minimise_and_resize(s):
    since = len(s.stderr())
    save_by_rename(s.scene, ANIMATED)
    wait_for(lambda: "reload ok" in s.stderr()[since:])
    # Not while its one background build runs (1 s after the swap): it would
    # count against whichever of the two measures it fell in.
    wait_for(lambda: "twins built" in s.stderr()[since:], timeout=20)
    if shutil.which("twm"):
        shown = cpu_over(s, 2.0)
        xdotool("windowminimize", "--sync", s.window)
        check("minimise reaches the window", wait_for(lambda: "raymarching: minimised" in s.stderr(), timeout=5))
        hidden = cpu_over(s, 2.0)
        print(f"     CPU over 2 s for an animated scene: shown {shown:.2f} s, minimised {hidden:.2f} s")
        check("a minimised window draws nothing: under a fifth of the CPU time shown", hidden < shown / 5,
              f"{hidden:.2f} s vs {shown:.2f} s")
        xdotool("windowmap", "--sync", s.window)
        xdotool("windowfocus", "--sync", s.window)  # twm gives focus back to no one
        check("restoring reaches the window", wait_for(lambda: "raymarching: restored" in s.stderr(), timeout=5))
    else:
        print("     twm not installed: minimise skipped")
    # X allows no 0x0 window: ask for it anyway, then for the thinnest ones.
    for w, h in [(0, 0), (1, 1), (1, 300), (300, 1), (WINDOW[0], WINDOW[1])]:
        xdotool("windowsize", "--sync", s.window, w, h)
        time.sleep(0.4)
    check("minimised and resized to the smallest sizes: the process lives", s.alive())
    sizes = re.findall(r"framebuffer (\d+)x(\d+)", s.stderr())
    print(f"     framebuffer sizes seen: {', '.join('x'.join(p) for p in sizes)}")
    path = s.shot()
    colour, size = mean_colour(path) if path else (None, None)
    check("after restoring, the picture is right at the window's size",
          size == WINDOW and colour and all(abs(c * 255 - v) < 1 for c, v in zip(colour, (51, 102, 153))),
          (size, colour, s.stderr()[-600:]))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("binary")
    parser.add_argument("--reloads", type=int, default=1000)
    parser.add_argument("--no-rss", action="store_true")
    parser.add_argument("--trace", metavar="CSV", help="write RSS and GL objects every 10 reloads here")
    args = parser.parse_args()
    if args.reloads < 40:
        parser.error("--reloads needs at least 40: the program cache (8) must fill before counting")
    work = harness.work_dir("rm-session-")
    wm = start_window_manager(work)
    s = Session(os.path.abspath(args.binary), work, solid((1, 2, 3), "first"))
    try:
        check("window opens", s.window is not None, s.stderr())
        if not s.window:
            return
        check("first program presented", wait_for(lambda: "presented generation 1" in s.stderr(), timeout=40))
        for step in (lambda: reload_many(s, args.reloads, not args.no_rss, args.trace), lambda: autosave_storm(s),
                     lambda: delete_and_recreate(s), lambda: unwritable_shot_dir(s),
                     lambda: restore_still(s), lambda: minimise_and_resize(s)):
            if not s.alive():
                break
            step()
        status = s.quit()
        check("Q quits with status 0 at the end", status == 0, status)
        log = s.stderr()
        for bad in ("GL error", "runtime error", "AddressSanitizer", "LeakSanitizer"):
            check(f"no '{bad}' in the whole session", bad not in log,
                  "\n".join(l for l in log.splitlines() if bad in l)[:2000])
    finally:
        if s.alive():
            s.proc.kill()
        if wm:
            wm.kill()


if __name__ == "__main__":
    try:
        main()
    finally:
        code = summary()
    sys.exit(code)
