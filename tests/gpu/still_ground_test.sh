#!/bin/sh
# A still camera keeps the ground (shaders/shading_tiles.glsl): each frame of a video on the
# visibility path draws over the last one and shades again only the 64-pixel squares where a
# body or a contact shadow is or was, painting the sky back where one had stood in it. Its
# visibility buffer is filled one frame in 15 (the keys' epochs, shaders/visibility.glsl), and a
# part starts the count again at its first frame, so a part starting at frame 33 meets the
# whole run's fills at other frames (30 and 45). So a part of a video, whose first frame is drawn
# fresh, must match the whole run frame for frame:
#  - bone bodies seen from a pedestrian's eye, their heads against the sky (the sky painted back);
#  - skinned bodies from above (drawn over the shading: their squares are drawn again after);
#  - joint spheres.
# The summary must say that a still camera's last frame kept some squares, and a camera moving
# every frame none.
#   still_ground_test.sh THRONG OUT_DIR
set -eu
throng=$1 out=$2
fail() { echo "still_ground: $*: FAIL"; exit 1; }
rm -rf "$out"
mkdir -p "$out"
common="--device llvmpipe --path visibility --width 640 --height 360 --duration 1.5 --fps 30"
check_part() {  # name, then the render's options: frames 33-44 drawn alone against the whole run
    name=$1
    shift
    mkdir -p "$out/$name/whole" "$out/$name/part"
    # shellcheck disable=SC2086
    summary=$("$throng" render $common "$@" --out "$out/$name/whole/%05d.png" 2>&1) || fail "$name: the whole run failed: $summary"
    kept=$(echo "$summary" | sed -n 's/.*its last frame kept the ground of \([0-9]*\) squares.*/\1/p')
    [ -n "$kept" ] && [ "$kept" -ge 1 ] || fail "$name: a still camera's last frame kept no square of the one before: $summary"
    # shellcheck disable=SC2086
    "$throng" render $common "$@" --frames 33:44 --out "$out/$name/part/%05d.png" 2>/dev/null || fail "$name: the part failed"
    frame=33
    while [ "$frame" -le 44 ]; do
        file=$(printf '%05d.png' "$frame")
        cmp -s "$out/$name/whole/$file" "$out/$name/part/$file" || fail "$name: frame $frame drawn over the last differs from it drawn fresh"
        frame=$((frame + 1))
    done
    report="$report $name kept $kept,"
}
report=""
check_part bones --body bones --characters 60 --camera 0,1.2,-14,0,1.5,0
check_part skin --body skin --characters 40 --view overview
check_part spheres --body spheres --characters 300 --view overview
cat >"$out/moving.json" <<'JSON'
{"camera_path": [{"time": 0, "eye": [0, 20, -60], "target": [0, 0, 0], "fov": 40},
                 {"time": 2, "eye": [30, 20, -50], "target": [0, 0, 0]}]}
JSON
mkdir -p "$out/moving"
summary=$("$throng" render $common --characters 300 --camera-path "$out/moving.json" --out "$out/moving/%05d.png" 2>&1) || fail "the moving camera's run failed: $summary"
echo "$summary" | grep -q "its last frame kept the ground of 0 squares" || fail "a camera moving every frame kept squares of the frame before: $summary"
echo "still_ground:$report parts drawn fresh match the whole runs; a moving camera kept none: PASS"
