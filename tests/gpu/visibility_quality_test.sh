#!/bin/sh
# The visibility path's picture against the fast path's at the default 4x MSAA (#14: a cheaper
# anti-aliasing must look at least as good). The visibility path draws with one sample and
# smooths its rims analytically; the fast path without multisampling is the same ray-cast
# spheres with no smoothing at all. So, on the default crowd:
#   - the visibility path differs from fast at 4x in fewer pixels than fast at 1x does
#     (measured 1.08% against 1.81%): its smoothing does what four samples do;
#   - against 16 samples a pixel (fast at 4x MSAA, rendered at twice the size with the level of
#     detail's threshold doubled to match, then averaged down by FFmpeg's area filter), it
#     differs in fewer pixels than fast at 4x does (measured 18,971 against 27,526): at least
#     as good as four samples;
#   - it draws the same bytes whatever --msaa asks for (samples would change no pixel).
#   visibility_quality_test.sh THRONG IMAGE_COMPARE OUT_DIR
set -eu
throng=$1 compare=$2 out=$3
mkdir -p "$out"
"$throng" render --device llvmpipe --path fast --body spheres --msaa 4 --out "$out/fast4.png" 2>/dev/null
"$throng" render --device llvmpipe --path fast --body spheres --msaa 1 --out "$out/fast1.png" 2>/dev/null
"$throng" render --device llvmpipe --path visibility --body spheres --msaa 4 --out "$out/visibility4.png" 2>/dev/null
"$throng" render --device llvmpipe --path visibility --body spheres --msaa 1 --out "$out/visibility1.png" 2>/dev/null
if ! cmp -s "$out/visibility4.png" "$out/visibility1.png"; then
    echo "visibility_quality: --msaa 4 and --msaa 1 drew different images: FAIL"
    exit 1
fi
# image_compare's report: "differing=N (P%)"; a loose tolerance counts only real differences.
differing() { "$compare" "$1" "$2" --tolerance 24 --max-fraction 1 --failure-dir "$out/unused" | sed -n 's/.*differing=\([0-9]*\) .*/\1/p'; }
# closer REFERENCE WHAT OTHER OTHER_NAME: the visibility path's picture differs from REFERENCE
# (described by WHAT) in fewer pixels than OTHER does, and OTHER in at least 1000 (a real gap).
closer() {
    visibility=$(differing "$out/visibility1.png" "$1")
    other=$(differing "$3" "$1")
    echo "visibility_quality: pixels differing from $2: visibility $visibility, $4 $other"
    if [ -z "$visibility" ] || [ -z "$other" ] || [ "$other" -lt 1000 ] || [ "$visibility" -ge "$other" ]; then
        echo "visibility_quality: the visibility path is not closer to $2 than $4 is: FAIL"
        exit 1
    fi
}
closer "$out/fast4.png" "fast at 4x MSAA" "$out/fast1.png" "fast at 1x"
"$throng" render --device llvmpipe --path fast --body spheres --msaa 4 --width 2560 --height 1440 --lod-pixels 96 --out "$out/fast4_double.png" 2>/dev/null
ffmpeg -loglevel error -y -i "$out/fast4_double.png" -vf scale=1280:720:flags=area "$out/samples16.png"
closer "$out/samples16.png" "16 samples a pixel" "$out/fast4.png" "fast at 4x"
echo "visibility_quality: PASS"
