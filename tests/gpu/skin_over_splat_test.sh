#!/bin/sh
# Skinned bodies on the visibility path (#14) are drawn after a shading pass that writes no
# depth: each fragment tests itself against the splat's distance at its pixel and the ground
# plane (shaders/skin_shading.glsl). The fast path draws the same skins into a depth buffer
# that holds the rasterised ground. With skinned bodies only and one sample, the two differ in
# the contact shadows' rounding alone: a sole below the ground would show in dozens of pixels
# (48 when the ground's test is left out). With skinned bodies only, nothing is splatted but
# the contact shadows, so this holds the ground's part of the test, not the splat's (`auto`
# draws a nearer character at a coarser level than a farther one only where their builds
# differ across the skin threshold, which no scene here sets up).
#   skin_over_splat_test.sh THRONG IMAGE_COMPARE OUT_DIR
set -eu
throng=$1 compare=$2 out=$3
mkdir -p "$out"
for path in fast visibility; do
    "$throng" render --device llvmpipe --body skin --msaa 1 -n 50 --path "$path" --out "$out/$path.png"
done
if "$compare" "$out/visibility.png" "$out/fast.png" --tolerance 12 --max-fraction 0.000005 --failure-dir "$out"; then
    echo "skin_over_splat: PASS"
else
    echo "skin_over_splat: FAIL"
fi
