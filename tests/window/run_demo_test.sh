#!/usr/bin/env bash
# Driver for the window tests of `throng demo` (see tests/window/CMakeLists.txt).
#
#   run_demo_test.sh screenshot  --throng T --check-screenshot C --xvfb-run X --out-dir D
#   run_demo_test.sh close       --throng T --send-close S --xvfb-run X --out-dir D [--after-ms N]
#   run_demo_test.sh no-display  --throng T --out-dir D
#   run_demo_test.sh frame-limit --throng T --xvfb-run X --out-dir D
#   run_demo_test.sh check-headless   --throng T --check-screenshot C --out-dir D
#   run_demo_test.sh check-unreadable --throng T --check-screenshot C --out-dir D
#
# screenshot: under Xvfb, 120 frames with scripted window resizes and a screenshot; the demo
#             must exit 0 without validation messages, and the screenshot must pass
#             check_screenshot (not blank, crowd visible, HUD visible).
# close:      under Xvfb, the demo runs with no frame limit; send_close closes its window the
#             way a window manager does, --after-ms after it appears; the demo must exit 0
#             within 30 s, without validation messages.
# frame-limit: under Xvfb, the storage buffer range lowered (THRONG_STORAGE_BUFFER_LIMIT) so
#             that the visibility path's per-pixel buffer holds 600,000 pixels: a 760x480
#             window starts on the visibility path the demo picks, and the scripted resize to
#             1100x700 must hand it to the fast path, saying so, exit 0 and no validation message.
# no-display: without DISPLAY/WAYLAND_DISPLAY the demo must exit 1 with one line on stderr
#             that points to `throng render`.
# check-headless, check-unreadable: tests of check_screenshot itself, no display needed. A
#             headless `throng render` frame has a crowd but no HUD: it must fail the HUD
#             check and only that one (exit 1); a missing file must give exit 2.
# Everything the demo writes goes to files under --out-dir, printed when a test fails.
set -euo pipefail

readonly xvfb_screen="-screen 0 1280x800x24"
readonly demo_title="throng demo"
readonly close_wait_s=30
# Deterministic lavapipe, the validation layer on (any message fails the test), and no leak
# report from a sanitizer build (the Vulkan loader and drivers keep allocations to exit).
export LP_NUM_THREADS=2 THRONG_VALIDATION=1 ASAN_OPTIONS=detect_leaks=0

fail() {
    echo "run_demo_test: FAIL: $*" >&2
    exit 1
}

usage() {
    echo "run_demo_test: usage error: $*" >&2
    exit 2
}

[ $# -ge 1 ] || usage "no mode given"
mode=$1
shift
throng="" check_screenshot="" send_close="" xvfb_run="" out_dir="" after_ms=1500
while [ $# -gt 0 ]; do
    [ $# -ge 2 ] || usage "$1 needs a value"
    case $1 in
        --throng) throng=$2 ;;
        --check-screenshot) check_screenshot=$2 ;;
        --send-close) send_close=$2 ;;
        --xvfb-run) xvfb_run=$2 ;;
        --out-dir) out_dir=$2 ;;
        --after-ms) after_ms=$2 ;;
        *) usage "unknown option $1" ;;
    esac
    shift 2
done
[ -n "$throng" ] || usage "--throng is required"
[ -n "$out_dir" ] || usage "--out-dir is required"
mkdir -p "$out_dir"

# The window tests need a display server; a missing one is a failure, never a skip.
require_xvfb() {
    [ -n "$xvfb_run" ] || usage "--xvfb-run is required for mode $mode"
    command -v "$xvfb_run" >/dev/null 2>&1 ||
        fail "xvfb-run not found ('$xvfb_run'): install the Debian packages xvfb and xauth (tools/setup.sh)"
    command -v xauth >/dev/null 2>&1 ||
        fail "xauth not found (xvfb-run needs it): install the Debian package xauth (tools/setup.sh)"
}

# Prints the file (a log of the demo) under a heading, for the test log.
show() {
    echo "----- $1 -----" >&2
    cat "$2" >&2 || true
    echo "----- end of $1 -----" >&2
}

# Fails if the demo's stderr holds a validation-layer message.
check_no_validation() {
    local log=$1
    if grep -n "validation:" "$log" >&2; then
        show "demo stderr" "$log"
        fail "the validation layer reported the lines above"
    fi
}

