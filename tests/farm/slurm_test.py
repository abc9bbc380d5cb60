#!/usr/bin/env python3
"""scripts/farm/slurm-render against a real single-node Slurm on this machine:
munged, slurmctld and slurmd from Debian's packages, configured in a
temporary directory with ports of their own, started for the test and
stopped after it. (slurmd runs jobs as their user: it needs root.)

A 12-frame sequence as a 3-task job array is bit-identical to one whole
run, and its join job makes a 12-frame video; a project whose frames feed
the next fails in every task, and no video is made.

  slurm_test.py RAYMARCHING_BINARY
"""
import os
import signal
import socket
import subprocess
import sys
import tempfile
import time
import unittest
from pathlib import Path

from farm_test import same_pixels

BINARY = None
ROOT = Path(__file__).resolve().parents[2]
SCRIPT = ROOT / "scripts" / "farm" / "slurm-render"


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


class LocalSlurm:
    """munged, slurmctld and slurmd with everything under `root`."""

    def __init__(self, root):
        self.root = root
        self.pids = []
        host = socket.gethostname().split(".")[0]
        munge = root / "munge"
        munge.mkdir(mode=0o700)
        key = munge / "munge.key"
        key.write_bytes(os.urandom(1024))
        key.chmod(0o400)
        self.socket = munge / "munge.socket"
        subprocess.run(["munged", "--force", f"--key-file={key}", f"--socket={self.socket}",
                        f"--pid-file={munge / 'munged.pid'}", f"--log-file={munge / 'munged.log'}",
                        f"--seed-file={munge / 'munged.seed'}"], check=True)
        self.pid_files = [munge / "munged.pid", root / "slurmctld.pid", root / "slurmd.pid"]
        for d in ("state", "spool"):
            (root / d).mkdir()
        self.conf = root / "slurm.conf"
        self.conf.write_text(f"""ClusterName=rmtest
SlurmctldHost={host}
SlurmctldPort={free_port()}
SlurmdPort={free_port()}
AuthType=auth/munge
AuthInfo=socket={self.socket}
CredType=cred/munge
SlurmUser=root
SlurmdUser=root
StateSaveLocation={root / 'state'}
SlurmdSpoolDir={root / 'spool'}
SlurmctldPidFile={root / 'slurmctld.pid'}
SlurmdPidFile={root / 'slurmd.pid'}
SlurmctldLogFile={root / 'slurmctld.log'}
SlurmdLogFile={root / 'slurmd.log'}
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
MpiDefault=none
ReturnToService=2
NodeName={host} CPUs={os.cpu_count()} State=UNKNOWN
PartitionName=render Nodes={host} Default=YES MaxTime=INFINITE State=UP
""")
        self.env = dict(os.environ, SLURM_CONF=str(self.conf), RAYMARCHING=BINARY)
        subprocess.run(["slurmctld", "-f", str(self.conf)], check=True, env=self.env)
        subprocess.run(["slurmd", "-f", str(self.conf)], check=True, env=self.env)
        # The daemons start in seconds, but once, beside the window's tests on
        # 2 busy cores, slurmctld had not answered in 30 s.
        for _ in range(1200):
            state = subprocess.run(["sinfo", "-h", "-o", "%T"], capture_output=True, text=True, env=self.env).stdout
            if state.strip() == "idle":
                return
            time.sleep(0.1)
        # Said here, with the logs, and stopped: the temporary directory goes
        # with the failed class, and daemons left running would outlive it.
        logs = "".join(f"\n--- {name}:\n" + "".join((root / name).read_text(errors="replace").splitlines(True)[-10:])
                       for name in ("slurmctld.log", "slurmd.log") if (root / name).exists())
        self.stop()
        raise RuntimeError(f"the node never became idle in 120 s: {state!r}{logs}")

    def stop(self):
        """SIGTERM to each daemon, and SIGKILL to one still there after 10 s."""
        pids = []
        for pid_file in reversed(self.pid_files):
            try:
                pids.append(int(pid_file.read_text().split()[0]))
                os.kill(pids[-1], signal.SIGTERM)
            except (OSError, ValueError):
                pass
        deadline = time.monotonic() + 10
        for pid in pids:
            while Path(f"/proc/{pid}").exists() and time.monotonic() < deadline:
                time.sleep(0.1)
            if Path(f"/proc/{pid}").exists():
                os.kill(pid, signal.SIGKILL)


