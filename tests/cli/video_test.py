#!/usr/bin/env python3
"""`throng render --duration` (#15), registered in video.cmake; on lavapipe with validation on.

  video_test.py --throng BIN --dir DIR

- A 2-second 30 fps MP4 of 200 characters decodes with FFmpeg's tools (ffprobe) to 60 H.264
  frames of the asked size, and its first frame equals `throng render --time 0` of the same
  crowd within the codec's error (PSNR >= 35 dB, FFmpeg's psnr filter).
- A 1-second 10 fps GIF decodes to 10 frames of the asked size, its first and last frames
  within PSNR 30 dB of their single renders (256 colours, dithered), and a second run gives
  the same bytes.
- SIGINT in the middle of a long video ends it by that signal and leaves no file, and no
  temporary, in the output folder.
- With --camera-path, frames 0 and 30 of a 30 fps video are byte-identical to `render --time 0`
  and `--time 1` with the same path, and differ from each other (the camera moved).
- Frames 0-29 and 30-59, rendered by two processes that GNU parallel runs, are byte-identical
  to frames 0-59 of one run; MP4 parts of the same ranges join with FFmpeg's concat demuxer,
  without re-encoding, into 60 frames.
Prints "video_test: PASS", or the first failure and exits 1.
"""
import argparse
import filecmp
import pathlib
import shutil
import signal
import subprocess
import sys
import time

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
import video_checks  # noqa: E402  (tests/video_checks.py)


def fail(message):
    print(f"video_test: FAIL: {message}")
    sys.exit(1)


