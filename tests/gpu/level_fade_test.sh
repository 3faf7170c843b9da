#!/bin/sh
# Cross-fades between levels of detail run over frames (shaders/lod_fade.glsl): a video of a
# walking crowd has a few characters at two levels in some frame (those crossing a threshold),
# far fewer than the distance band the fade once was drew; a still has none, so it matches the
# video's first frame; and a part of the video, which first draws the frames its cross-fades
# depend on, matches the whole run frame for frame. Then a camera that cuts from far to near at
# frame 15 sets many characters fading at once, and a part from frame 17 must match the whole
# run there too: drawn without the frames before it, every character would start at its level.
# Bone bodies alone never fade, so their parts draw no frame before their first, and still match.
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

mkdir -p "$out/cut_whole" "$out/cut_part"
cat >"$out/cut.json" <<'JSON'
{"camera_path": [{"time": 0, "eye": [0, 30, -90], "target": [0, 0, 0], "fov": 40},
                 {"time": 0.49, "eye": [0, 30, -90], "target": [0, 0, 0]},
                 {"time": 0.5, "eye": [0, 3, -18], "target": [0, 1, 0]}]}
JSON
cut="$video --camera-path $out/cut.json"
# shellcheck disable=SC2086
summary=$("$throng" render $cut --out "$out/cut_whole/%05d.png" 2>&1) || fail "the cut's whole run failed: $summary"
cutMost=$(echo "$summary" | sed -n 's/.*at most \([0-9]*\) cross-fading between levels in a frame.*/\1/p')
[ -n "$cutMost" ] && [ "$cutMost" -ge 10 ] || fail "a cut from far to near set fewer than 10 characters fading: $summary"
# shellcheck disable=SC2086
"$throng" render $cut --frames 17:29 --out "$out/cut_part/%05d.png" 2>/dev/null || fail "the cut's part failed"
for frame in 17 18 19 20 21 22 29; do
    name=$(printf '%05d.png' "$frame")
    cmp -s "$out/cut_whole/$name" "$out/cut_part/$name" || fail "frame $frame of the part after the cut differs from the whole run's"
done
mkdir -p "$out/bones_whole" "$out/bones_part"
bones=$(echo "$cut" | sed 's/--body auto/--body bones/')
# shellcheck disable=SC2086
"$throng" render $bones --out "$out/bones_whole/%05d.png" 2>/dev/null || fail "the bone bodies' whole run failed"
# shellcheck disable=SC2086
"$throng" render $bones --frames 17:29 --out "$out/bones_part/%05d.png" 2>/dev/null || fail "the bone bodies' part failed"
for frame in 17 18 29; do
    name=$(printf '%05d.png' "$frame")
    cmp -s "$out/bones_whole/$name" "$out/bones_part/$name" || fail "frame $frame of a part of bone bodies differs from the whole run's"
done
echo "level_fade: at most $most of 300 characters cross-fading in a frame, $cutMost after a cut; the still is the first frame; parts drawn alone match the whole run: PASS"
