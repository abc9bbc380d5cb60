#!/usr/bin/env python3
"""`render -o NAME.mp4` and its kin, with the real ffmpeg and ffprobe.

  video_test.py RAYMARCHING_BINARY

Each video is decoded again: its frame count, size and rate by ffprobe, and
one frame by ffmpeg, compared with the PNG `render` draws of that frame. A
missing, failing or killed ffmpeg, a --timeout and a signal (SIGTERM,
SIGINT) leave no file under the output's name and no hidden one beside it;
a signal keeps the frames of a sequence written whole, and `--skip-existing`
goes on from them; a signal ignored when the render began (nohup's SIGHUP)
stays ignored.
"""
import os
import pty
import re
import signal
import subprocess
import sys
import tempfile
import time
import unittest
from pathlib import Path

BINARY = None
ROOT = Path(__file__).resolve().parents[2]

# Every frame is far from the next: a gradient that moves a tenth of the
# picture per frame, so that frame 11 or 13 does not pass for frame 12.
MOVING = """void mainImage(out vec4 fragColor, in vec2 fragCoord) {
  vec2 uv = fragCoord / iResolution.xy;
  float phase = 6.2831853 * (uv.x + 0.1 * float(iFrame));
  fragColor = vec4(0.5 + 0.4 * sin(phase), 0.5 + 0.4 * cos(phase + uv.y), uv.y, 1.0);
}
"""


def children(pid):
    """The children of process `pid`, those of all its threads: the render
    runs on a thread of its own, with a deep stack."""
    found = []
    for task in Path(f"/proc/{pid}/task").iterdir():
        try:
            found += (task / "children").read_text().split()
        except FileNotFoundError:  # a thread that ended
            pass
    return found


def ffmpeg_child(pid):
    """The pid of the ffmpeg that process `pid` started, or None."""
    return next((int(c) for c in children(pid) if Path(f"/proc/{c}/comm").read_text().strip() == "ffmpeg"), None)


def render(*args, env=None, check=True):
    result = subprocess.run([BINARY, "render", *map(str, args)], capture_output=True, text=True, env=env)
    if check and result.returncode != 0:
        raise AssertionError(f"render {' '.join(map(str, args))} failed ({result.returncode}): {result.stderr}")
    return result


def probe(video):
    """ffprobe's view of the first video stream: codec, size, rate, frames."""
    out = subprocess.run(["ffprobe", "-v", "error", "-count_frames", "-select_streams", "v:0", "-show_entries",
                          "stream=codec_name,width,height,r_frame_rate,pix_fmt,nb_read_frames", "-of",
                          "default=noprint_wrappers=1", str(video)], capture_output=True, text=True, check=True).stdout
    return dict(line.split("=", 1) for line in out.split())


def frame_of(video, n, png):
    subprocess.run(["ffmpeg", "-v", "error", "-i", str(video), "-vf", f"select=eq(n\\,{n})", "-frames:v", "1",
                    str(png)], check=True)
    return png


def mean_error(a, b):
    """Mean absolute difference of the colour channels of two pictures, 0 to 1."""
    out = subprocess.run(["oiiotool", str(a), "--ch", "R,G,B", str(b), "--ch", "R,G,B", "--diff"],
                         capture_output=True, text=True).stdout
    return float(re.search(r"Mean error = ([0-9.e+-]+)", out).group(1))


def leftovers(directory):
    return sorted(p.name for p in Path(directory).iterdir())


