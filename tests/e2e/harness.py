"""What the window end-to-end tests share: pass/fail bookkeeping, waiting,
xdotool, saving like an editor, and reading back screenshots."""
import atexit
import os
import re
import resource
import shlex
import shutil
import subprocess
import tempfile
import time

passed, failed = 0, 0
work_dirs = []
windows = []  # (binary, folder) of every window opened: where a crashed one left its core


def check(name, ok, detail=""):
    global passed, failed
    if ok:
        passed += 1
        print(f"ok   {name}", flush=True)
    else:
        failed += 1
        print(f"FAIL {name} {detail}", flush=True)


def work_dir(prefix):
    """A new folder for a test's files, in the system's temporary folder.
    summary() removes it if every check passed, and keeps it, naming it, if
    one failed: its logs and pictures are what a failure is read from."""
    path = tempfile.mkdtemp(prefix=prefix)
    work_dirs.append(path)
    return path


def print_crash_backtraces():
    """A window that crashed (an abort, a segfault) left a core file in its
    folder: each one's backtrace, every thread, goes into the log, since a
    crash seen once in CI may not be seen again (a heap corruption in
    e2e.window, 2026-12-01). At the script's exit, after summary() has
    removed the folders of a test that passed, and after an exception too
    (that crash's test ended in one). The core is removed: it is hundreds of
    MB."""
    for binary, folder in windows:
        for name in sorted(os.listdir(folder)) if os.path.isdir(folder) else []:
            if not re.fullmatch(r"core(\.\d+)?", name):
                continue
            core = os.path.join(folder, name)
            print(f"a window crashed: backtrace of {core}:")
            try:
                gdb = ["gdb", "-batch", "-nx", "-iex", "set debuginfod enabled off", "-ex", "thread apply all bt 40"]
                trace = subprocess.run([*gdb, binary, core], capture_output=True, text=True, timeout=120).stdout
                print("\n".join(line for line in trace.splitlines() if line.startswith(("#", "Thread", "Program"))))
            except (OSError, subprocess.TimeoutExpired) as e:
                print(f"  no backtrace: {e}")
            os.remove(core)


atexit.register(print_crash_backtraces)


def summary():
    """Prints the totals and removes or names the work folders; returns the
    exit status for the test."""
    print(f"{passed} passed, {failed} failed")
    status = 1 if failed or not passed else 0
    for path in work_dirs:
        if status:
            print(f"kept for inspection: {path}")
        else:
            # A window the test killed may still be closing its files there.
            shutil.rmtree(path, ignore_errors=True)
    return status


def wait_for(predicate, timeout=20.0, step=0.05):
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        value = predicate()
        if value:
            return value
        time.sleep(step)
    return None


def xdotool(*args, env=None):
    """xdotool's answer, on the display of `env` (default: this process's)."""
    out = subprocess.run(["xdotool", *map(str, args)], capture_output=True, text=True, env=env).stdout.strip()
    if args and args[0] == "key" and "--window" in args:
        # xdotool presses a key of the focused window by XTEST and releases
        # it by XSendEvent once the window has gone (Q quits in 5 ms): the
        # key stayed down in the server, and its autorepeat quit every
        # window opened after it (seen: nine tests of e2e.budget in a row).
        keys = [str(a) for a in args[args.index("--window") + 2:]]
        subprocess.run(["xdotool", "keyup", *keys], capture_output=True, env=env)
    return out


def save_by_rename(path, text):
    """As vim, VS Code and JetBrains save: a temporary renamed over the file."""
    tmp = path + ".tmp~"
    with open(tmp, "w") as f:
        f.write(text)
    os.rename(tmp, path)


