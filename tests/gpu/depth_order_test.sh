#!/bin/sh
# Depth where bodies cross (#13): two characters overlapping on screen, B's centre DEPTH metres
# behind A's and SIDE metres to the side, rendered with each body in BODIES and with the
# paper's joint spheres as the reference; check_depth_order compares which one is in front at
# every pixel both bodies cover.
#   depth_order_test.sh THRONG CHECK_DEPTH_ORDER WALK_BVH OUT_DIR DEPTH SIDE MIN_AGREEMENT BODIES...
set -eu
throng=$1 check=$2 walk=$3 out=$4 depth=$5 side=$6 agreement=$7
shift 7
walk=$(cd "$(dirname "$walk")" && pwd)/$(basename "$walk")  # scene paths are relative to the scene
mkdir -p "$out"

# One scene per variant; a character left out stands 30 m behind the camera (each in its own
# spot, so placement never redraws), so the seed's draws (start frames, builds, clothing) are
# the same in all four.
scene() {  # scene NAME A_CENTRE B_CENTRE
    cat > "$out/$1.json" <<EOF
{
  "clips": [{"name": "walk", "path": "$walk"}],
  "seed": 5,
  "groups": [
    {"count": 1, "clips": ["walk"], "heading": 90, "region": {"centre": $2, "size": [0.2, 0.2]}},
    {"count": 1, "clips": ["walk"], "heading": 90, "region": {"centre": $3, "size": [0.2, 0.2]}}
  ],
  "camera": {"eye": [0.4, 1.5, -3.6], "target": [0.2, 0.95, 0.5], "fov": 42}
}
EOF
}
away_a="[-5, -30]" away_b="[5, -30]"
scene both "[0, 0]" "[$side, $depth]"
scene a "[0, 0]" "$away_b"
scene b "$away_a" "[$side, $depth]"
scene none "$away_a" "$away_b"

for body in spheres "$@"; do
    for variant in both a b none; do
        "$throng" render --device llvmpipe --body "$body" --msaa 1 --time 0.4 --width 640 --height 480 \
            --scene "$out/$variant.json" --out "$out/${body}_$variant.png"
    done
done
for body in "$@"; do
    "$check" "$out/spheres" "$out/$body" --min-agreement "$agreement"
done