case $mode in
screenshot)
    require_xvfb
    [ -n "$check_screenshot" ] || usage "--check-screenshot is required"
    shot="$out_dir/demo_screenshot.png"
    log="$out_dir/demo_screenshot.stderr"
    rm -f "$shot" "$log"
    rc=0
    "$xvfb_run" -a -s "$xvfb_screen" \
        "$throng" demo --device llvmpipe --characters 300 --frames 120 --script-resize --screenshot "$shot" \
        2>"$log" || rc=$?
    if [ "$rc" -ne 0 ]; then
        show "demo stderr" "$log"
        fail "throng demo exited with $rc, expected 0"
    fi
    check_no_validation "$log"
    [ -f "$shot" ] || { show "demo stderr" "$log"; fail "throng demo exited 0 but wrote no screenshot $shot"; }
    "$check_screenshot" "$shot" || fail "the screenshot $shot failed check_screenshot (exit $?)"
    echo "run_demo_test: screenshot: PASS"
    ;;

frame-limit)
    require_xvfb
    log="$out_dir/demo_frame_limit.stderr"
    rm -f "$log"
    rc=0
    THRONG_STORAGE_BUFFER_LIMIT=4800000 "$xvfb_run" -a -s "$xvfb_screen" \
        "$throng" demo --device llvmpipe --characters 100 --width 760 --height 480 --frames 40 --script-resize 2>"$log" || rc=$?
    [ "$rc" -eq 0 ] || { show "demo stderr" "$log"; fail "throng demo exited with $rc, expected 0"; }
    check_no_validation "$log"
    grep -q "visibility path" "$log" || { show "demo stderr" "$log"; fail "the demo did not start on the visibility path"; }
    grep -q "a 1100x700 window is more than the visibility path's 600000 pixels on this device: drawing with the fast path" "$log" ||
        { show "demo stderr" "$log"; fail "the window grown past the visibility path's frame did not hand the crowd to the fast path"; }
    echo "run_demo_test: frame-limit: PASS"
    ;;

hide-ui)
    # --hide-ui: the demo's last frame shows the crowd and no HUD panel, so check_screenshot
    # must reject it for the missing HUD and nothing else.
    require_xvfb
    [ -n "$check_screenshot" ] || usage "--check-screenshot is required"
    shot="$out_dir/demo_hide_ui.png"
    log="$out_dir/demo_hide_ui.stderr"
    rm -f "$shot" "$log"
    rc=0
    "$xvfb_run" -a -s "$xvfb_screen" \
        "$throng" demo --device llvmpipe --characters 200 --frames 30 --hide-ui --screenshot "$shot" 2>"$log" || rc=$?
    [ "$rc" -eq 0 ] || { show "demo stderr" "$log"; fail "throng demo exited with $rc, expected 0"; }
    check_no_validation "$log"
    rc=0
    "$check_screenshot" "$shot" 2>"$out_dir/demo_hide_ui.check" || rc=$?
    cat "$out_dir/demo_hide_ui.check" >&2
    [ "$rc" -eq 1 ] && grep -q "no HUD" "$out_dir/demo_hide_ui.check" || fail "the --hide-ui frame still shows a HUD panel"
    if grep -E "blank frame|no crowd|dark outside" "$out_dir/demo_hide_ui.check" >/dev/null; then
        fail "the --hide-ui frame failed for more than the hidden HUD"
    fi
    echo "run_demo_test: hide-ui: PASS"
    ;;

close)
    require_xvfb
    [ -n "$send_close" ] || usage "--send-close is required"
    # xvfb-run runs one command: this script again, in the inner mode, on the new display.
    "$xvfb_run" -a -s "$xvfb_screen" bash "${BASH_SOURCE[0]}" close-inner --throng "$throng" \
        --send-close "$send_close" --out-dir "$out_dir" --after-ms "$after_ms"
    ;;

