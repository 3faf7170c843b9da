"""The command line and the `throng simulate` run that the Python tests of simulate share
(tests/gpu/simulate_matches_render.py, tests/quality/simulate_physics.py). Standard library only."""
import argparse
import pathlib
import shutil
import subprocess


def arguments(doc):
    """--throng BIN --dir DIR, with DIR emptied and made."""
    parser = argparse.ArgumentParser(description=doc.splitlines()[0])
    parser.add_argument("--throng", required=True)
    parser.add_argument("--dir", required=True, type=pathlib.Path)
    args = parser.parse_args()
    shutil.rmtree(args.dir, ignore_errors=True)
    args.dir.mkdir(parents=True)
    return args


def simulate(throng, directory, options, fail):
    """Runs `throng simulate OPTIONS` into DIR/t.csv and DIR/j.csv; calls fail(message) on a non-zero exit."""
    trajectory, joints = directory / "t.csv", directory / "j.csv"
    command = [throng, "simulate", *options, "--out", str(trajectory), "--joints-out", str(joints)]
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode != 0:
        fail(f"{' '.join(command)}: exit {done.returncode}: {done.stderr}")
    return trajectory, joints