class Video(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = Path(self.tmp.name)
        self.scene = self.dir / "moving.frag"
        self.scene.write_text(MOVING)

    def tearDown(self):
        self.tmp.cleanup()

    def test_an_mp4_decodes_to_its_frames_and_frame_12_is_the_png_of_frame_12(self):
        video = self.dir / "moving.mp4"
        render(self.scene, "-o", video, "--frames", 24, "--fps", 24, "--size", "160x90")
        info = probe(video)
        self.assertEqual(info["codec_name"], "h264")
        self.assertEqual(info["pix_fmt"], "yuv420p")
        self.assertEqual((info["width"], info["height"]), ("160", "90"))
        self.assertEqual(info["r_frame_rate"], "24/1")
        self.assertEqual(info["nb_read_frames"], "24")
        decoded = frame_of(video, 12, self.dir / "decoded12.png")
        errors = {}
        for n in (11, 12, 13):
            still = self.dir / f"still{n}.png"
            render(self.scene, "-o", still, "--time", n / 24, "--fps", 24, "--size", "160x90")
            errors[n] = mean_error(still, decoded)
        self.assertLess(errors[12], 0.02, errors)  # H.264 at crf 18, chroma at half resolution
        self.assertGreater(min(errors[11], errors[13]), 5 * errors[12], errors)
        self.assertEqual(leftovers(self.dir), sorted(["moving.frag", "moving.mp4", "decoded12.png", "still11.png",
                                                      "still12.png", "still13.png"]))

    def test_webm_gif_and_mov_with_a_duration(self):
        for name, codec in (("clip.webm", "vp9"), ("clip.gif", "gif"), ("clip.mov", "h264")):
            with self.subTest(name):
                render(self.scene, "-o", self.dir / name, "--duration", 0.5, "--fps", 24, "--size", "160x90")
                info = probe(self.dir / name)
                self.assertEqual(info["codec_name"], codec)
                self.assertEqual(info["nb_read_frames"], "12")

    def test_codec_and_quality_are_passed_to_ffmpeg(self):
        coarse, fine = self.dir / "coarse.mp4", self.dir / "fine.mp4"
        render(self.scene, "-o", coarse, "--frames", 12, "--size", "160x90", "--crf", 40)
        render(self.scene, "-o", fine, "--frames", 12, "--size", "160x90", "--crf", 4)
        still = self.dir / "still5.png"
        render(self.scene, "-o", still, "--time", 5 / 60, "--size", "160x90")
        self.assertLess(coarse.stat().st_size, fine.stat().st_size)
        self.assertGreater(mean_error(still, frame_of(coarse, 5, self.dir / "coarse5.png")),
                           2 * mean_error(still, frame_of(fine, 5, self.dir / "fine5.png")))
        mpeg4 = self.dir / "mpeg4.mp4"
        render(self.scene, "-o", mpeg4, "--frames", 4, "--size", "160x90", "--codec", "mpeg4")
        self.assertEqual(probe(mpeg4)["codec_name"], "mpeg4")

    def test_a_project_with_feedback_runs_on_across_the_frames(self):
        # A buffer that gains a tenth every frame, shown as it is.
        (self.dir / "buffer_a.frag").write_text(
            "#pragma channel0 self filter=nearest\n"
            "void mainImage(out vec4 c, in vec2 f) { c = texelFetch(iChannel0, ivec2(f), 0) + vec4(0.1); }\n")
        project = self.dir / "image.frag"
        project.write_text("#pragma channel0 \"buffer_a.frag\" filter=nearest\n"
                           "void mainImage(out vec4 c, in vec2 f) { c = vec4(texelFetch(iChannel0, ivec2(f), 0).rgb, 1.0); }\n")
        video = self.dir / "gaining.mp4"
        render(project, "-o", video, "--frames", 8, "--size", "160x90")
        render(project, "-o", self.dir / "frame%d.png", "--frames", 8, "--size", "160x90")
        decoded = frame_of(video, 7, self.dir / "decoded7.png")
        self.assertLess(mean_error(self.dir / "frame7.png", decoded), 0.02)
        self.assertGreater(mean_error(self.dir / "frame0.png", decoded), 0.5)

    def test_without_ffmpeg_one_line_says_so_and_nothing_is_written(self):
        env = dict(os.environ, PATH=str(self.dir))  # a PATH that holds no ffmpeg
        r = render(self.scene, "-o", self.dir / "none.mp4", "--frames", 4, "--size", "160x90", env=env, check=False)
        self.assertEqual(r.returncode, 2)
        self.assertEqual(r.stderr, f"raymarching: error: '{self.dir / 'none.mp4'}': a video needs ffmpeg, which is "
                                   "not on PATH (Debian: apt-get install ffmpeg)\n")
        self.assertEqual(leftovers(self.dir), ["moving.frag"])

    def test_a_failing_ffmpeg_is_reported_in_its_own_words(self):
        r = render(self.scene, "-o", self.dir / "bad.mp4", "--frames", 4, "--size", "160x90", "--codec", "no-such-codec",
                   check=False)
        self.assertEqual(r.returncode, 2)
        self.assertIn("ffmpeg", r.stderr)
        self.assertIn("no-such-codec", r.stderr)
        self.assertEqual(len(r.stderr.splitlines()), 1, r.stderr)
        self.assertEqual(leftovers(self.dir), ["moving.frag"])

    def test_a_killed_ffmpeg_leaves_nothing_under_any_name(self):
        out = self.dir / "killed.mp4"
        run = subprocess.Popen([BINARY, "render", str(ROOT / "examples" / "default.frag"), "-o", str(out),
                                "--frames", "5000", "--size", "320x180"], stderr=subprocess.PIPE, text=True)
        ffmpeg = None
        for _ in range(200):  # its ffmpeg starts once the scene is built
            ffmpeg = ffmpeg_child(run.pid)
            if ffmpeg:
                break
            time.sleep(0.05)
        self.assertIsNotNone(ffmpeg, "render started no ffmpeg")
        time.sleep(1.0)  # frames are on their way
        self.assertEqual(leftovers(self.dir)[0][0], ".", "ffmpeg writes a hidden file while it encodes")
        os.kill(ffmpeg, signal.SIGKILL)
        _, err = run.communicate(timeout=60)
        self.assertEqual(run.returncode, 2)
        self.assertEqual(err, f"raymarching: error: ffmpeg stopped while writing '{out}' (killed by signal 9, Killed)\n")
        self.assertEqual(leftovers(self.dir), ["moving.frag"])

    def test_a_timeout_stops_ffmpeg_and_removes_its_file(self):
        # Late enough that ffmpeg has started (the scene is built first: over
        # 1 s sanitized on a slow day), long before 5000 frames are done.
        started = time.monotonic()
        r = render(ROOT / "examples" / "default.frag", "-o", self.dir / "late.mp4", "--frames", 5000, "--size",
                   "320x180", "--timeout", 5, check=False)
        self.assertEqual(r.returncode, 124)
        self.assertLess(time.monotonic() - started, 15)
        self.assertEqual(r.stderr, "raymarching: error: the render ran past --timeout 5 s and was stopped; "
                                   "the video it was writing is removed\n")
        time.sleep(0.2)
        self.assertEqual(leftovers(self.dir), ["moving.frag"])

    def start_encoding(self, out):
        """A long render of a video to `out`, once its ffmpeg runs and has frames."""
        run = subprocess.Popen([BINARY, "render", str(ROOT / "examples" / "default.frag"), "-o", str(out),
                                "--frames", "5000", "--size", "320x180"], stderr=subprocess.PIPE, text=True)
        for _ in range(200):  # its ffmpeg starts once the scene is built
            if ffmpeg_child(run.pid):
                break
            time.sleep(0.05)
        time.sleep(1.0)  # frames are on their way
        self.assertEqual(leftovers(self.dir)[0][0], ".", "ffmpeg writes a hidden file while it encodes")
        return run

    def test_a_signal_stops_ffmpeg_and_removes_its_file(self):
        # SIGTERM is what kill, Slurm's scancel and its time limit send.
        run = self.start_encoding(self.dir / "stopped.mp4")
        run.send_signal(signal.SIGTERM)
        _, err = run.communicate(timeout=60)
        self.assertEqual(run.returncode, 128 + signal.SIGTERM)
        self.assertEqual(err, "raymarching: error: the render was stopped by SIGTERM; the video it was writing is "
                              "removed\n")
        time.sleep(0.2)
        self.assertEqual(leftovers(self.dir), ["moving.frag"])

    def test_a_signal_keeps_the_frames_of_a_sequence_written_whole(self):
        # Ctrl-C (SIGINT) while frames are written: those done stay, each a
        # whole picture, and no hidden file is left of the next.
        run = subprocess.Popen([BINARY, "render", str(self.scene), "-o", str(self.dir / "f%05d.png"), "--frames",
                                "100000", "--size", "160x90"], stderr=subprocess.PIPE, text=True)
        deadline = time.monotonic() + 60
        while len(leftovers(self.dir)) < 6 and time.monotonic() < deadline:
            time.sleep(0.02)
        run.send_signal(signal.SIGINT)
        _, err = run.communicate(timeout=60)
        self.assertEqual(run.returncode, 128 + signal.SIGINT)
        frames = [name for name in leftovers(self.dir) if name != "moving.frag"]
        self.assertGreaterEqual(len(frames), 5)
        self.assertEqual(err, f"raymarching: error: the render was stopped by SIGINT; the {len(frames)} frames it "
                              "wrote are kept\n")
        self.assertEqual(frames, [f"f{n:05d}.png" for n in range(len(frames))])
        for name in (frames[0], frames[-1]):
            info = subprocess.run(["oiiotool", "--info", str(self.dir / name)], capture_output=True, text=True)
            self.assertIn("160 x   90", info.stdout, name)

    def test_a_stopped_sequence_started_again_with_skip_existing_goes_on_where_it_stopped(self):
        # As a Slurm task cancelled and requeued: the frames kept are not
        # drawn again, and the whole is the frames of one uninterrupted run.
        args = [str(self.scene), "--frames", "40", "--size", "160x90", "--date", "2026-01-01T00:00:00"]
        (self.dir / "stopped").mkdir()
        run = subprocess.Popen([BINARY, "render", "-o", str(self.dir / "stopped" / "f%02d.png"), *args],
                               stderr=subprocess.PIPE, text=True)
        deadline = time.monotonic() + 60
        while len(leftovers(self.dir / "stopped")) < 5 and time.monotonic() < deadline:
            time.sleep(0.02)
        run.send_signal(signal.SIGTERM)
        run.communicate(timeout=60)
        kept = {name: os.stat(self.dir / "stopped" / name) for name in leftovers(self.dir / "stopped")}
        self.assertTrue(5 <= len(kept) < 40, kept.keys())
        render("-o", self.dir / "stopped" / "f%02d.png", *args, "--skip-existing")
        self.assertEqual(leftovers(self.dir / "stopped"), [f"f{n:02d}.png" for n in range(40)])
        for name, before in kept.items():
            after = os.stat(self.dir / "stopped" / name)
            self.assertEqual((after.st_ino, after.st_mtime_ns), (before.st_ino, before.st_mtime_ns), name)
        (self.dir / "whole").mkdir()
        render("-o", self.dir / "whole" / "f%02d.png", *args)
        for n in range(40):
            name = f"f{n:02d}.png"
            self.assertEqual((self.dir / "stopped" / name).read_bytes(), (self.dir / "whole" / name).read_bytes(), name)

    def test_a_signal_ignored_when_the_render_began_stays_ignored(self):
        # nohup ignores SIGHUP for the program it starts: the render goes on.
        run = subprocess.Popen([BINARY, "render", str(self.scene), "-o", str(self.dir / "v.mp4"), "--frames", "48",
                                "--size", "160x90"], stderr=subprocess.PIPE, text=True,
                               preexec_fn=lambda: signal.signal(signal.SIGHUP, signal.SIG_IGN))
        deadline = time.monotonic() + 60
        while not leftovers(self.dir)[0].startswith(".") and time.monotonic() < deadline:
            time.sleep(0.02)
        run.send_signal(signal.SIGHUP)
        _, err = run.communicate(timeout=60)
        self.assertEqual(run.returncode, 0, err)
        self.assertEqual(probe(self.dir / "v.mp4")["nb_read_frames"], "48")

    def test_on_a_terminal_the_progress_bar_shows_the_count_the_rate_and_the_time_left(self):
        controller, terminal = pty.openpty()
        run = subprocess.Popen([BINARY, "render", str(self.scene), "-o", str(self.dir / "bar.mp4"), "--frames", "30",
                                "--size", "160x90"], stderr=terminal, stdout=subprocess.DEVNULL)
        os.close(terminal)
        shown = b""
        while True:
            try:
                chunk = os.read(controller, 4096)
            except OSError:  # the terminal closed with the process
                break
            if not chunk:
                break
            shown += chunk
        os.close(controller)
        self.assertEqual(run.wait(), 0)
        text = shown.decode()
        self.assertRegex(text, r"\] 1/30 frames  [0-9.]+ fps  ETA \d+:\d\d")
        self.assertRegex(text, r"\] 30/30 frames  [0-9.]+ fps  in \d+:\d\d")


if __name__ == "__main__":
    BINARY = sys.argv.pop(1)
    unittest.main(verbosity=2)