class Slurm(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        if os.geteuid() != 0:
            raise unittest.SkipTest("slurmd runs jobs as their user and needs root")
        cls.tmp = tempfile.TemporaryDirectory()
        cls.slurm = LocalSlurm(Path(cls.tmp.name))

    @classmethod
    def tearDownClass(cls):
        cls.slurm.stop()
        cls.tmp.cleanup()

    def setUp(self):
        self.dir = Path(tempfile.mkdtemp(dir=self.tmp.name))

    def submit(self, *args):
        return subprocess.run([str(SCRIPT), "--wait", "--sbatch", f"--output={self.dir}/job-%A_%a.out", *map(str, args)],
                              capture_output=True, text=True, env=self.slurm.env, cwd=self.dir)

    def test_a_job_array_makes_the_whole_run_bit_for_bit_and_the_join_a_video(self):
        scene = ROOT / "examples" / "shadertoy.frag"
        (self.dir / "whole").mkdir()
        (self.dir / "array").mkdir()
        subprocess.run([BINARY, "render", str(scene), "-o", str(self.dir / "whole" / "f_%02d.png"), "--frames", "12",
                        "--size", "160x90", "--fps", "24"], check=True, capture_output=True)
        r = self.submit("--slices", 3, "--video", self.dir / "array.mp4", scene, "-o", self.dir / "array" / "f_%02d.png",
                        "--frames", 12, "--size", "160x90", "--fps", 24)
        self.assertEqual(r.returncode, 0, r.stderr)
        array, join = r.stdout.split()
        logs = {p.name: p.read_text() for p in self.dir.glob("job-*.out")}
        for task, frames in enumerate(("0:3", "4:7", "8:11")):
            self.assertIn(f"raymarching slice {frames} on ", logs.get(f"job-{array}_{task}.out", ""), logs)
        self.assertTrue(any("raymarching joined" in text for name, text in logs.items() if join in name), logs)
        whole = sorted(p.name for p in (self.dir / "whole").iterdir())
        self.assertEqual(whole, sorted(p.name for p in (self.dir / "array").iterdir()))
        self.assertEqual(len(whole), 12)
        for name in whole:
            self.assertTrue(same_pixels(self.dir / "whole" / name, self.dir / "array" / name), name)
        count = subprocess.run(["ffprobe", "-v", "error", "-count_frames", "-show_entries", "stream=nb_read_frames,r_frame_rate",
                                "-of", "default=nw=1", str(self.dir / "array.mp4")],
                               capture_output=True, text=True, check=True).stdout.split()
        self.assertEqual(sorted(count), ["nb_read_frames=12", "r_frame_rate=24/1"])

    def test_a_project_whose_frames_feed_the_next_fails_every_task_and_makes_no_video(self):
        out = self.dir / "frames"
        out.mkdir()
        r = self.submit("--slices", 2, "--video", self.dir / "none.mp4", ROOT / "examples" / "progressive" / "image.frag",
                        "-o", out / "f_%02d.png", "--frames", 4, "--size", "32x18")
        self.assertEqual(r.returncode, 1)
        self.assertIn("slurm-render: no video: a slice failed", r.stderr)
        self.assertEqual(list(out.iterdir()), [])
        self.assertFalse((self.dir / "none.mp4").exists())
        logs = "".join(p.read_text() for p in self.dir.glob("job-*.out"))
        self.assertEqual(logs.count("its frames cannot be rendered apart"), 2, logs)


if __name__ == "__main__":
    BINARY = os.path.abspath(sys.argv.pop(1))
    unittest.main(verbosity=2)
