#!/usr/bin/env python3
"""`throng simulate` moves the crowd `throng render` draws, and places its joints where the
GPU does: the same options and seed, rendered at --time 0 and --time 1 with --dump-instances
(joints resolved by the compute pass on lavapipe), against simulate's rows at the same times
(--fps 30: the same 1/30 s steps render takes).

  simulate_matches_render.py --throng BIN --dir DIR

Each character's ground position and heading within 1e-4 (m, rad), each joint within 1e-4 of
the clip's height. Prints the largest differences and "simulate_matches_render: PASS".
"""
import csv
import json
import math
import pathlib
import shutil
import subprocess
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
import simulate_run  # noqa: E402  (tests/simulate_run.py)

CROWD = ["--characters", "12", "--mode", "goals", "--seed", "7", "--speed", "0.5:2.5"]


def fail(message):
    print(f"simulate_matches_render: FAIL: {message}")
    sys.exit(1)


def run(command):
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode != 0:
        fail(f"{' '.join(command)}: exit {done.returncode}: {done.stderr}")


def main():
    args = simulate_run.arguments(__doc__)
    t, j = simulate_run.simulate(args.throng, args.dir, [*CROWD, "--time", "1", "--fps", "30"], fail)
    with open(t, newline="") as f:
        ground = {(int(r["id"]), int(r["frame"])): r for r in csv.DictReader(f)}
    with open(j, newline="") as f:
        joints = {(int(r["id"]), int(r["frame"]), int(r["joint"])): r for r in csv.DictReader(f)}
    worst_ground = worst_joint = 0.0
    for seconds, frame in (("0", 0), ("1", 30)):
        dump = args.dir / f"render{frame}.json"
        run([args.throng, "render", "--device", "llvmpipe", *CROWD, "--time", seconds, "--width", "32", "--height", "32",
             "--dump-instances", str(dump), "--out", str(args.dir / f"render{frame}.png")])
        instances = json.loads(dump.read_text())
        height = max(clip["height"] for clip in instances["clips"])
        if len(instances["characters"]) != 12:
            fail(f"render drew {len(instances['characters'])} characters, expected 12")
        for character in instances["characters"]:
            m = character["index"]
            row = ground[(m, frame)]
            x, z, yaw = character["ground"]
            worst_ground = max(worst_ground, abs(x - float(row["x"])), abs(z - float(row["z"])),
                               abs(math.remainder(yaw - float(row["heading"]), 2 * math.pi)))
            for joint, position in zip(character["joints"], character["positions"]):
                sampled = joints[(m, frame, joint)]
                worst_joint = max(worst_joint, max(abs(p - float(sampled[k])) for p, k in zip(position, "xyz")) / height)
    print(f"simulate_matches_render: ground {worst_ground:.2e} m or rad, joints {worst_joint:.2e} of the height apart")
    if worst_ground > 1e-4 or worst_joint > 1e-4:
        fail("simulate and render disagree")
    shutil.rmtree(args.dir, ignore_errors=True)
    print("simulate_matches_render: PASS")


if __name__ == "__main__":
    main()