def scene_copy(scene, prefix):
    """A new folder holding a copy of `scene`'s folder, for a window to open
    and edit while the repository stays as it is: (the folder, the copied
    scene, its text, a path for the window's stderr, the environment that
    gives it an empty Mesa shader cache of its own)."""
    work = tempfile.mkdtemp(prefix=prefix)
    folder = os.path.join(work, "scene")
    shutil.copytree(os.path.dirname(os.path.abspath(scene)), folder, symlinks=True)
    copy = os.path.join(folder, os.path.basename(scene))
    env = dict(os.environ, MESA_SHADER_CACHE_DIR=os.path.join(work, "mesa-cache"))
    return work, copy, open(copy).read(), os.path.join(work, "stderr.txt"), env


def save_in_place(path, text):
    """As nano and many autosaves do: truncate and write the same file."""
    with open(path, "w") as f:
        f.write(text)


def cpu_seconds(pid):
    """CPU time the process has used so far: user + system, all threads."""
    with open(f"/proc/{pid}/stat") as f:
        fields = f.read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def screenshots(out_path):
    """The pictures the program reported writing ("screenshot: PATH" on its
    stdout, captured in out_path), oldest first."""
    with open(out_path) as f:
        return [l[len("screenshot: "):] for l in f.read().splitlines() if l.startswith("screenshot: ")]


def take_screenshot(window, out_path, timeout=20.0):
    """Presses F12 in the window; returns the new picture's path, or None."""
    before = len(screenshots(out_path))
    xdotool("key", "--window", window, "F12")
    new = wait_for(lambda: screenshots(out_path)[before:], timeout=timeout, step=0.02)
    return new[0] if new else None


def metadata(image):
    out = subprocess.run(["iinfo", "-v", image], capture_output=True, text=True).stdout
    return dict(re.findall(r'^\s+([\w:]+): "(.*)"$', out, re.M))


def mean_colour(image):
    """The image's mean RGB in [0, 1], and its size as (width, height)."""
    stats = subprocess.run(["oiiotool", "--stats", image], capture_output=True, text=True).stdout
    avg = re.search(r"Stats Avg: ([0-9.]+) ([0-9.]+) ([0-9.]+)", stats)
    size = re.search(r"(\d+) x\s*(\d+)", stats)
    scale = 255.0 if "(of 255)" in stats else 1.0
    colour = [float(v) / scale for v in avg.groups()] if avg else None
    return colour, (int(size.group(1)), int(size.group(2))) if size else None


def allow_core_file():
    """In the window's process, before it starts: a crash writes a core file
    (print_crash_backtraces reads it), up to 4 GB."""
    _, hard = resource.getrlimit(resource.RLIMIT_CORE)
    resource.setrlimit(resource.RLIMIT_CORE, (4 << 30 if hard == resource.RLIM_INFINITY else min(4 << 30, hard), hard))


def open_window(args, stdout_path, stderr_path, cwd, env=None):
    """Starts the program (a window) with its output in files. An X server
    resets when its last client leaves, and a window opened in that moment
    fails with "Failed to open display" (seen in CI between two windows of
    one test): such a start is tried again, up to three times."""
    windows.append((args[0], cwd))
    for attempt in range(3):
        proc = subprocess.Popen(args, stdout=open(stdout_path, "w"), stderr=open(stderr_path, "w"), cwd=cwd, env=env,
                                preexec_fn=allow_core_file)
        try:
            proc.wait(timeout=2.0)
        except subprocess.TimeoutExpired:
            return proc  # still running: it has its display
        if "Failed to open display" not in open(stderr_path).read() or attempt == 2:
            return proc
        time.sleep(0.5)
    return proc


