#!/usr/bin/env bash
# tools/bench_against_probe.sh's arithmetic, with stand-ins for the probe and for throng that
# print known times in turn: each round's ratio is its Throng frame over the mean of the probe
# runs either side of it, the table gives the medians, one round keeps the before/after line,
# and a ROUNDS that is no count is refused before anything runs. TABLE keeps the table as CSV
# with each row's lowest and highest round, and tools/plot_probe_ratio plots it.
# Usage: bench_against_probe_test.sh REPOSITORY SCRATCH
set -euo pipefail
repository=$1 scratch=$2
fail() { echo "bench_against_probe_test: FAIL: $*" >&2; exit 1; }
rm -rf "$scratch"
mkdir -p "$scratch/probe"

# The probe stand-in: its Makefile builds nothing; ./probe prints the next of PROBE_TIMES as the
# 2000-character row's median frame (CSV column 8), counting its runs in PROBE_RUNS.
cat >"$scratch/probe/Makefile" <<'EOF'
all:
	@true
EOF
cat >"$scratch/probe/probe" <<'EOF'
#!/bin/sh
run=$(($(cat "$PROBE_RUNS") + 1))
echo "$run" >"$PROBE_RUNS"
echo "mode,n,mesh,frames,warmup,min_ms,max_ms,wall_median_ms"
echo "full,2000,impostor,3,1,0,0,$(echo "$PROBE_TIMES" | cut -d' ' -f"$run")"
EOF
# The throng stand-in: `bench ... --csv FILE` writes a 2000-character row whose frame (column 3)
# is the next of THRONG_TIMES and whose compute, draw, splat and shading (9, 10, 16, 17) follow
# from it.
cat >"$scratch/throng" <<'EOF'
#!/bin/sh
run=$(($(cat "$THRONG_RUNS") + 1))
echo "$run" >"$THRONG_RUNS"
frame=$(echo "$THRONG_TIMES" | cut -d' ' -f"$run")
while [ "$#" -gt 0 ] && [ "$1" != "--csv" ]; do shift; done
{
    echo "# device stand-in, LP_NUM_THREADS=2"
    echo "mode,characters,frame_ms,c4,c5,c6,c7,c8,compute,draw,c11,c12,c13,c14,c15,splat,shading"
    echo "visibility,2000,$frame,0,0,0,0,0,1,$((frame - 1)),0,0,0,0,0,0.5,$((frame - 2))"
    echo "visibility,10000,$((frame + 10)),0,0,0,0,0,2,$((frame + 9)),0,0,0,0,0,1,$((frame + 8))"
} >"$2"
EOF
chmod +x "$scratch/probe/probe" "$scratch/throng"

run() {  # ROUNDS, then the probe's times and throng's, each space-separated, in the order run
    echo 0 >"$scratch/probe-runs"
    echo 0 >"$scratch/throng-runs"
    ROUNDS=$1 PROBE_TIMES=$2 THRONG_TIMES=$3 TABLE=${TABLE:-} PROBE_RUNS="$scratch/probe-runs" THRONG_RUNS="$scratch/throng-runs" \
        THRONG="$scratch/throng" PROBE_SOURCE="$scratch/probe" sh "$repository/tools/bench_against_probe.sh" 2>&1
}
# The table's row for N characters (not the rounds' lines, whose third field is "x_probe").
row() { echo "$1" | awk -v n="${2:-2000}" '$1 == "visibility" && $2 == n && $3 ~ /^[0-9.]+$/'; }

# Three rounds between four probe runs of 40, 60, 50 and 70 ms: Throng's 10, 12 and 11 ms
# are 10/50, 12/55 and 11/60 of the probe.
out=$(TABLE="$scratch/table.csv" run 3 "40 60 50 70" "10 12 11") || fail "three rounds: exit $?: $out"
[ "$(cat "$scratch/probe-runs")" = 4 ] || fail "three rounds ran the probe $(cat "$scratch/probe-runs") times, not 4"
[ "$(cat "$scratch/throng-runs")" = 3 ] || fail "three rounds ran throng $(cat "$scratch/throng-runs") times, not 3"
echo "$out" | grep -q "ms, in order: 40 60 50 70 (3 rounds)" || fail "no list of the probe's runs: $out"
table=$(row "$out")
# frame 11 (median of 10 12 11), compute 1, splat 0.5, draw 10, shading 9, ratio median(0.200, 0.218, 0.183)
echo "$table" | awk '{ exit !($3 == "11.00" && $4 == "1.00" && $5 == "0.50" && $6 == "10.00" && $7 == "9.00" && $8 == "0.200" && $9 == "<=") }' ||
    fail "the medians' row is not frame 11, compute 1, splat 0.5, draw 10, shading 9, x_probe 0.200: '$table'"
