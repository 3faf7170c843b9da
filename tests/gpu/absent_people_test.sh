#!/bin/sh
# People whose trajectory has not started yet (or has ended) draw nothing on any render path
# or body: a crowd of one walker, and the same walker with a second person whose track starts
# at 2 s right in front of the camera, give byte-identical images at 1 s; at 2.5 s, when the
# second person is there, the images differ (so the check can't pass by drawing nobody).
#   absent_people_test.sh THRONG OUT_DIR
set -eu
throng=$1
out=$2
mkdir -p "$out"
{
    echo "id,time,x,y"
    k=0
    while [ $k -le 40 ]; do echo "1,$(awk "BEGIN{print $k/10}"),$(awk "BEGIN{print $k*0.12}"),0"; k=$((k + 1)); done
} > "$out/one.csv"
cp "$out/one.csv" "$out/two.csv"
k=20
while [ $k -le 40 ]; do echo "2,$(awk "BEGIN{print $k/10}"),1,$(awk "BEGIN{print -2+$k*0.05}")" >> "$out/two.csv"; k=$((k + 1)); done
render() {  # file time label options...
    file=$1 time=$2 label=$3
    shift 3
    "$throng" render --device llvmpipe --trajectories "$out/$file.csv" --time "$time" --camera 2,1.6,6,1,1,0 --width 160 --height 90 \
        "$@" --out "$out/$label.png" 2>/dev/null
}
for case in "fast_spheres:--path fast --body spheres" "compute:--path compute" "paper:--path paper" "cpu:--path cpu" \
            "visibility_spheres:--path visibility --body spheres" "fast_auto:--path fast --body auto" \
            "visibility_auto:--path visibility --body auto"; do
    name=${case%%:*}
    options=${case#*:}
    # shellcheck disable=SC2086  # the options are words
    render one 1 "${name}_one" $options
    # shellcheck disable=SC2086
    render two 1 "${name}_two" $options
    cmp -s "$out/${name}_one.png" "$out/${name}_two.png" || { echo "absent_people: FAIL: $name draws a person before their track starts"; exit 1; }
    # shellcheck disable=SC2086
    render one 2.5 "${name}_one_later" $options
    # shellcheck disable=SC2086
    render two 2.5 "${name}_two_later" $options
    if cmp -s "$out/${name}_one_later.png" "$out/${name}_two_later.png"; then
        echo "absent_people: FAIL: $name does not draw the second person once their track has started"
        exit 1
    fi
done
echo "absent_people: PASS"