def capture_screen(window, ppm_path):
    """What the X server shows of `window` (not an F12 shot): xwd reads it,
    and its ZPixmap is written as a binary PPM that OpenImageIO reads."""
    import struct
    data = subprocess.run(["xwd", "-silent", "-id", str(window)], capture_output=True).stdout
    if len(data) < 100:
        return None
    fields = struct.unpack(">25I", data[:100])
    header_size, width, height = fields[0], fields[4], fields[5]
    byte_order, bits_per_pixel, bytes_per_line = fields[7], fields[11], fields[12]
    masks, ncolors = fields[14:17], fields[19]
    if bits_per_pixel != 32:
        return None
    start = header_size + 12 * ncolors
    shifts = [(m & -m).bit_length() - 1 for m in masks]
    order = "<" if byte_order == 0 else ">"
    rgb = bytearray()
    for y in range(height):
        row = data[start + y * bytes_per_line:start + y * bytes_per_line + 4 * width]
        for (p,) in struct.iter_unpack(order + "I", row):
            rgb += bytes((p & m) >> s for m, s in zip(masks, shifts))
    with open(ppm_path, "wb") as f:
        f.write(b"P6\n%d %d\n255\n" % (width, height) + bytes(rgb))
    return ppm_path


def count_pixels(ppm_path, region, test):
    """How many pixels of a binary PPM (as capture_screen writes) inside
    region (x, y, w, h) pass test(r, g, b), with channels in [0, 255]."""
    with open(ppm_path, "rb") as f:
        magic, width, height, _, data = f.read().split(maxsplit=4)
    width, x0, y0, w, h = int(width), *region
    count = 0
    for y in range(y0, y0 + h):
        row = data[3 * (y * width + x0):3 * (y * width + x0 + w)]
        count += sum(1 for i in range(0, len(row), 3) if test(row[i], row[i + 1], row[i + 2]))
    return count


def first_frame_window(proc, title, stderr_path, timeout=20.0, marker="presented generation 1"):
    """The id of the window titled `title` once the program (run with -v) has
    presented its first frame (logged `marker`); None, with the program
    killed, if either does not come within `timeout`."""
    window = wait_for(lambda: xdotool("search", "--name", title), timeout=timeout)
    if not window or not wait_for(lambda: marker in open(stderr_path).read(), timeout=timeout):
        proc.kill()
        return None
    return window.splitlines()[0]


def pixels_over(a, b, threshold, work, region=None):
    """How many pixels of images a and b differ by more than `threshold` in
    of R, G and B (the screen has no alpha), over `region` (x, y, w, h) or
    the whole picture."""
    cut = ["--cut", "{}x{}+{}+{}".format(*region[2:], *region[:2])] if region else []
    rgb = []
    for image, name in ((a, "rgb_a.png"), (b, "rgb_b.png")):
        rgb.append(os.path.join(work, name))
        subprocess.run(["oiiotool", image, "--ch", "R,G,B", *cut, "-o", rgb[-1]], check=True)
    a, b = rgb
    limit = f"{threshold:g}"  # idiff prints the threshold as it was given
    out = subprocess.run(["idiff", "-fail", limit, a, b], capture_output=True, text=True).stdout
    found = re.search(r"(\d+) pixels \([0-9.]+%\) over " + re.escape(limit), out)
    return int(found.group(1)) if found else (0 if "PASS" in out else None)


def matches_render(binary, shot, scene_file, reference, fail_percent=0):
    """Renders what the shot's metadata says, headless, to `reference`, and
    compares pixels: none may differ by more than 1.5/255, but for
    `fail_percent` of them. Returns (ok, idiff's report)."""
    command = shlex.split(metadata(shot)["ImageDescription"])
    assert command[:2] == ["raymarching", "render"], command
    subprocess.run([binary, "render", scene_file] + command[3:] + ["-o", reference], check=True)
    # One 8-bit step of tolerance: the window's framebuffer and the float
    # target may round differently. A pixel -failpercent lets pass is still
    # a warning, and idiff's exit status 1, unless -warnpercent allows it.
    limits = ["-fail", str(1.5 / 255), "-failpercent", str(fail_percent)]
    diff = subprocess.run(["idiff", *limits, *(arg.replace("fail", "warn") for arg in limits), shot, reference],
                          capture_output=True, text=True)
    return diff.returncode == 0, diff.stdout + " " + " ".join(command)
