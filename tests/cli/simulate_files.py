#!/usr/bin/env python3
"""End-to-end checks of the files `throng simulate` writes (registered in simulate.cmake).

  simulate_files.py --throng BIN --dir DIR --asset-dir ASSETS

- The issue's example and a goals crowd succeed; the headers are exact; the rows are
  characters x (frames + 1), x joints for --joints-out (joints counted from the BVH files'
  ROOT/JOINT lines, not from throng), frame by frame with ids 0..n-1, each row's time its
  frame / fps. The heading is continuous (not wrapped) through an avoid crowd's turns.
- Two runs give byte-identical files, and so do --threads 1 and --threads 2.
- Both or neither: joints to a full device (/dev/full) fails with exit 2 and one line, and
  the trajectories' file that already existed keeps its old bytes, with no temporary left.
- Nothing goes to stdout; stderr has the summary line, and progress lines for a run that
  takes over a second.
- SIGINT or SIGTERM during a long run ends it by that signal and leaves no file behind; so
  does SIGPIPE when the reader of `--joints-out -` stops early.
Prints "simulate_files: PASS", or the first failure and exits 1. Standard library only.
"""
import argparse
import csv
import filecmp
import os
import pathlib
import re
import shutil
import signal
import subprocess
import sys
import time

TRAJECTORY_HEADER = "id,frame,time,x,y,z,heading,speed"
JOINTS_HEADER = "id,frame,time,joint,name,x,y,z"
SET = ["idle.bvh", "slow_walk.bvh", "walk.bvh", "run.bvh"]  # the project's own set, the default crowd


def fail(message):
    print(f"simulate_files: FAIL: {message}")
    sys.exit(1)


def run(throng, *args, expect=0):
    done = subprocess.run([throng, "simulate", *args], capture_output=True, text=True)
    if done.returncode != expect:
        fail(f"{' '.join(args)}: exit {done.returncode}, expected {expect}; stderr: {done.stderr}")
    return done


def bvh_joints(path):
    return sum(1 for line in path.read_text().splitlines() if re.match(r"\s*(ROOT|JOINT)\s", line))


def check_rows(path, header, characters, frames, fps, joints=None):
    with open(path, newline="") as f:
        lines = f.read().split("\n")
    if lines[0] != header:
        fail(f"{path.name}: header {lines[0]!r}, expected {header!r}")
    if lines[-1] != "":
        fail(f"{path.name}: does not end with a line break")
    rows = list(csv.reader(lines[1:-1]))
    per_frame = characters * (joints or 1)
    if len(rows) != per_frame * frames:
        fail(f"{path.name}: {len(rows)} rows, expected {characters} x {frames}" + (f" x {joints}" if joints else ""))
    for n, row in enumerate(rows):
        frame, rest = divmod(n, per_frame)
        character, joint = divmod(rest, joints or 1)
        if len(row) != len(header.split(",")):
            fail(f"{path.name}: row {n + 2} has {len(row)} fields")
        if int(row[0]) != character or int(row[1]) != frame or abs(float(row[2]) - frame / fps) > 1e-6:
            fail(f"{path.name}: row {n + 2} is {row[:3]}, expected character {character}, frame {frame}")
        if joints and int(row[3]) != joint:
            fail(f"{path.name}: row {n + 2} has joint {row[3]}, expected {joint}")
    return rows


def check_layouts(throng, work, joints):
    issue = ["--characters", "1", "--mode", "group", "--speed", "1.8", "--time", "8", "--fps", "60"]
    a, b = work / "a", work / "b"
    for folder in (a, b):
        folder.mkdir()
        done = run(throng, *issue, "--out", str(folder / "t.csv"), "--joints-out", str(folder / "j.csv"))
        if done.stdout:
            fail(f"stdout is not empty: {done.stdout!r}")
    frames = round(8 * 60) + 1
    check_rows(a / "t.csv", TRAJECTORY_HEADER, 1, frames, 60)
    names = {row[4] for row in check_rows(a / "j.csv", JOINTS_HEADER, 1, frames, 60, joints)}
    if len(names) != joints:
        fail(f"j.csv names {len(names)} joints, expected {joints}")
    for name in ("t.csv", "j.csv"):
        if not filecmp.cmp(a / name, b / name, shallow=False):
            fail(f"two runs wrote different {name}")
    # A crowd steering to goals: several characters, another rate, any thread count.
    crowd = ["-n", "3", "--mode", "goals", "--seed", "5", "--time", "2", "--fps", "25"]
    for threads in ("1", "2"):
        run(throng, *crowd, "--threads", threads, "--out", str(work / f"g{threads}.csv"), "--joints-out", str(work / f"gj{threads}.csv"))
    check_rows(work / "g1.csv", TRAJECTORY_HEADER, 3, 51, 25)
    check_heading_continuous(throng, work)
    check_rows(work / "gj1.csv", JOINTS_HEADER, 3, 51, 25, joints)
    for one, two in (("g1.csv", "g2.csv"), ("gj1.csv", "gj2.csv")):
        if not filecmp.cmp(work / one, work / two, shallow=False):
            fail(f"--threads 1 and 2 wrote different files ({one}, {two})")


