#!/bin/sh
# Frames per second of video rendering against single-frame renders of the same frames, in
# one run (#15's benchmark). A benchmark: it prints figures and asserts nothing.
#   tools/bench_video.sh [THRONG]   (CHARACTERS=2000 WIDTH=1280 HEIGHT=720 FRAMES=30 SINGLES=5 FPS=30)
# The video renders FRAMES frames back to back into an MP4 through one offscreen renderer; the
# single renders are `throng render --time T` of SINGLES of those frames, each a whole process
# (crowd load, device, pipelines, one frame, PNG).
set -eu
throng=${1:-build/release/throng}
characters=${CHARACTERS:-2000}
width=${WIDTH:-1280}
height=${HEIGHT:-720}
frames=${FRAMES:-30}
singles=${SINGLES:-5}
fps=${FPS:-30}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
now() { date +%s.%N; }
duration=$(awk "BEGIN{print $frames / $fps}")
start=$(now)
"$throng" render -n "$characters" --width "$width" --height "$height" --duration "$duration" --fps "$fps" --out "$dir/video.mp4" 2>"$dir/video.log"
video=$(awk "BEGIN{print $(now) - $start}")
start=$(now)
k=0
while [ "$k" -lt "$singles" ]; do
    "$throng" render -n "$characters" --width "$width" --height "$height" --time "$(awk "BEGIN{print $k * $frames / $singles / $fps}")" \
        --out "$dir/single_$k.png" 2>/dev/null
    k=$((k + 1))
done
single=$(awk "BEGIN{print $(now) - $start}")
echo "video rendering, $(tail -1 "$dir/video.log" | sed 's/.*characters, //')"
awk "BEGIN{printf \"video:  %d frames in %.2f s, %.2f frames per second (whole process)\n\", $frames, $video, $frames / $video}"
awk "BEGIN{printf \"single: %d renders in %.2f s, %.2f frames per second\n\", $singles, $single, $singles / $single}"
awk "BEGIN{printf \"ratio:  video renders %.1fx the frames per second of single renders\n\", ($frames / $video) / ($singles / $single)}"