echo "$out" | grep -q "2000  x_probe by round: 0.200 0.218 0.183$" || fail "the rounds' ratios are not 0.200 0.218 0.183: $out"
# The 10,000-character row, gathered across the rounds apart from the 2000 one: 20, 22 and 21 ms
# are 0.400, 0.400 and 0.350 of the probe.
table=$(row "$out" 10000)
echo "$table" | awk '{ exit !($3 == "21.00" && $4 == "2.00" && $8 == "0.400" && $9 == "<=") }' ||
    fail "the 10,000-character row is not frame 21, compute 2, x_probe 0.400: '$table'"
echo "$out" | grep -q "10000  x_probe by round: 0.400 0.400 0.350$" || fail "the 10,000 rounds' ratios are not 0.400 0.400 0.350: $out"

# The kept table: the caption with the probe's runs, then the medians with the lowest and highest
# round and the target; plotted, it makes a PNG, and a CSV of another shape is refused.
head -n 1 "$scratch/table.csv" | grep -q "^# device stand-in, LP_NUM_THREADS=2; probe at 2000 characters, ms: 40 60 50 70$" ||
    fail "the table's caption is not the device and the probe's runs: $(head -n 1 "$scratch/table.csv")"
grep -qx "visibility,2000,11.00,1.00,0.50,10.00,9.00,0.200,0.183,0.218,0.2" "$scratch/table.csv" ||
    fail "the table's 2000-character row is not the medians, 0.183 to 0.218, target 0.2: $(cat "$scratch/table.csv")"
grep -qx "visibility,10000,21.00,2.00,1.00,20.00,19.00,0.400,0.350,0.400,0.5" "$scratch/table.csv" ||
    fail "the table's 10,000-character row is not the medians, 0.350 to 0.400, target 0.5: $(cat "$scratch/table.csv")"
"$repository/tools/plot_probe_ratio" "$scratch/table.csv" "$scratch/ratio.png" >/dev/null || fail "plot_probe_ratio failed on the table"
[ "$(head -c 8 "$scratch/ratio.png" | od -An -tx1 | tr -d ' ')" = 89504e470d0a1a0a ] || fail "plot_probe_ratio wrote no PNG"
rc=0
"$repository/tools/plot_probe_ratio" "$scratch/probe/Makefile" "$scratch/bad.png" 2>/dev/null || rc=$?
[ "$rc" -eq 2 ] && [ ! -e "$scratch/bad.png" ] || fail "plot_probe_ratio took a file that is no table (exit $rc)"

# One round keeps the before/after line, the ratio against their mean.
out=$(run 1 "50 70" "15") || fail "one round: exit $?: $out"
echo "$out" | grep -q "50 ms before, 70 ms after" || fail "one round lost its before/after line: $out"
row "$out" | awk '{ exit !($8 == "0.250") }' || fail "one round: 15 ms against 60 is not 0.250: $out"
if echo "$out" | grep -q "by round"; then fail "one round printed the rounds' ratios: $out"; fi

# A ROUNDS that is not a count from 1 to 100 is refused (exit 2) before either program runs.
for rounds in 0 x 101 -1 1.5; do
    rc=0
    out=$(run "$rounds" "50 70" "15") || rc=$?
    [ "$rc" -eq 2 ] || fail "ROUNDS='$rounds' exited $rc, not 2: $out"
    echo "$out" | grep -q "ROUNDS must be a whole number from 1 to 100" || fail "ROUNDS='$rounds' gave no clear message: $out"
    [ "$(cat "$scratch/probe-runs")" = 0 ] || fail "ROUNDS='$rounds' ran the probe"
done
echo "bench_against_probe_test: ok"
