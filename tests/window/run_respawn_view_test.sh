#!/usr/bin/env bash
# window.demo_respawn_in_view: a crowd rebuilt by [, ] or M is shown, pressed as a person presses
# them (XTest key taps through xdotool on an Xvfb display, the validation layer on). The demo
# once kept its camera through a rebuild, so a camera that had followed someone away, or
# looked past a smaller crowd's edge, showed empty ground until F was pressed.
#
#   run_respawn_view_test.sh --throng T --xvfb-run X --out-dir D --frames N --check-screenshot C
#                            (N unused: the run ends by Esc)
#
# One run, in its own scratch directory under D, started with --camera looking at empty
# ground 150 m from the crowd:
#   first   the screenshot must show no crowd (check_screenshot's "no crowd");
#   ]       the new crowd is out of view: the demo must say it framed it, and the screenshot
#           of the frame that acted on the key must show the crowd;
#   M       the next crowd is in view: the camera must stay (no second "framed it" line), and
#           the screenshot must still show a crowd.
# Esc must then end the run with status 0 and no error or validation message in the log.
set -euo pipefail

# The options, the display, the demo process, input and checks.
source "$(dirname "${BASH_SOURCE[0]}")/demo_driver.sh" "$@"
[ -n "$check_screenshot" ] || fail "--check-screenshot is required"

readonly framed_line="throng: the new crowd is out of view: framed it"

# check_screenshot's report on the last screenshot: its stdout and stderr.
last_report() {
    "$check_screenshot" "throng-screenshot-$shots.png" 2>&1 || true
}

# The last screenshot shows a crowd ($1 = yes) or none ($1 = no).
expect_crowd() {
    local report
    report=$(last_report)
    case $1 in
        yes) ! grep -q "no crowd" <<<"$report" || fail_step "the screenshot shows no crowd: $report" ;;
        no) grep -q "no crowd" <<<"$report" || fail_step "the screenshot shows a crowd where the camera sees none: $report" ;;
    esac
}

framed_lines() {
    grep -c -F "$framed_line" "$log" || true
}

respawn_view() {
    start_demo respawn_view --camera 150,12,150,150,0,165
    step="first screenshot (the camera looks at empty ground)"
    probe
    expect_crowd no
    key_step "key ] (double the crowd, out of view)" bracketright
    [ "$(framed_lines)" -eq 1 ] || fail_step "the demo did not say it framed the new crowd ($(framed_lines) lines)"
    expect_crowd yes
    key_step "key M (next mode, the crowd in view)" m
    [ "$(framed_lines)" -eq 1 ] || fail_step "the camera was moved although the new crowd was in view"
    expect_crowd yes
    act "key Esc (quit)" xdo key Escape
    expect_exit 0
    check_log_clean
    note "$run_name: PASS ($shots screenshots)"
}

respawn_view
note "all runs passed"
