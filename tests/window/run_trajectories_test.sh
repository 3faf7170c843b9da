#!/usr/bin/env bash
# window.demo_follows_trajectories: the demo shows a crowd read with --trajectories (#15), and
# the keys that reshape a crowd keep working on it, pressed as a person presses them (XTest
# key taps through xdotool on an Xvfb display, the validation layer on).
#
#   run_trajectories_test.sh --throng T --xvfb-run X --out-dir D --frames N   (N unused: the run ends by Esc)
#
# One run, in its own scratch directory under D, of 40 characters following an avoid crowd's
# tracks that `throng simulate` wrote:
#   M    must say it changes nothing (the crowd follows its tracks; there is no mode to cycle);
#   ]    must stop at the file's 40 tracks, saying so, instead of asking for 80 followers;
#   [ ]  halve the crowd and double it back.
# After each, a screenshot (P) proves the demo still renders; Esc must end it with status 0,
# with no error or validation message in its log.
set -euo pipefail

# The options, the display, the demo process, input and checks.
source "$(dirname "${BASH_SOURCE[0]}")/demo_driver.sh" "$@"

follow() {
    local tracks="$out_dir/tracks.csv"
    "$throng" simulate -n 40 --mode avoid --time 8 --fps 10 --out "$tracks" 2>/dev/null
    start_demo follow --trajectories "$tracks"
    step="first screenshot (the demo renders the followed crowd)"
    probe
    grep -q -F "throng: trajectories $tracks: CSV (id, time, x, z)" "$log" || fail_step "the demo did not say what it read"
    key_step "key M (no mode to change)" m
    grep -q -F "throng: mode: the crowd follows --trajectories, so M changes nothing" "$log" || fail_step "M did not say it changes nothing"
    key_step "key ] (at most one character per track)" bracketright
    grep -q -F "the trajectory file has 40 tracks: the crowd stops there" "$log" || fail_step "] did not stop at the file's 40 tracks"
    key_step "key [ (halve the crowd)" bracketleft
    key_step "key ] (double it back)" bracketright
    act "key Esc (quit)" xdo key Escape
    expect_exit 0
    step="checking the log"
    if grep -n -i -E "validation|error|fail|abort|assert" "$log" >&2; then
        fail_step "the demo's stderr has the lines above"
    fi
    note "$run_name: PASS ($shots screenshots)"
}

follow
note "all runs passed"
