"""FFmpeg's tools on a video, shared by the Python tests of videos and recordings
(tests/cli/video_test.py, tests/window/recording_test.py). Standard library; needs ffprobe and
ffmpeg (Debian's ffmpeg package, installed by tools/setup.sh)."""
import collections
import re
import subprocess

Probe = collections.namedtuple("Probe", "codec width height rate frames")


def _run(args, fail):
    done = subprocess.run([str(a) for a in args], capture_output=True, text=True, timeout=280)
    if done.returncode != 0:
        fail(f"{' '.join(map(str, args))} exited {done.returncode}: {done.stderr.strip()[-2000:]}")
    return done


def probe(path, fail):
    """The first video stream's codec, size, frame rate (as "30/1") and decoded frame count."""
    done = _run(["ffprobe", "-v", "error", "-count_frames", "-select_streams", "v:0", "-show_entries",
                 "stream=codec_name,width,height,r_frame_rate,nb_read_frames", "-of", "csv=p=0", path], fail)
    codec, width, height, rate, frames = done.stdout.strip().split(",")
    return Probe(codec, int(width), int(height), rate, int(frames))


def psnr(video, frame, image, fail, crop=None):
    """FFmpeg's PSNR (dB) of the video's frame number `frame` against the image, or against its
    top-left `crop` = (width, height) part."""
    reference = f"[1:v]crop={crop[0]}:{crop[1]}:0:0[b]" if crop else "[1:v]null[b]"
    done = _run(["ffmpeg", "-v", "info", "-nostats", "-i", video, "-i", image, "-lavfi",
                 f"[0:v]trim=start_frame={frame}:end_frame={frame + 1},setpts=PTS-STARTPTS[a];{reference};[a][b]psnr",
                 "-f", "null", "-"], fail)
    found = re.search(r"PSNR .*average:([0-9.]+|inf)", done.stderr)
    if not found:
        fail(f"ffmpeg printed no PSNR: {done.stderr[-500:]}")
    return float(found.group(1))