close-inner)
    [ -n "${DISPLAY:-}" ] || fail "close-inner runs under xvfb-run, which sets DISPLAY"
    log="$out_dir/demo_close_${after_ms}ms.stderr"
    rm -f "$log"
    "$throng" demo --device llvmpipe --characters 300 2>"$log" &
    demo_pid=$!
    send_pid=""
    # Never leave a process behind, whatever happens below.
    trap 'kill -KILL $demo_pid $send_pid 2>/dev/null || true' EXIT

    # send_close waits for the window; if the demo dies first, say so at once.
    send_out="$out_dir/send_close_${after_ms}ms.stdout"
    "$send_close" "$demo_title" --after-ms "$after_ms" --timeout-ms 20000 >"$send_out" &
    send_pid=$!
    while kill -0 "$send_pid" 2>/dev/null; do
        if ! kill -0 "$demo_pid" 2>/dev/null; then
            # The demo may have reacted to the close before send_close got to exit.
            sleep 0.5
            grep -q "sent WM_DELETE_WINDOW" "$send_out" && break
            rc=0
            wait "$demo_pid" || rc=$?
            show "demo stderr" "$log"
            fail "throng demo exited with $rc before its window was closed"
        fi
        sleep 0.05
    done
    rc=0
    wait "$send_pid" || rc=$?
    send_pid=""
    cat "$send_out"
    if [ "$rc" -ne 0 ]; then
        show "demo stderr" "$log"
        fail "send_close exited with $rc: no window titled '$demo_title' appeared"
    fi

    # Wait for the demo to exit on its own, at most close_wait_s seconds.
    waited=0
    while kill -0 "$demo_pid" 2>/dev/null; do
        if [ "$waited" -ge $((close_wait_s * 10)) ]; then
            kill -TERM "$demo_pid" 2>/dev/null || true
            sleep 1
            kill -KILL "$demo_pid" 2>/dev/null || true
            wait "$demo_pid" 2>/dev/null || true
            show "demo stderr" "$log"
            fail "throng demo still running ${close_wait_s} s after WM_DELETE_WINDOW: killed it"
        fi
        sleep 0.1
        waited=$((waited + 1))
    done
    rc=0
    wait "$demo_pid" || rc=$?
    trap - EXIT
    if [ "$rc" -ne 0 ]; then
        show "demo stderr" "$log"
        fail "throng demo exited with $rc after WM_DELETE_WINDOW, expected 0"
    fi
    check_no_validation "$log"
    echo "run_demo_test: close after ${after_ms} ms: PASS" \
        "(demo exited 0 about $((waited / 10)).$((waited % 10)) s after the close request)"
    ;;

no-display)
    out="$out_dir/demo_no_display.stdout"
    log="$out_dir/demo_no_display.stderr"
    rc=0
    env -u DISPLAY -u WAYLAND_DISPLAY "$throng" demo --frames 5 >"$out" 2>"$log" || rc=$?
    [ "$rc" -eq 1 ] || { show "demo stderr" "$log"; fail "throng demo without a display exited with $rc, expected 1"; }
    lines=$(wc -l <"$log")
    [ "$lines" -eq 1 ] || { show "demo stderr" "$log"; fail "expected exactly one line on stderr, got $lines"; }
    grep -q "throng render" "$log" || { show "demo stderr" "$log"; fail "stderr does not mention 'throng render'"; }
    echo "run_demo_test: no display: PASS ($(cat "$log"))"
    ;;

check-headless)
    [ -n "$check_screenshot" ] || usage "--check-screenshot is required"
    shot="$out_dir/headless_render.png"
    rm -f "$shot"
    "$throng" render --device llvmpipe --characters 200 --view overview --width 640 --height 400 --out "$shot" ||
        fail "throng render exited with $?"
    rc=0
    "$check_screenshot" "$shot" 2>"$out_dir/headless_render.check" || rc=$?
    cat "$out_dir/headless_render.check" >&2
    [ "$rc" -eq 1 ] || fail "check_screenshot exited with $rc on a frame without HUD, expected 1"
    grep -q "no HUD" "$out_dir/headless_render.check" || fail "check_screenshot did not report the missing HUD"
    if grep -E "blank frame|no crowd|dark outside" "$out_dir/headless_render.check" >/dev/null; then
        fail "check_screenshot rejected the headless render for more than the missing HUD"
    fi
    echo "run_demo_test: check_screenshot rejects a frame without HUD: PASS"
    ;;

check-unreadable)
    [ -n "$check_screenshot" ] || usage "--check-screenshot is required"
    rc=0
    "$check_screenshot" "$out_dir/does_not_exist.png" || rc=$?
    [ "$rc" -eq 2 ] || fail "check_screenshot exited with $rc on a missing file, expected 2"
    echo "run_demo_test: check_screenshot on a missing file exits 2: PASS"
    ;;

*)
    usage "unknown mode '$mode' (screenshot, hide-ui, close, no-display, check-headless, check-unreadable)"
    ;;
esac
