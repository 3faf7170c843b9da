#!/usr/bin/env python3
"""The demo's recording (#15), registered as window.demo_records; on lavapipe under Xvfb with the
validation layer on (any message fails). The R key and the Record button are pressed by
window.demo_every_control; this test checks what they write, through --record.

  recording_test.py --throng BIN --xvfb-run X --dir DIR

- `demo --frames 90 --record rec.mp4` in a 641x361 window: 90 fixed 1/60 s steps are 1.5 s of
  demo time, so the MP4 holds the frames due at 0, 1/30, ... 44/30 s: 45 H.264 frames of
  640x360 (the window cropped to even sizes) at 30 fps. Its last frame shows the demo's end:
  against the --screenshot of the last frame (one 1/60 s step later) it scores at least 25 dB
  PSNR, and at least 5 dB more than the first frame does, so the video follows the demo.
- `--record frames/%03d.png` writes 15 numbered PNGs for 30 steps (frames due at 0..14/30 s).
- A resize ends a recording, saved at the size it started with, with a line that says so, and
  the demo goes on to exit 0.
- SIGINT while recording leaves no file and no temporary.
- `--record` into a missing folder, to a file that is not a video, or to a bad frame pattern:
  exit 2 and one line.
Prints "recording_test: PASS", or the first failure and exits 1.
"""
import argparse
import os
import pathlib
import re
import shutil
import signal
import subprocess
import sys
import time

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
import video_checks  # noqa: E402  (tests/video_checks.py)

SCREEN = "-screen 0 1280x800x24"


def fail(message):
    print(f"recording_test: FAIL: {message}")
    sys.exit(1)


def run(args, expect=0, **kwargs):
    done = subprocess.run([str(a) for a in args], capture_output=True, text=True, timeout=200, **kwargs)
    if done.returncode != expect:
        fail(f"{' '.join(map(str, args))} exited {done.returncode}, expected {expect}: {done.stderr.strip()[-2000:]}")
    if "validation:" in done.stderr:
        fail(f"validation messages: {done.stderr[-2000:]}")
    return done


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--throng", required=True)
    parser.add_argument("--xvfb-run", required=True)
    parser.add_argument("--dir", required=True)
    args = parser.parse_args()
    out = pathlib.Path(args.dir)
    shutil.rmtree(out, ignore_errors=True)  # a rerun starts from nothing
    out.mkdir(parents=True)
    os.environ.update(LP_NUM_THREADS="2", THRONG_VALIDATION="1", ASAN_OPTIONS="detect_leaks=0")
    demo = [args.xvfb_run, "-a", "-s", SCREEN, args.throng, "demo", "--device", "llvmpipe", "-n", "200"]

    # A whole scripted run, and its last frame as a screenshot.
    video, shot = out / "rec.mp4", out / "last.png"
    done = run([*demo, "--width", "641", "--height", "361", "--hide-ui", "--frames", "90", "--record", video, "--screenshot", shot])
    if not re.search(r"^throng: saved .*rec\.mp4: 45 frames, 1\.5 s at 30 fps, 45 of them drawn ", done.stderr, re.M):
        fail(f"no 'saved ... rec.mp4: 45 frames' line: {done.stderr[-1000:]}")
    found = tuple(video_checks.probe(video, fail))
    if found != ("h264", 640, 360, "30/1", 45):
        fail(f"the recording decodes to {found}, not 45 h264 frames of 640x360 at 30/1")
    last, first = (video_checks.psnr(video, frame, shot, fail, crop=(640, 360)) for frame in (44, 0))
    print(f"recording_test: against the last frame's screenshot: last video frame {last:.2f} dB, first {first:.2f} dB")
    if last < 25 or last < first + 5:
        fail(f"the recording's last frame is not the demo's end: {last:.2f} dB (first frame {first:.2f} dB)")

    # A frame folder.
    frames = out / "frames"
    frames.mkdir()
    run([*demo, "--width", "320", "--height", "180", "--frames", "30", "--record", frames / "%03d.png"])
    names = sorted(p.name for p in frames.iterdir())
    if names != [f"{i:03d}.png" for i in range(15)]:
        fail(f"--record frames/%03d.png wrote {names}, not 000.png .. 014.png")

    # A resize ends the recording, saved at its first size.
    resized = out / "resized.mp4"
    done = run([*demo, "--frames", "120", "--script-resize", "--record", resized])
    if "the window changed size, so the recording ends here" not in done.stderr:
        fail(f"no line about the resize ending the recording: {done.stderr[-1000:]}")
    # The first resize comes at frame 30 of 120: about 15 video frames at the first size (a
    # frame or two either way, as the resize lands between frames).
    codec, width, height, _, count = video_checks.probe(resized, fail)
    if (codec, width, height) != ("h264", 1280, 720) or not 12 <= count <= 17:
        fail(f"the resized run's recording is {count} {codec} frames of {width}x{height}, not 12-17 frames of 1280x720")

    # SIGINT while recording: no file, no temporary.
    interrupted = out / "interrupted"
    interrupted.mkdir()
    log = out / "interrupted.stderr"
    with open(log, "w") as stderr:
        process = subprocess.Popen([*map(str, demo), "--record", str(interrupted / "long.mp4")], stdout=subprocess.DEVNULL,
                                   stderr=stderr, start_new_session=True)
    deadline = time.monotonic() + 60
    while not list(interrupted.iterdir()):  # the recording's temporary appears once it has started
        if process.poll() is not None or time.monotonic() > deadline:
            process.kill()
            fail(f"the demo never started recording: {log.read_text()[-1000:]}")
        time.sleep(0.1)
    time.sleep(2)
    # The demo, not xvfb-run: the signal a terminal's Ctrl-C sends to the demo's process.
    demo_pid = run(["pgrep", "-s", str(process.pid), "-x", "throng"]).stdout.split()[0]
    os.kill(int(demo_pid), signal.SIGINT)
    try:
        process.wait(timeout=60)
    except subprocess.TimeoutExpired:
        os.killpg(process.pid, signal.SIGKILL)
        fail("the demo did not end within 60 s of SIGINT")
    if process.returncode == 0:
        fail(f"the interrupted demo exited 0, as if it had finished: {log.read_text()[-1000:]}")
    left = list(interrupted.iterdir())
    if left:
        fail(f"SIGINT while recording left {left}")

    # Refused before anything is drawn.
    for record, why in [(out / "missing" / "a.mp4", "directory .* does not exist"), (out / "a.txt", "--record writes a video"),
                        (out / "%s.png", "a frame pattern takes one frame number")]:
        done = run([*demo, "--frames", "5", "--record", record], expect=2)
        if not re.search(why, done.stderr) or record.exists():
            fail(f"--record {record}: expected exit 2 saying '{why}' and no file: {done.stderr.strip()}")
    print("recording_test: PASS")


if __name__ == "__main__":
    main()
