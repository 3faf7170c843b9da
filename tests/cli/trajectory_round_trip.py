#!/usr/bin/env python3
"""Round trip of trajectories (#15), registered in trajectories.cmake.

  trajectory_round_trip.py --throng BIN --dir DIR

`throng simulate` writes an avoid crowd's trajectories; `throng render --trajectories` reads
them back and dumps the GPU-resolved characters (--dump-instances) at sampled times, on
lavapipe with the validation layer (THRONG_VALIDATION=1 in the test's environment). Every
character's ground position must be within 1 cm of the file's row at that time, and
`throng simulate --trajectories` must write the same positions back. The checks read only the
files. Prints "trajectory_round_trip: PASS", or the first failure and exits 1.
"""
import argparse
import csv
import json
import math
import pathlib
import subprocess
import sys

FPS = 10
TIMES = [0.0, 1.3, 2.9]  # seconds, on the file's samples


def fail(message):
    print(f"trajectory_round_trip: FAIL: {message}")
    sys.exit(1)


def run(args):
    done = subprocess.run(args, capture_output=True, text=True, timeout=240)
    if done.returncode != 0:
        fail(f"{' '.join(map(str, args))} exited {done.returncode}: {done.stderr.strip()}")
    return done


def rows_by_frame(path, first_id=0):
    """{frame: {character: (x, z)}}, the character being the row's id less `first_id`."""
    frames = {}
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            frames.setdefault(int(row["frame"]), {})[int(row["id"]) - first_id] = (float(row["x"]), float(row["z"]))
    return frames


def expect_same_crowd(back, expected, what):
    """Every character of `back` within 1 cm of `expected` at every frame."""
    for frame, rows in expected.items():
        for index, (fx, fz) in rows.items():
            x, z = back[frame][index]
            if math.hypot(x - fx, z - fz) > 0.01:
                fail(f"{what} puts character {index} at ({x}, {z}) at frame {frame}, the CSV says ({fx}, {fz})")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--throng", required=True)
    parser.add_argument("--dir", required=True)
    args = parser.parse_args()
    out = pathlib.Path(args.dir)
    out.mkdir(parents=True, exist_ok=True)
    written = out / "avoid.csv"
    run([args.throng, "simulate", "-n", "30", "--mode", "avoid", "--seed", "7", "--time", "3", "--fps", str(FPS), "--out", written])
    expected = rows_by_frame(written)
    worst = 0.0
    for time in TIMES:
        dump = out / f"dump_{time}.json"
        done = run([args.throng, "render", "--trajectories", written, "--time", str(time), "--width", "160", "--height", "90",
                    "--device", "llvmpipe", "--dump-instances", dump, "--out", out / f"frame_{time}.png"])
        if "trajectories" not in done.stderr or "ground plane x,z" not in done.stderr:
            fail(f"render did not say what it detected: {done.stderr.strip()}")
        characters = json.loads(dump.read_text())["characters"]
        rows = expected[round(time * FPS)]
        if len(characters) != len(rows):
            fail(f"at {time} s the dump has {len(characters)} characters, the file {len(rows)}")
        for character in characters:
            x, z = character["ground"][0], character["ground"][1]
            fx, fz = rows[character["index"]]
            error = math.hypot(x - fx, z - fz)
            worst = max(worst, error)
            if error > 0.01:
                fail(f"at {time} s character {character['index']} is at ({x:.4f}, {z:.4f}), the file says ({fx:.4f}, {fz:.4f})")
    again = out / "again.csv"
    run([args.throng, "simulate", "--trajectories", written, "--time", "3", "--fps", str(FPS), "--out", again])
    expect_same_crowd(rows_by_frame(again), expected, "simulate --trajectories")
    # The JuPedSim/PedPy text layout: what PedPy needs (comment lines first, a framerate, the
    # unit, rows of ID FR X Y Z), ids from 1, X and Y the ground with Y = -z; read back by
    # --trajectories, it gives the same crowd.
    text = out / "avoid.txt"
    run([args.throng, "simulate", "-n", "30", "--mode", "avoid", "--seed", "7", "--time", "3", "--fps", str(FPS), "--format", "jupedsim",
         "--out", text])
    lines = text.read_text().splitlines()
    header = [line for line in lines if line.startswith("#")]
    rows = [line.split() for line in lines if line and not line.startswith("#")]
    if not lines[0].startswith("#") or f"#framerate: {FPS}" not in header or not any("in metres" in line for line in header):
        fail(f"the jupedsim header lacks what PedPy reads: {header}")
    if "#ID\tFR\tX\tY\tZ" not in header:
        fail("the jupedsim header has no '#ID FR X Y Z' column line")
    if len(rows) != 30 * (3 * FPS + 1) or any(len(row) != 5 for row in rows):
        fail(f"the jupedsim file has {len(rows)} rows, or rows without 5 fields")
    for row in rows:
        ident, frame, x, y = int(row[0]), int(row[1]), float(row[2]), float(row[3])
        fx, fz = expected[frame][ident - 1]
        if math.hypot(x - fx, -y - fz) > 1e-5:
            fail(f"jupedsim row {row} is not character {ident - 1} of the CSV at frame {frame} ({fx}, {fz})")
    from_text = out / "from_text.csv"
    done = run([args.throng, "simulate", "--trajectories", text, "--time", "3", "--fps", str(FPS), "--out", from_text])
    if "JuPedSim/PedPy text" not in done.stderr:
        fail(f"--trajectories did not detect the text layout: {done.stderr.strip()}")
    # A follower keeps its file's id: the text layout's, character index + 1.
    expect_same_crowd(rows_by_frame(from_text, first_id=1), expected, "the jupedsim file read back")
    print(f"trajectory_round_trip: worst distance from the file {100 * worst:.4f} cm")
    print("trajectory_round_trip: PASS")


if __name__ == "__main__":
    main()
