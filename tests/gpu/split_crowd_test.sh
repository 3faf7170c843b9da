#!/bin/sh
# A crowd past one storage buffer is drawn in batches (#14). THRONG_STORAGE_BUFFER_LIMIT lowers
# the device's limit so 1000 characters split into 3 or 4 batches, and each path and body must
# draw the same image as the unsplit crowd (a pixel may differ by a rounding step where two
# bones' rims meet in another order).
#   split_crowd_test.sh THRONG IMAGE_COMPARE OUT_DIR
set -eu
throng=$1 compare=$2 out=$3
mkdir -p "$out"
common="--device llvmpipe --characters 1000 --time 1 --width 320 --height 240 --camera 0,3,-8,0,1,4,50"
for case in "spheres compute" "spheres fast" "spheres cpu" "spheres paper" "bones fast" "skin fast" "auto fast"; do
    set -- $case
    name=$1_$2
    # shellcheck disable=SC2086
    "$throng" render $common --body "$1" --path "$2" --out "$out/$name.png" 2>/dev/null
    # shellcheck disable=SC2086
    summary=$(THRONG_STORAGE_BUFFER_LIMIT=700000 "$throng" render $common --body "$1" --path "$2" --out "$out/${name}_split.png" 2>&1)
    case "$summary" in
        *" batches"*) ;;
        *) echo "split_crowd: $name: not split into batches: $summary: FAIL"; exit 1 ;;
    esac
    "$compare" "$out/${name}_split.png" "$out/$name.png" --tolerance 2 --max-fraction 0.0005 --failure-dir "$out/$name-failure" >/dev/null
    echo "split_crowd: $name: $(echo "$summary" | grep -o 'in [0-9]* batches') match the unsplit render: PASS"
done