def run(args, **kwargs):
    done = subprocess.run([str(a) for a in args], capture_output=True, text=True, timeout=280, **kwargs)
    if done.returncode != 0:
        fail(f"{' '.join(map(str, args))} exited {done.returncode}: {done.stderr.strip()[-2000:]}")
    return done


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--throng", required=True)
    parser.add_argument("--dir", required=True)
    args = parser.parse_args()
    out = pathlib.Path(args.dir)
    shutil.rmtree(out, ignore_errors=True)  # a rerun starts from nothing
    out.mkdir(parents=True)
    throng = args.throng
    crowd = ["--device", "llvmpipe", "-n", "200", "--width", "320", "--height", "180"]

    # The video, and the first frame as one image.
    video = out / "crowd.mp4"
    run([throng, "render", *crowd, "--duration", "2", "--fps", "30", "--out", video])
    codec, width, height, _, frames = video_checks.probe(video, fail)
    if (codec, width, height, frames) != ("h264", 320, 180, 60):
        fail(f"the MP4 decodes to {frames} {codec} frames of {width}x{height}, not 60 h264 frames of 320x180")
    first = out / "first.png"
    run([throng, "render", *crowd, "--time", "0", "--out", first])
    psnr = video_checks.psnr(video, 0, first, fail)
    print(f"video_test: first frame against render --time 0: PSNR {psnr:.2f} dB")
    if psnr < 35:
        fail(f"the first frame differs from render --time 0: PSNR {psnr:.2f} dB < 35")

    # A GIF: 256 colours from the first frame, dithered; close to the render (PSNR >= 30 dB), and
    # the same bytes from the same run.
    gif, again = out / "crowd.gif", out / "again.gif"
    fixed = [*crowd, "--camera", "0,12,-30,0,0,0,40"]  # a later frame is its single render only with the camera given
    for target in (gif, again):
        run([throng, "render", *fixed, "--duration", "1", "--fps", "10", "--out", target])
    found = video_checks.probe(gif, fail)
    if (found.codec, found.width, found.height, found.frames) != ("gif", 320, 180, 10):
        fail(f"the GIF decodes to {found}, not 10 gif frames of 320x180")
    if not filecmp.cmp(gif, again, shallow=False):
        fail("two runs of the same GIF differ")
    # Its first frame, and its last (written against the previous frame, with the
    # encoder's transparency for unchanged pixels), each against its single render.
    at_0, at_9 = out / "gif_at_0.png", out / "gif_at_0.9.png"
    run([throng, "render", *fixed, "--time", "0", "--out", at_0])
    run([throng, "render", *fixed, "--time", "0.9", "--out", at_9])
    for frame, image in ((0, at_0), (9, at_9)):
        gif_psnr = video_checks.psnr(gif, frame, image, fail)
        print(f"video_test: GIF frame {frame} against its single render: PSNR {gif_psnr:.2f} dB")
        if gif_psnr < 30:
            fail(f"GIF frame {frame} differs from its single render: PSNR {gif_psnr:.2f} dB < 30")

    # Interrupted: no file, no temporary.
    folder = out / "interrupted"
    folder.mkdir()
    process = subprocess.Popen([throng, "render", *crowd, "--duration", "60", "--out", folder / "long.mp4"],
                               stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    time.sleep(3.0)
    if process.poll() is not None:
        fail(f"the long render ended before it was interrupted: {process.stderr.read()}")
    process.send_signal(signal.SIGINT)
    process.wait(timeout=60)
    if process.returncode != -signal.SIGINT:
        fail(f"an interrupted render exited {process.returncode}, not by SIGINT")
    left = list(folder.iterdir())
    if left:
        fail(f"an interrupted render left {[p.name for p in left]}")

    # Split renders through GNU parallel, against one whole run.
    small = ["--device", "llvmpipe", "-n", "50", "--mode", "avoid", "--width", "160", "--height", "90", "--duration", "2", "--fps", "30"]
    (out / "whole").mkdir()
    (out / "split").mkdir()
    run([throng, "render", *small, "--out", out / "whole" / "%05d.png"])
    run(["parallel", "--halt", "now,fail=1", throng, "render", *small, "--frames", "{}", "--out", out / "split" / "%05d.png", ":::", "0:29", "30:59"])
    for frame in range(60):
        name = f"{frame:05d}.png"
        if not (out / "split" / name).is_file() or not filecmp.cmp(out / "whole" / name, out / "split" / name, shallow=False):
            fail(f"frame {name} of the split render is missing or differs from the whole run's")
    if len(list((out / "split").iterdir())) != 60:
        fail("the split render wrote other files than frames 0-59")
    run(["parallel", "--halt", "now,fail=1", throng, "render", *small, "--frames", "{1}", "--out", out / "part_{2}.mp4", ":::", "0:29", "30:59",
         ":::+", "a", "b"])
    (out / "parts.txt").write_text(f"file '{out / 'part_a.mp4'}'\nfile '{out / 'part_b.mp4'}'\n")
    joined = out / "joined.mp4"
    run(["ffmpeg", "-v", "error", "-y", "-f", "concat", "-safe", "0", "-i", out / "parts.txt", "-c", "copy", joined])
    codec, width, height, _, frames = video_checks.probe(joined, fail)
    if (codec, frames) != ("h264", 60):
        fail(f"the joined parts decode to {frames} {codec} frames, not 60 h264 frames")
    # A camera path: frame f of a 30 fps video is `render --time f/30` with the same path (the
    # crowd stepped the same 1/30 s steps), at the first keyframe and at the second; and the
    # camera moved between them. Joint spheres: bodies cross-fade between levels over frames,
    # which a still has none of, and this camera changes every character's size on screen.
    path = out / "camera_path.json"
    path.write_text('{"camera_path": [{"time": 0, "eye": [0, 12, -30], "target": [0, 0, 0], "fov": 40},'
                    ' {"time": 1, "eye": [25, 3, -10], "target": [0, 1, 0], "fov": 30}]}')
    moving = ["--device", "llvmpipe", "-n", "50", "--body", "spheres", "--width", "160", "--height", "90", "--camera-path", path]
    (out / "moving").mkdir()
    run([throng, "render", *moving, "--duration", "1.1", "--out", out / "moving" / "%03d.png"])
    for frame, seconds in ((0, "0"), (30, "1")):
        single = out / f"moving_at_{seconds}.png"
        run([throng, "render", *moving, "--time", seconds, "--out", single])
        if not filecmp.cmp(out / "moving" / f"{frame:03d}.png", single, shallow=False):
            fail(f"frame {frame} of the camera-path video differs from render --time {seconds} with the same path")
    if filecmp.cmp(out / "moving" / "000.png", out / "moving" / "030.png", shallow=False):
        fail("the camera path's two keyframes gave the same picture: the camera did not move")
    print("video_test: PASS")


if __name__ == "__main__":
    main()
