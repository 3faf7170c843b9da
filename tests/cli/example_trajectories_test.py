#!/usr/bin/env python3
"""assets/trajectories/corridor.csv is what its stated command makes today (#15): the project's
own example, remade by `throng simulate` and compared row by row (same ids, frames and columns;
numbers within 1e-4, as the CSV prints six decimals and another CPU may round the last one
differently).

  example_trajectories_test.py --throng BIN --source-dir DIR --dir SCRATCH
"""
import argparse
import csv
import pathlib
import subprocess
import sys

COMMAND = ["simulate", "--scene", "assets/scenes/corridor.json", "--time", "12", "--fps", "10", "--out"]


def fail(message):
    print(f"example_trajectories_test: FAIL: {message}")
    sys.exit(1)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--throng", required=True)
    parser.add_argument("--source-dir", required=True)
    parser.add_argument("--dir", required=True)
    args = parser.parse_args()
    root, scratch = pathlib.Path(args.source_dir), pathlib.Path(args.dir)
    scratch.mkdir(parents=True, exist_ok=True)
    remade = scratch / "corridor.csv"
    done = subprocess.run([args.throng, *COMMAND, str(remade)], cwd=root, capture_output=True, text=True, timeout=120)
    if done.returncode != 0:
        fail(f"throng {' '.join(COMMAND)} exited {done.returncode}: {done.stderr.strip()}")
    with open(root / "assets/trajectories/corridor.csv") as a, open(remade) as b:
        committed, today = list(csv.reader(a)), list(csv.reader(b))
    if len(committed) != len(today) or committed[0] != today[0]:
        fail(f"{len(committed)} rows with header {committed[0]} committed, {len(today)} with {today[0]} made today")
    for number, (old, new) in enumerate(zip(committed[1:], today[1:]), start=2):
        if len(old) != len(new) or old[:2] != new[:2] or any(abs(float(x) - float(y)) > 1e-4 for x, y in zip(old[2:], new[2:])):
            fail(f"line {number}: committed {old}, made today {new}")
    print(f"example_trajectories_test: PASS ({len(today) - 1} rows match)")


if __name__ == "__main__":
    main()
