#!/usr/bin/env bash
# window.demo_pace_keys: the demo's pace keys change how the crowd moves, pressed as a person
# presses them (XTest key taps through xdotool on an Xvfb display, the validation layer on).
# Up and Down shift every locomotion-set character's desired ground speed by 0.5 m/s
# (issue #12); the blend follows at a bounded acceleration.
#
#   run_pace_test.sh --throng T --xvfb-run X --out-dir D --frames N
#
# Three runs of the default crowd (the project's set: idle, slow walk, walk, run), each in its
# own scratch directory under D, with THRONG_LOG=info for the demo's closing blend line:
#   pace_up    --frames N: Up four times as soon as the window is up. Each press is logged
#              with the crowd's mean desired and actual speed: the desired speed must rise
#              by the step at the first press (the crowd walked at its own speed) and at every
#              press after; at the end of the N fixed 1/60 s frames the crowd must walk at
#              the speed it wants, at least 1.5 m/s faster than before the presses, and the
#              run must weigh at least 80% of the poses.
#   pace_down  the same with Down three times: at the end the crowd stands (under 0.25 m/s)
#              and the idle weighs at least 80%.
#   no_set     --bvh walk.bvh (every character plays one clip): Up must log that the pace
#              keys change nothing, and Esc must still end the run with status 0.
# N must leave the blend time to follow: the presses come within a second or two of the
# window, and idle to run takes about 2 s of crowd time at 1.5 m/s².
set -euo pipefail

# The options, the display, the demo process, input and checks.
source "$(dirname "${BASH_SOURCE[0]}")/demo_driver.sh" "$@"
export THRONG_LOG=info

# Prints "offset wants walks" for every pace line the demo logged (one per press), in order.
press_lines() {
    sed -n -E 's|^throng: pace ([+-][0-9.]+) m/s: wants ([0-9.]+), walks ([0-9.]+) m/s.*|\1 \2 \3|p' "$log"
}

# The demo's closing line: the pace and the blend after the last frame.
end_line() {
    grep "^throng: info: demo: at the end, pace " "$log" || fail_step "no closing 'demo: at the end, pace' line"
}

# Prints the percent clip $1 weighs in the closing line (0 when it has no part).
share_of() {
    local share
    share=$(end_line | grep -oE "(; | / )$1 [0-9]+%" | grep -oE "[0-9]+%" | tr -d %) || true
    echo "${share:-0}"
}

# True when awk finds the condition $1 true of the numbers $2 (a) and $3 (b).
holds() {
    awk -v a="$2" -v b="${3:-0}" "BEGIN { exit !($1) }"
}

# Runs the default crowd for --frames N, taps key $2 $3 times, waits for the press line of
# pace $4 and for the demo to finish its frames.
pace_run() {
    local name=$1 key=$2 presses=$3 last_offset=$4
    start_demo "$name" --frames "$frames"
    act "key $key x$presses" xdo key --delay 30 $(printf "$key %.0s" $(seq "$presses"))
    wait_until "$step_wait_s" "no press line for pace $last_offset m/s" grep -q -F "throng: pace $last_offset m/s: " "$log"
    expect_frames_done
    check_log_clean
    step="checking the pace lines"
    [ "$(press_lines | wc -l)" -eq "$presses" ] || fail_step "expected $presses press lines, found $(press_lines | wc -l)"
    note "$name: $(end_line)"
}

# Every press moved the crowd's mean desired speed by the step the right way ($1: 1 up, -1
# down), the first by the whole step, as no character was at an end of its set yet.
check_presses() {
    local direction=$1 offset wants walks previous="" first=1
    while read -r offset wants walks; do
        if [ "$first" -eq 1 ]; then
            holds "(a - b) * $direction > 0.45 && (a - b) * $direction < 0.55" "$wants" "$walks" ||
                fail_step "the first press made the crowd want $wants m/s while it walked $walks: not a 0.5 m/s step"
            first=0
        else
            holds "(b - a) * $direction > 0.05" "$previous" "$wants" ||
                fail_step "a press at pace $offset m/s left the crowd wanting $wants m/s, after $previous"
        fi
        previous=$wants
    done < <(press_lines)
}

# The speed the crowd walked at before the first press.
walked_before() {
    press_lines | head -n 1 | awk '{ print $3 }'
}

pace_up() {
    pace_run pace_up Up 4 +2.0
    check_presses 1
    local before wants walks
    before=$(walked_before)
    read -r wants walks < <(end_line | sed -E 's|.*wants ([0-9.]+), walks ([0-9.]+) m/s.*|\1 \2|')
    holds "b >= a + 1.5" "$before" "$walks" ||
        fail_step "the crowd walks $walks m/s at the end, $before m/s before the presses: it did not speed up"
    holds "a - b < 0.05 && b - a < 0.05" "$wants" "$walks" ||
        fail_step "the crowd walks $walks m/s at the end but wants $wants: the blend did not follow in $frames frames"
    [ "$(share_of run)" -ge 80 ] || fail_step "the run weighs $(share_of run)% of the poses at the end, not 80% or more"
    note "$run_name: PASS (walked $before m/s, then $walks m/s with the run at $(share_of run)%)"
}

pace_down() {
    pace_run pace_down Down 3 -1.5
    check_presses -1
    local walks
    walks=$(end_line | sed -E 's|.*walks ([0-9.]+) m/s.*|\1|')
    holds "a < 0.25" "$walks" || fail_step "the crowd still walks $walks m/s after three presses down"
    [ "$(share_of idle)" -ge 80 ] || fail_step "the idle weighs $(share_of idle)% of the poses at the end, not 80% or more"
    note "$run_name: PASS (walked $(walked_before) m/s, then $walks m/s with the idle at $(share_of idle)%)"
}

# Characters that play one clip have no pace: the demo says so instead of doing nothing.
no_set() {
    start_demo no_set --bvh "$(dirname "$throng")/share/throng/walk.bvh"
    act "key Up with no locomotion set" xdo key Up
    wait_until "$step_wait_s" "no line saying the pace keys change nothing" \
        grep -q -F "throng: pace: no character blends a locomotion set" "$log"
    act "key Esc (quit)" xdo key Escape
    expect_exit 0
    check_log_clean
    [ "$(press_lines | wc -l)" -eq 0 ] || fail_step "a pace changed with no locomotion set"
    note "$run_name: PASS ($(grep -F "throng: pace:" "$log"))"
}

pace_up
pace_down
no_set
note "all runs passed"
