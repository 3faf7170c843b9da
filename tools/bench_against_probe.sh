#!/bin/sh
# Throng's frame time as a ratio of the naive reference renderer's (#14, "How speed is stated"):
# ../shared/probe (impostors, no culling, no LOD, no MSAA) at 2000 characters, run before and
# after `throng bench --no-readback` in the same session on the same device (the probe's timed
# frames don't read their image back either), and each Throng row divided by
# the probe's time (the mean of its two medians, so a drift in the machine's load between
# them is split). A benchmark: it prints figures and asserts nothing.
set -eu

usage() {
    cat <<'EOF'
usage: tools/bench_against_probe.sh [throng bench options...]

Builds ../shared/probe into a scratch folder (it needs only Debian's packages, which
tools/setup.sh installs), runs it at 2000 characters, then `throng bench`, then the probe
again, and prints every Throng row's median frame time beside its ratio to the probe's at
2000 characters, with #14's targets (2000 characters <= 0.2, 10,000 <= 0.5).

Environment:
  THRONG          the throng binary          (default: build/release/throng under the repository)
  PROBE_SOURCE    the probe's sources        (default: ../shared/probe beside the repository)
  MODES           render paths               (default: fast,visibility)
  CHARACTERS      crowd sizes                (default: 2000,10000)
  FRAMES, WARMUP  timed and untimed frames   (default: 10 and 3, for both programs)
  LP_NUM_THREADS  lavapipe's threads         (default: 2)

Other options go to `throng bench` as they are, e.g. --msaa 1 --body spheres. Don't give
--modes, -n, --frames, --warmup or --csv: the script sets them.
EOF
}
case "${1:-}" in -h | --help) usage; exit 0 ;; esac

root=$(cd "$(dirname "$0")/.." && pwd)
throng=${THRONG:-$root/build/release/throng}
probe_source=${PROBE_SOURCE:-$root/../shared/probe}
modes=${MODES:-fast,visibility}
characters=${CHARACTERS:-2000,10000}
frames=${FRAMES:-10}
warmup=${WARMUP:-3}
export LP_NUM_THREADS="${LP_NUM_THREADS:-2}"

[ -x "$throng" ] || { echo "bench_against_probe: no throng binary at $throng (build first, or set THRONG)" >&2; exit 2; }
[ -f "$probe_source/Makefile" ] || { echo "bench_against_probe: no probe sources at $probe_source (set PROBE_SOURCE)" >&2; exit 2; }

scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT INT TERM
# The probe's folder may be read-only (its README says so): build a copy.
cp -R "$probe_source" "$scratch/probe"
make -s -C "$scratch/probe" >"$scratch/probe-build.log" 2>&1 || { cat "$scratch/probe-build.log" >&2; echo "bench_against_probe: the probe did not build" >&2; exit 1; }

run_probe() {
    # CSV: column 2 is N, column 8 the median whole frame (submit + wait), in ms.
    (cd "$scratch/probe" && ./probe --n 2000 --mesh impostor --modes full --frames "$frames" --warmup "$warmup") |
        awk -F, '$2 == "2000" { print $8 }'
}

before=$(run_probe)
# --no-readback: the probe's timed frames don't copy their image back to the host either.
"$throng" bench --modes "$modes" -n "$characters" --frames "$frames" --warmup "$warmup" --no-readback --csv "$scratch/throng.csv" "$@" >"$scratch/throng.txt"
after=$(run_probe)
[ -n "$before" ] && [ -n "$after" ] || { echo "bench_against_probe: the probe printed no 2000-character row" >&2; exit 1; }

grep '^# device' "$scratch/throng.csv" | sed 's/^# //'
echo "probe (impostors, no MSAA) at 2000 characters: $before ms before, $after ms after"
awk -F, -v before="$before" -v after="$after" '
    BEGIN {
        probe = (before + after) / 2
        printf "%-11s %10s %10s %10s %10s %10s %10s %9s %s\n", "mode", "characters", "frame_ms", "compute_ms", "splat_ms", "draw_ms", "shading_ms", "x_probe", "target"
    }
    /^#/ || $1 == "mode" { next }
    {
        # Columns: 9 compute, 10 draw, 16 and 17 the visibility path splat and shading within them.
        target = $2 == 2000 ? "<= 0.2" : $2 == 10000 ? "<= 0.5" : ""
        printf "%-11s %10d %10.2f %10.2f %10.2f %10.2f %10.2f %9.3f %s\n", $1, $2, $3, $9, $16, $10, $17, $3 / probe, target
    }' "$scratch/throng.csv"
