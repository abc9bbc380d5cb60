#!/usr/bin/env python3
"""scripts/farm/parallel-render with the real GNU parallel: a 24-frame
sequence rendered as three slices at once is bit-identical to one whole run,
and joins into a 24-frame video; a project whose frames feed the next is
refused, and writes nothing.

  farm_test.py RAYMARCHING_BINARY
"""
import os
import subprocess
import sys
import tempfile
import unittest
from pathlib import Path

BINARY = None
ROOT = Path(__file__).resolve().parents[2]
SCRIPT = ROOT / "scripts" / "farm" / "parallel-render"
SCENE = ROOT / "examples" / "shadertoy.frag"


def same_pixels(a, b):
    return subprocess.run(["idiff", "-fail", "0", "-failpercent", "0", str(a), str(b)],
                          capture_output=True).returncode == 0


class Farm(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = Path(self.tmp.name)
        self.env = dict(os.environ, RAYMARCHING=BINARY)

    def tearDown(self):
        self.tmp.cleanup()

    def test_three_slices_at_once_make_the_whole_run_bit_for_bit(self):
        (self.dir / "whole").mkdir()
        (self.dir / "sliced").mkdir()
        subprocess.run([BINARY, "render", str(SCENE), "-o", str(self.dir / "whole" / "f_%03d.png"), "--frames", "24",
                        "--size", "160x90", "--fps", "24"], check=True, capture_output=True)
        joblog = self.dir / "jobs.txt"
        subprocess.run([str(SCRIPT), "--slices", "3", "--jobs", "3", "--joblog", str(joblog), "--video",
                        str(self.dir / "sliced.mp4"), str(SCENE), "-o", str(self.dir / "sliced" / "f_%03d.png"),
                        "--frames", "24", "--size", "160x90", "--fps", "24"], check=True, env=self.env)
        # Three jobs, each over a third, and all three running at one moment.
        jobs = [line.split("\t") for line in joblog.read_text().splitlines()[1:]]
        self.assertEqual(sorted(j[-1].split()[-1] for j in jobs), ["'0:7'", "'16:23'", "'8:15'"])
        # One iDate for all: without --date each run would read its own clock.
        dates = {j[-1].split("--date ")[1].split()[0] for j in jobs}
        self.assertEqual(len(dates), 1, jobs)
        starts = [float(j[2]) for j in jobs]
        ends = [float(j[2]) + float(j[3]) for j in jobs]
        self.assertLess(max(starts), min(ends), "the slices did not run at the same time")
        whole = sorted((self.dir / "whole").iterdir())
        self.assertEqual([p.name for p in whole], [p.name for p in sorted((self.dir / "sliced").iterdir())])
        self.assertEqual(len(whole), 24)
        for frame in whole:
            self.assertTrue(same_pixels(frame, self.dir / "sliced" / frame.name), frame.name)
        count = subprocess.run(["ffprobe", "-v", "error", "-count_frames", "-show_entries", "stream=nb_read_frames",
                                "-of", "default=nw=1:nk=1", str(self.dir / "sliced.mp4")],
                               capture_output=True, text=True, check=True).stdout.strip()
        self.assertEqual(count, "24")
        self.assertEqual(sorted(p.name for p in self.dir.iterdir()), ["jobs.txt", "sliced", "sliced.mp4", "whole"])

    def test_a_project_whose_frames_feed_the_next_is_refused(self):
        out = self.dir / "frames"
        out.mkdir()
        r = subprocess.run([str(SCRIPT), "--slices", "2", str(ROOT / "examples" / "progressive" / "image.frag"), "-o",
                            str(out / "f_%02d.png"), "--frames", "4", "--size", "32x18"],
                           capture_output=True, text=True, env=self.env)
        self.assertNotEqual(r.returncode, 0)
        self.assertIn("raymarching: error: --frame-range: this project feeds each frame into the next", r.stderr)
        self.assertEqual(list(out.iterdir()), [])

    def test_the_sequence_must_be_given_whole(self):
        r = subprocess.run([str(SCRIPT), str(SCENE), "-o", str(self.dir / "f_%02d.png"), "--size", "32x18"],
                           capture_output=True, text=True, env=self.env)
        self.assertEqual(r.returncode, 2)
        self.assertEqual(r.stderr, "parallel-render: give --frames COUNT, the whole sequence\n")


if __name__ == "__main__":
    BINARY = os.path.abspath(sys.argv.pop(1))
    unittest.main(verbosity=2)