def check_heading_continuous(throng, work):
    """The heading is not wrapped: an avoid crowd that turns round has no 2 pi jump in it."""
    path = work / "turning.csv"
    run(throng, "-n", "200", "--mode", "avoid", "--seed", "3", "--time", "10", "--fps", "25", "--out", str(path))
    last, jump, beyond_pi = {}, 0.0, 0
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            heading = float(row["heading"])
            if row["id"] in last:
                jump = max(jump, abs(heading - last[row["id"]]))
            last[row["id"]] = heading
            beyond_pi += abs(heading) > 3.1416
    if jump > 0.5:
        fail(f"turning.csv: a heading jumps by {jump:.3f} rad between frames")
    if not beyond_pi:
        fail("turning.csv: no heading passes pi, so the check shows nothing")


def check_both_or_neither(throng, work):
    folder = work / "full"
    folder.mkdir()
    (folder / "t.csv").write_bytes(b"old\n")
    os.symlink("/dev/full", folder / "full")
    done = run(throng, "-n", "2", "--time", "1", "--fps", "30", "--out", str(folder / "t.csv"),
               "--joints-out", str(folder / "full"), expect=2)
    if done.stderr.count("\n") != 1 or "No space left on device" not in done.stderr:
        fail(f"a full device: expected one line naming ENOSPC, got {done.stderr!r}")
    if (folder / "t.csv").read_bytes() != b"old\n":
        fail("a failed run changed the existing --out file")
    if sorted(p.name for p in folder.iterdir()) != ["full", "t.csv"]:
        fail(f"a failed run left {sorted(p.name for p in folder.iterdir())}")


def check_progress(throng, work):
    # A short run says one line, the summary; a run past a second also reports its progress.
    done = run(throng, "-n", "2", "--time", "1", "--fps", "30", "--out", str(work / "short.csv"))
    if not re.fullmatch(r"throng: wrote .*short\.csv: 62 rows \(2 characters x 31 frames\); 1 s simulated at 30 fps in [0-9.]+ s\n",
                        done.stderr):
        fail(f"a short run: expected the summary alone on stderr, got {done.stderr!r}")
    started = time.monotonic()
    done = run(throng, "-n", "2000", "--time", "60", "--fps", "30", "--out", os.devnull)
    took = time.monotonic() - started
    if done.stdout:
        fail(f"stdout is not empty: {done.stdout!r}")
    progress = [int(p) for p in re.findall(r"^throng: simulate: (\d+)% \(frame \d+ of 1800\) in ", done.stderr, re.M)]
    if progress != sorted(set(progress)) or (took > 1.5 and not progress) or (took < 0.9 and progress):
        fail(f"progress lines {progress} for a run of {took:.1f} s: {done.stderr!r}")
    if not re.search(r"^throng: wrote /dev/null: 3602000 rows \(2000 characters x 1801 frames\)", done.stderr, re.M):
        fail(f"no summary line: {done.stderr!r}")


def check_signals(throng, work):
    for sig in (signal.SIGINT, signal.SIGTERM):
        folder = work / f"signal{int(sig)}"
        folder.mkdir()
        # SIGINT's default disposition, whatever ctest's shell gave this script. 200 characters
        # for 10 minutes at 30 fps: 1.1e8 joint rows, under the limit, and minutes of work.
        child = subprocess.Popen([throng, "simulate", "-n", "200", "--time", "600", "--fps", "30", "--out", str(folder / "t.csv"),
                                  "--joints-out", str(folder / "j.csv")], stderr=subprocess.PIPE, text=True,
                                 preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
        deadline = time.monotonic() + 20
        while time.monotonic() < deadline and child.poll() is None and not any(p.stat().st_size > 0 for p in folder.iterdir()):
            time.sleep(0.05)
        if child.poll() is not None or not any(".tmp-" in p.name for p in folder.iterdir()):
            child.kill()
            fail(f"the long run never wrote to its temporaries: {child.communicate()[1]!r}")
        child.send_signal(sig)
        code = child.wait(timeout=20)
        child.stderr.close()
        if code != -sig:
            fail(f"{sig.name}: exit status {code}, expected death by the signal")
        if list(folder.iterdir()):
            fail(f"{sig.name} left {[p.name for p in folder.iterdir()]}")
    # A reader of stdout that stops early: SIGPIPE, and the other file's temporary goes too.
    folder = work / "pipe"
    folder.mkdir()
    child = subprocess.Popen([throng, "simulate", "-n", "200", "--time", "600", "--fps", "30", "--out", str(folder / "t.csv"),
                              "--joints-out", "-"], stdout=subprocess.PIPE, stderr=subprocess.DEVNULL)
    child.stdout.read(100)
    child.stdout.close()
    code = child.wait(timeout=20)
    if code != -signal.SIGPIPE or list(folder.iterdir()):
        fail(f"a closed stdout: exit status {code}, left {[p.name for p in folder.iterdir()]}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--throng", required=True)
    parser.add_argument("--dir", required=True, type=pathlib.Path)
    parser.add_argument("--asset-dir", required=True, type=pathlib.Path)
    args = parser.parse_args()
    counts = {bvh_joints(args.asset_dir / name) for name in SET}
    if len(counts) != 1:
        fail(f"the project's set has clips of different joint counts: {counts}")
    shutil.rmtree(args.dir, ignore_errors=True)
    args.dir.mkdir(parents=True)
    check_layouts(args.throng, args.dir, counts.pop())
    check_both_or_neither(args.throng, args.dir)
    check_progress(args.throng, args.dir)
    check_signals(args.throng, args.dir)
    shutil.rmtree(args.dir, ignore_errors=True)
    print("simulate_files: PASS")


if __name__ == "__main__":
    main()
