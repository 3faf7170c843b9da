#!/bin/sh
# Cross-fades between levels of detail run over frames (shaders/lod_fade.glsl): a video of a
# walking crowd has a few characters at two levels in some frame (those crossing a threshold),
# far fewer than the distance band the fade once was drew; a still has none, so it matches the
# video's first frame; and a part of the video, which first draws the frames its cross-fades
# depend on, matches the whole run frame for frame (without those frames its first frame
# differs).
#   level_fade_test.sh THRONG OUT_DIR
set -eu
throng=$1 out=$2
fail() { echo "level_fade: $*: FAIL"; exit 1; }
rm -rf "$out"
mkdir -p "$out/whole" "$out/part"
common="--device llvmpipe --body auto --characters 300 --width 320 --height 180"
video="$common --duration 1 --fps 30"
# shellcheck disable=SC2086
summary=$("$throng" render $video --out "$out/whole/%05d.png" 2>&1) || fail "the whole run failed: $summary"
most=$(echo "$summary" | sed -n 's/.*at most \([0-9]*\) cross-fading between levels in a frame.*/\1/p')
[ -n "$most" ] || fail "the summary does not say how many characters cross-fade: $summary"
[ "$most" -ge 1 ] || fail "no character cross-faded in 30 frames of a walking crowd"
[ "$most" -le 30 ] || fail "$most of 300 characters cross-faded in one frame (more than the few crossing a threshold)"
# shellcheck disable=SC2086
"$throng" render $common --out "$out/still.png" 2>/dev/null || fail "the still failed"
cmp -s "$out/still.png" "$out/whole/00000.png" || fail "the still differs from the video's first frame"
# shellcheck disable=SC2086
"$throng" render $video --frames 15:29 --out "$out/part/%05d.png" 2>/dev/null || fail "the part failed"
frame=15
while [ "$frame" -le 29 ]; do
    name=$(printf '%05d.png' "$frame")
    cmp -s "$out/whole/$name" "$out/part/$name" || fail "frame $frame of the part (frames 15-29) differs from the whole run's"
    frame=$((frame + 1))
done
[ "$(ls "$out/part" | wc -l)" -eq 15 ] || fail "the part wrote other files than frames 15-29"
echo "level_fade: at most $most of 300 characters cross-fading in a frame; the still is the first frame; frames 15-29 drawn alone match the whole run: PASS"
