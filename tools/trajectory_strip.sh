#!/usr/bin/env bash
# Four frames of a trajectory file as throng renders it, 2 x 2, for the README:
#
#   tools/trajectory_strip.sh TRAJECTORIES OUT.png [SECONDS...] -- [render options...]
#
# Renders `throng render --trajectories TRAJECTORIES --time T` at each of the four SECONDS
# (default 0 3 6 9), 480 x 270 each, and tiles them with FFmpeg (hstack, vstack) into OUT.png.
# Frame f of `render --duration ... --out FILE.mp4` is the single render of its time, so the
# tiles are frames of the video the README's command makes. THRONG names the binary (default
# build/release/throng).
set -euo pipefail
[ $# -ge 2 ] || { echo "usage: $0 TRAJECTORIES OUT.png [SECONDS...] -- [render options...]" >&2; exit 2; }
trajectories=$1 out=$2
shift 2
times=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do times+=("$1"); shift; done
[ $# -gt 0 ] && shift  # the --
[ ${#times[@]} -gt 0 ] || times=(0 3 6 9)
[ ${#times[@]} -eq 4 ] || { echo "$0: give four times, not ${#times[@]}" >&2; exit 2; }
throng=${THRONG:-build/release/throng}
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
inputs=()
for i in 0 1 2 3; do
    "$throng" render --trajectories "$trajectories" --time "${times[$i]}" --width 480 --height 270 "$@" \
        --out "$scratch/$i.png" 2>"$scratch/log" || { cat "$scratch/log" >&2; exit 1; }
    inputs+=(-i "$scratch/$i.png")
done
ffmpeg -v error -y "${inputs[@]}" -filter_complex "[0][1]hstack[top];[2][3]hstack[bottom];[top][bottom]vstack" \
    -frames:v 1 "$scratch/strip.png"
mv "$scratch/strip.png" "$out"
