#!/usr/bin/env python3
"""Physics of `throng simulate`'s output, checked from its CSV alone (standard library only),
so nothing here shares code with what it checks.

  simulate_physics.py --throng BIN --dir DIR

Runs the issue's example, one character of the project's set in group mode at 1.8 m/s for
8 s at 60 fps, and checks:
- the speed column is the distance between consecutive rows over 1/60 s (0 at frame 0);
- the speed blend tracks: the median speed over the last 3 s is within 5% of 1.8 m/s, and so
  is the straight-line distance covered in those 3 s over 3 s;
- the character walks where its heading faces (0 faces +Z, +pi/2 faces +X);
- joints.csv agrees with the trajectory: the ROOT joint (the hips, joint 0) stays within
  0.5 m of the trajectory's x, z at every frame, and y is 0 on the trajectory;
- the feet reach the ground: each foot's lowest joint (ankle or toe) comes within 5 cm of
  y = 0 and never sinks more than 3 cm below it; no joint goes lower than that.
Prints the measured figures and "simulate_physics: PASS", or the first failure and exits 1.
"""
import csv
import math
import pathlib
import shutil
import statistics
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
import simulate_run  # noqa: E402  (tests/simulate_run.py)

SPEED, FPS, SECONDS, TAIL = 1.8, 60, 8, 3


def fail(message):
    print(f"simulate_physics: FAIL: {message}")
    sys.exit(1)


def read(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def check_trajectory(rows):
    dt = 1.0 / FPS
    for before, after in zip(rows, rows[1:]):
        moved = math.hypot(float(after["x"]) - float(before["x"]), float(after["z"]) - float(before["z"])) / dt
        if abs(moved - float(after["speed"])) > 1e-3:
            fail(f"frame {after['frame']}: moved {moved:.6f} m/s, speed column says {after['speed']}")
    if float(rows[0]["speed"]) != 0.0 or any(float(r["y"]) != 0.0 for r in rows):
        fail("frame 0's speed or some y is not 0")
    tail = [r for r in rows if float(r["time"]) >= SECONDS - TAIL - 1e-9]
    median = statistics.median(float(r["speed"]) for r in tail)
    dx, dz = float(tail[-1]["x"]) - float(tail[0]["x"]), float(tail[-1]["z"]) - float(tail[0]["z"])
    covered = math.hypot(dx, dz) / (float(tail[-1]["time"]) - float(tail[0]["time"]))
    print(f"simulate_physics: last {TAIL} s: median speed {median:.4f} m/s, covered {covered:.4f} m/s (wanted {SPEED})")
    for what, value in (("median speed", median), ("distance covered per second", covered)):
        if abs(value - SPEED) > 0.05 * SPEED:
            fail(f"{what} {value:.4f} m/s is not within 5% of {SPEED}")
    heading = float(tail[-1]["heading"])
    off = math.degrees(abs(math.remainder(math.atan2(dx, dz) - heading, 2 * math.pi)))
    print(f"simulate_physics: walks {off:.2f} deg off its heading")
    if off > 10:
        fail(f"walks {off:.1f} deg away from where its heading faces")


def check_joints(trajectory, joints):
    ground = {int(r["frame"]): (float(r["x"]), float(r["z"])) for r in trajectory}
    worst_root, lowest, feet = 0.0, math.inf, {}
    for r in joints:
        x, y, z = float(r["x"]), float(r["y"]), float(r["z"])
        lowest = min(lowest, y)
        if r["joint"] == "0":
            gx, gz = ground[int(r["frame"])]
            worst_root = max(worst_root, math.hypot(x - gx, z - gz))
        name = r["name"].lower()
        if "foot" in name or "toe" in name:
            side = "left" if name.startswith("l") else "right"
            feet[side] = min(feet.get(side, math.inf), y)
    print(f"simulate_physics: root at most {worst_root:.3f} m from the trajectory; feet lowest "
          f"{', '.join(f'{s} {y:.4f} m' for s, y in sorted(feet.items()))}; lowest joint {lowest:.4f} m")
    if worst_root > 0.5:
        fail(f"the root joint strays {worst_root:.3f} m from the trajectory")
    if sorted(feet) != ["left", "right"]:
        fail(f"expected a left and a right foot among the joint names, found {sorted(feet)}")
    for side, y in feet.items():
        if not -0.03 <= y <= 0.05:
            fail(f"the {side} foot's lowest point is {y:.4f} m, not on the ground")
    if lowest < -0.03:
        fail(f"a joint sinks to {lowest:.4f} m, below the ground")


def main():
    args = simulate_run.arguments(__doc__)
    t, j = simulate_run.simulate(args.throng, args.dir, ["--characters", "1", "--mode", "group", "--speed", str(SPEED),
                                                         "--time", str(SECONDS), "--fps", str(FPS)], fail)
    trajectory = read(t)
    if len(trajectory) != SECONDS * FPS + 1:
        fail(f"{len(trajectory)} trajectory rows, expected {SECONDS * FPS + 1}")
    check_trajectory(trajectory)
    check_joints(trajectory, read(j))
    shutil.rmtree(args.dir, ignore_errors=True)
    print("simulate_physics: PASS")


if __name__ == "__main__":
    main()
