#!/bin/sh
# Throng's frame time as a ratio of the naive reference renderer's (#14, "How speed is stated"):
# ../shared/probe (impostors, no culling, no LOD, no MSAA) at 2000 characters, run before and
# after `throng bench --no-readback` in the same session on the same device (the probe's timed
# frames don't read their image back either), and each Throng row divided by
# the probe's time (the mean of its two medians, so a drift in the machine's load between
# them is split). With ROUNDS, the two alternate and the medians of the rounds are given.
# A benchmark: it prints figures and asserts nothing.
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
  ROUNDS          Throng runs, each between two probe runs (default: 1); past 1, every
                  figure is the median of the rounds', and each round's ratio is printed too
  LP_NUM_THREADS  lavapipe's threads         (default: 2)
  TABLE           also write the table as CSV to this file (a "# caption" line first: the
                  device and the probe's times), with each row's lowest and highest ratio
                  of the rounds; tools/plot_probe_ratio plots it

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
rounds=${ROUNDS:-1}
table=${TABLE:-}
case "$rounds" in
    [1-9] | [1-9][0-9] | 100) ;;
    *) echo "bench_against_probe: ROUNDS must be a whole number from 1 to 100, not '$rounds'" >&2; exit 2 ;;
esac
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

# Rounds alternate the two programs, the probe first and last: probe, Throng, probe, Throng, ...,
# probe. Each Throng round is divided by the mean of the probe runs either side of it, so a
# machine whose speed drifts during the run (a shared VM's does, by 40% within minutes) moves
# both sides of each ratio alike; the table gives the median of the rounds' ratios.
probes="$scratch/probe.txt"
: >"$probes"
probe_once() {
    value=$(run_probe)
    [ -n "$value" ] || { echo "bench_against_probe: the probe printed no 2000-character row" >&2; exit 1; }
    echo "$value" >>"$probes"
}
probe_once
round=1
while [ "$round" -le "$rounds" ]; do
    # --no-readback: the probe's timed frames don't copy their image back to the host either.
    "$throng" bench --modes "$modes" -n "$characters" --frames "$frames" --warmup "$warmup" --no-readback --csv "$scratch/throng-$round.csv" "$@" >"$scratch/throng.txt"
    probe_once
    round=$((round + 1))
done

grep '^# device' "$scratch/throng-1.csv" | sed 's/^# //'
if [ "$rounds" -eq 1 ]; then
    echo "probe (impostors, no MSAA) at 2000 characters: $(sed -n 1p "$probes") ms before, $(sed -n 2p "$probes") ms after"
else
    echo "probe (impostors, no MSAA) at 2000 characters, ms, in order: $(tr '\n' ' ' <"$probes")($rounds rounds)"
fi
# Every round's rows, each with its round and its probe time (the mean of the runs either side),
# in one stream: the probe times first, then each round's CSV.
round=1
while [ "$round" -le "$rounds" ]; do
    awk -F, -v round="$round" '!/^#/ && $1 != "mode" { print round "," $0 }' "$scratch/throng-$round.csv"
    round=$((round + 1))
done | awk -F, -v rounds="$rounds" -v probeFile="$probes" -v tableFile="$scratch/table.csv" '
    function median(values, n,    i, j, t) {
        for (i = 2; i <= n; ++i)
            for (j = i; j > 1 && values[j - 1] > values[j]; --j) { t = values[j]; values[j] = values[j - 1]; values[j - 1] = t }
        return n % 2 ? values[(n + 1) / 2] : (values[n / 2] + values[n / 2 + 1]) / 2
    }
    BEGIN {
        runs = 0
        while ((getline line < probeFile) > 0) probe[++runs] = line + 0
        printf "%-11s %10s %10s %10s %10s %10s %10s %9s %s\n", "mode", "characters", "frame_ms", "compute_ms", "splat_ms", "draw_ms", "shading_ms", "x_probe", "target"
    }
    {
        # Columns (after the round): 4 frame, 10 compute, 11 draw, 17 and 18 the visibility
        # path splat and shading within them.
        key = $2 SUBSEP $3
        if (!(key in count)) { order[++rows] = key; name[key] = $2; size[key] = $3 }
        n = ++count[key]
        frame[key, n] = $4; compute[key, n] = $10; splat[key, n] = $17; draw[key, n] = $11; shading[key, n] = $18
        ratio[key, n] = $4 / ((probe[$1] + probe[$1 + 1]) / 2)
    }
    END {
        for (r = 1; r <= rows; ++r) {
            key = order[r]
            n = count[key]
            split("", a); split("", b); split("", c); split("", d); split("", e); split("", x)
            for (i = 1; i <= n; ++i) { a[i] = frame[key, i]; b[i] = compute[key, i]; c[i] = splat[key, i]; d[i] = draw[key, i]; e[i] = shading[key, i]; x[i] = ratio[key, i] }
            target = size[key] == 2000 ? "<= 0.2" : size[key] == 10000 ? "<= 0.5" : ""
            printf "%-11s %10d %10.2f %10.2f %10.2f %10.2f %10.2f %9.3f %s\n", name[key], size[key], median(a, n), median(b, n), median(c, n),
                   median(d, n), median(e, n), median(x, n), target
            low = high = x[1]
            for (i = 2; i <= n; ++i) { low = x[i] < low ? x[i] : low; high = x[i] > high ? x[i] : high }
            if (r == 1) print "mode,characters,frame_ms,compute_ms,splat_ms,draw_ms,shading_ms,x_probe,x_probe_lowest,x_probe_highest,target" > tableFile
            printf "%s,%d,%.2f,%.2f,%.2f,%.2f,%.2f,%.3f,%.3f,%.3f,%s\n", name[key], size[key], median(a, n), median(b, n), median(c, n),
                   median(d, n), median(e, n), median(x, n), low, high, size[key] == 2000 ? 0.2 : size[key] == 10000 ? 0.5 : "" > tableFile
            if (rounds > 1) {
                line = ""
                for (i = 1; i <= n; ++i) line = line sprintf(" %.3f", ratio[key, i])
                rounds_line[r] = sprintf("%-11s %10d  x_probe by round:%s", name[key], size[key], line)
            }
        }
        if (rounds > 1) {
            print "medians of " rounds " rounds; each round against the mean of the probe runs either side of it:"
            for (r = 1; r <= rows; ++r) print rounds_line[r]
        }
    }'
if [ -n "$table" ]; then
    {
        echo "# $(grep '^# device' "$scratch/throng-1.csv" | sed 's/^# //'); probe at 2000 characters, ms: $(tr '\n' ' ' <"$probes" | sed 's/ $//')"
        cat "$scratch/table.csv"
    } >"$table.tmp" && mv "$table.tmp" "$table"
    echo "bench_against_probe: wrote $table"
fi
