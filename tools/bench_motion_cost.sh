#!/bin/sh
# What motion synthesis costs the compute pass (#12, "Benchmark, not test"): three `throng
# bench` runs back to back, on the same device, crowd size, paths and frame size:
#   a  single clip:           every character plays assets/walk.bvh as it is (the paper's pass)
#   b  blend:                 every character blends the project's set (idle, slow_walk, walk, run)
#   c  blend + transition:    assets/scenes/bench_transitions.json, where every character blends
#                             that set and crossfades from the walk at every timed frame (its first 10 s)
# then the median compute-pass time of each per path and the ratios b/a and c/a (target of
# #12: c/a <= 2). With ROUNDS=N the three run N times in turn (a b c a b c ...) and each figure
# is the median of its N runs' medians: a machine whose load drifts (other builds beside it)
# then slows all three alike instead of whichever ran at the wrong time. A benchmark: it prints figures and asserts nothing; it warns when c did not
# blend and crossfade at every character and frame, as then c would not measure what it says.
set -eu

usage() {
    cat <<'EOF'
usage: tools/bench_motion_cost.sh [throng bench options...]

Runs `throng bench` three times (a: the single walk, b: blending the project's set,
c: blending + transitions, assets/scenes/bench_transitions.json) and prints the median
compute-pass time per render path and the ratios b/a and c/a.

Environment:
  THRONG      the throng binary        (default: build/release/throng under the repository)
  CHARACTERS  crowd size               (default: 10000)
  MODES       render paths to time     (default: compute,fast; the two with a compute pass)
  SPEED       b's desired ground speeds, m/s, as the scene's group has them (default: 1.7:2.3)
  ROUNDS      runs of each, taken in turn a b c a b c ... (default: 1); each figure is then
              the median of its runs' medians, and each run's is shown too

Other options go to every run as they are, e.g. --width 640 --height 360 --frames 10
--warmup 2 --device llvmpipe. Don't give --bvh, --locomotion, --speed, --scene, -n or
--modes: the script sets them.
EOF
}
case "${1:-}" in -h | --help) usage; exit 0 ;; esac

root=$(cd "$(dirname "$0")/.." && pwd)
throng=${THRONG:-$root/build/release/throng}
characters=${CHARACTERS:-10000}
modes=${MODES:-compute,fast}
speed=${SPEED:-1.7:2.3}
rounds=${ROUNDS:-1}
assets=$root/assets
[ -x "$throng" ] || { echo "bench_motion_cost: error: no throng at $throng (build it, or set THRONG)" >&2; exit 2; }
case "$rounds" in '' | *[!0-9]* | 0) echo "bench_motion_cost: error: ROUNDS takes a count from 1, not '$rounds'" >&2; exit 2 ;; esac

out=$(mktemp -d "${TMPDIR:-/tmp}/bench_motion_cost.XXXXXX")
trap 'rm -rf "$out"' EXIT
trap 'exit 130' INT TERM  # through the EXIT trap, so nothing is left behind

run() {  # NAME, then the options that choose the motion
    name=$1
    shift
    echo "bench_motion_cost: $name (round $round of $rounds)..." >&2
    "$throng" bench --characters "$characters" --modes "$modes" "$@" --json "$out/$name.$round.json" >"$out/$name.$round.txt"
}
round=1
while [ "$round" -le "$rounds" ]; do
    run single --bvh "$assets/walk.bvh" "$@"
    run blend --locomotion "$assets/idle.bvh,$assets/slow_walk.bvh,$assets/walk.bvh,$assets/run.bvh" --speed "$speed" "$@"
    run transition --scene "$assets/scenes/bench_transitions.json" "$@"
    round=$((round + 1))
done

python3 - "$out" "$rounds" <<'EOF'
import json, statistics, sys
out, rounds = sys.argv[1], int(sys.argv[2])
names = ("single", "blend", "transition")
runs = {name: [json.load(open(f"{out}/{name}.{r}.json")) for r in range(1, rounds + 1)] for name in names}
first = runs["single"][0]
print(f"device {first['device']} ({first['driver']}), LP_NUM_THREADS={first['lp_threads']}, "
      f"{first['width']}x{first['height']}, {first['msaa']}x MSAA, {first['joints']} joints, {first['build_type']} build")
print(f"median compute pass, ms (a: single clip, b: blend, c: blend + transition; {rounds} run(s) of each"
      f"{', the median of their medians' if rounds > 1 else ''})")
print(f"{'path':<8} {'characters':>10} {'a':>9} {'b':>9} {'c':>9} {'b/a':>6} {'c/a':>6}")
for row in first["rows"]:
    def same(name):  # this row in each run of `name`
        return [next(r for r in run["rows"] if r["mode"] == row["mode"] and r["characters"] == row["characters"]) for run in runs[name]]
    a, b, c = (statistics.median(r["compute_ms_median"] for r in same(name)) for name in names)
    ratio = lambda x: f"{x / a:6.2f}" if a > 0 else "     -"
    print(f"{row['mode']:<8} {row['characters']:>10} {a:9.3f} {b:9.3f} {c:9.3f} {ratio(b)} {ratio(c)}")
    if rounds > 1:
        spread = "  ".join(f"{letter}: " + ", ".join(f"{r['compute_ms_median']:.3f}" for r in same(n)) for letter, n in zip("abc", names))
        print(f"{'':<8} {'runs':>10}  {spread}")
    for shares in same("transition"):
        if shares["blend_share"] < 1 or shares["transition_share"] < 1:
            print(f"bench_motion_cost: warning: c blended at {shares['blend_share']:.3f} and crossfaded at "
                  f"{shares['transition_share']:.3f} of its character-frames, not all", file=sys.stderr)
print("target (#12): c/a <= 2")
EOF
