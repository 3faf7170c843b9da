#!/usr/bin/env bash
# Drives `throng demo` on an Xvfb display the way a person does, for the window tests that
# source it (run_controls_test.sh, run_pace_test.sh): it reads their options, runs the
# sourcing script again under xvfb-run (--inner), and gives them the demo process, input
# (xdotool key taps, held keys, drags, the wheel, clicks on HUD buttons where the demo's
# THRONG_HUD_LAYOUT file puts them) and the checks that the demo still renders.
#
#   source demo_driver.sh "$@"    with options --throng T --xvfb-run X --out-dir D --frames N
#                                 [--check-screenshot C] [--keys-only]
#
# Messages name the sourcing script. A missing tool (xvfb-run, xauth, xdotool) fails the
# test, never skips it.
readonly script_name=$(basename "$0" .sh)
readonly xvfb_screen="-screen 0 1280x800x24"
readonly demo_title="throng demo"
readonly window_wait_s=60  # the demo's start: the validation layer and lavapipe's shader compiles
readonly step_wait_s=30    # one step (a crowd rebuild included) on a slow, shared 2-core machine
readonly quit_wait_s=30    # from Esc or the Quit button to the demo's exit
readonly xdotool_wait_s=15 # one xdotool command
readonly characters=60
# Deterministic lavapipe, the validation layer on (any message makes the demo exit 1), and no
# leak report from a sanitizer build.
export LP_NUM_THREADS=2 THRONG_VALIDATION=1 ASAN_OPTIONS=detect_leaks=0

fail() {
    echo "$script_name: FAIL: $*" >&2
    exit 1
}

usage() {
    echo "$script_name: usage error: $*" >&2
    exit 2
}

# A line for the test log, with the seconds since the script started.
note() {
    local tenths=$(((${EPOCHREALTIME/./} - script_start_us) / 100000))
    echo "$script_name: [$((tenths / 10)).$((tenths % 10))s] $*"
}

readonly script_start_us=${EPOCHREALTIME/./}
inner=0 keys_only=0
throng="" xvfb_run="" out_dir="" frames="" check_screenshot=""
while [ $# -gt 0 ]; do
    case $1 in
        --inner) inner=1; shift; continue ;;
        --keys-only) keys_only=1; shift; continue ;;
    esac
    [ $# -ge 2 ] || usage "$1 needs a value"
    case $1 in
        --throng) throng=$2 ;;
        --xvfb-run) xvfb_run=$2 ;;
        --out-dir) out_dir=$2 ;;
        --frames) frames=$2 ;;
        --check-screenshot) check_screenshot=$2 ;;
        *) usage "unknown option $1" ;;
    esac
    shift 2
done
[ -n "$throng" ] || usage "--throng is required"
[ -n "$out_dir" ] || usage "--out-dir is required"
[[ "$frames" =~ ^[1-9][0-9]*$ ]] || usage "--frames N is required (N > 0)"
throng=$(realpath "$throng")  # the runs change directory
mkdir -p "$out_dir"
out_dir=$(realpath "$out_dir")
[ -z "$check_screenshot" ] || check_screenshot=$(realpath "$check_screenshot")

if [ "$inner" -eq 0 ]; then
    # A missing tool fails the test, never skips it.
    [ -n "$xvfb_run" ] || usage "--xvfb-run is required"
    command -v "$xvfb_run" >/dev/null 2>&1 ||
        fail "xvfb-run not found ('$xvfb_run'): install the Debian packages xvfb and xauth (tools/setup.sh)"
    command -v xauth >/dev/null 2>&1 || fail "xauth not found: install the Debian package xauth (tools/setup.sh)"
    command -v xdotool >/dev/null 2>&1 || fail "xdotool not found: install the Debian package xdotool (tools/setup.sh)"
    args=(--throng "$throng" --out-dir "$out_dir" --frames "$frames")
    [ -z "$check_screenshot" ] || args+=(--check-screenshot "$check_screenshot")
    [ "$keys_only" -eq 0 ] || args+=(--keys-only)
    exec "$xvfb_run" -a -s "$xvfb_screen" bash "$0" --inner "${args[@]}"
fi
[ -n "${DISPLAY:-}" ] || fail "--inner runs under xvfb-run, which sets DISPLAY"

# ---------------------------------------------------------------------------------------------
# The demo process: one at a time.

demo_pid="" window="" run_name="" log="" layout="" shots=0 step="starting"
# Never leave a demo behind, whatever happens.
trap '[ -z "$demo_pid" ] || kill -KILL "$demo_pid" 2>/dev/null || true' EXIT

# Prints the demo's stderr under a heading, for the test log.
show_log() {
    echo "----- demo stderr ($run_name) -----" >&2
    cat "$log" >&2 || true
    echo "----- end of demo stderr -----" >&2
}

# Fails the test at the current step, with the demo's stderr.
fail_step() {
    show_log
    fail "$run_name: $step: $*"
}

demo_alive() {
    kill -0 "$demo_pid" 2>/dev/null
}

# Called in every wait: a demo that exited early fails the step it exited in.
require_alive() {
    demo_alive && return 0
    local rc=0
    wait "$demo_pid" || rc=$?
    demo_pid=""
    if [ "$rc" -eq 0 ] && grep -q "^throng: demo: $frames frames in " "$log"; then
        fail_step "the demo finished its $frames frames before the input was done: the frame rate was" \
            "higher than --frames allows for (see tests/window/CMakeLists.txt)"
    fi
    fail_step "the demo exited (status $rc) before this step was done$1"
}

# Polls the command "$@" every 0.05 s until it succeeds, at most $1 seconds, failing with $2
# when it does not; fails at once if the demo exits meanwhile.
wait_until() {
    local limit_s=$1 what=$2
    shift 2
    local deadline=$((SECONDS + limit_s))
    until "$@"; do
        require_alive ""
        [ "$SECONDS" -lt "$deadline" ] || fail_step "$what within ${limit_s} s: the demo stopped responding"
        sleep 0.05
    done
}

# xdotool with a time limit: it must never be what hangs the test.
xdo() {
    timeout "$xdotool_wait_s" xdotool "$@" || fail_step "xdotool $* failed (status $?)"
}

# Starts the demo in a fresh scratch working directory $out_dir/NAME (screenshots land there)
# and waits for its window: sets window, log, layout. Arguments after NAME go to the demo.
start_demo() {
    run_name=$1
    shift
    local dir="$out_dir/$run_name"
    rm -rf "$dir"
    mkdir -p "$dir"
    cd "$dir"
    log="$out_dir/$run_name.stderr"
    layout="$dir/hud_layout.txt"
    shots=0
    # A user's older screenshot: the demo must pick the next free name, never overwrite it.
    if [ "${keep_older_screenshot:-0}" -eq 1 ]; then
        echo "an older screenshot" >throng-screenshot-1.png
        shots=1
    fi
    step="waiting for the window"
    # --trajectories gives the crowd its size: no --characters beside it.
    local size=(--characters "$characters")
    case " $* " in *" --trajectories "*) size=() ;; esac
    THRONG_HUD_LAYOUT="$layout" "$throng" demo --device llvmpipe "${size[@]}" "$@" 2>"$log" &
    demo_pid=$!
    note "$run_name: started throng demo $* (pid $demo_pid)"
    # --sync waits for the window; the time limit covers a demo that never opens one.
    window=$(timeout "$window_wait_s" xdotool search --sync --onlyvisible --name "^${demo_title}\$" | head -n 1) || true
    require_alive " (no window titled '$demo_title' yet)"
    [ -n "$window" ] || fail_step "no window titled '$demo_title' within ${window_wait_s} s"
    # Xvfb has no window manager to give the window the keyboard: XTest key events go to the
    # focused window, so focus it (it keeps the focus: nothing else runs on this display).
    xdo windowfocus --sync "$window"
    [ "$(xdo getwindowfocus)" = "$window" ] || fail_step "could not focus window $window"
    if [ "$keys_only" -eq 0 ]; then
        step="waiting for the HUD layout file"
        wait_until "$window_wait_s" "no HUD layout in $layout" test -s "$layout"
    fi
    note "$run_name: window $window is up"
}

# Waits, at most $2 seconds (default quit_wait_s), for the demo to exit; fails unless its
# status is $1.
expect_exit() {
    local want=$1 limit_s=${2:-$quit_wait_s}
    local deadline=$((SECONDS + limit_s)) rc=0
    while demo_alive; do
        [ "$SECONDS" -lt "$deadline" ] || fail_step "the demo still runs ${limit_s} s later"
        sleep 0.1
    done
    wait "$demo_pid" || rc=$?
    demo_pid=""
    [ "$rc" -eq "$want" ] || fail_step "the demo exited with status $rc, expected $want"
}

# Waits for a --frames N run to finish by itself with status 0: at worst nearly all N frames
# at 6 fps (lavapipe here under heavy load: 7 fps), so a demo that hangs fails here.
expect_frames_done() {
    step="waiting for the demo to finish its $frames frames"
    expect_exit 0 $((step_wait_s + frames / 6))
}

# The demo's stderr must hold no validation message and no error or warning line.
check_log_clean() {
    if grep -n -i -E "validation|error|warning|fail|abort|assert" "$log" >&2; then
        fail_step "the demo's stderr has the lines above"
    fi
}

# ---------------------------------------------------------------------------------------------
# Input, as a person gives it.

# The keys (X keysyms) and HUD buttons (layout ids) used so far, for a test that checks it
# used every control.
declare -A used_keys=() used_buttons=()
used_key() {
    local key
    for key in "$@"; do used_keys[$key]=1; done
}

# Presses and releases each named key (X keysym names), as quick taps: the demo queues key
# presses as they arrive, so even taps that fall between two frames count. --keys-only holds
# each key over a few frames instead (see run_controls_test.sh).
#
# The steps avoid waiting for fixed times where they can: with --frames N the run lasts N
# frames, and a wait of S seconds costs S x fps of them, from 7 to 58 fps on this shared
# 2-core machine; the probe after each step waits for frames instead.
press() {
    used_key "$@"
    if [ "$keys_only" -eq 0 ]; then
        xdo key --delay 30 "$@"
        return
    fi
    local key
    for key in "$@"; do
        xdo keydown "$key"
        sleep 0.4
        xdo keyup "$key"
        sleep 0.1
    done
}

# Holds each named key down for a few frames (the fly keys act while held). One xdotool
# command line for all: each xdotool start costs 40-250 ms here, frames included.
hold() {
    used_key "$@"
    local key chain=()
    for key in "$@"; do chain+=(keydown "$key" sleep 0.15 keyup "$key"); done
    xdo "${chain[@]}"
}

# Prints "x y", a point over the scene (bottom right, away from the HUD panel), in window pixels.
scene_point() {
    local WIDTH=0 HEIGHT=0
    eval "$(xdo getwindowgeometry --shell "$window" | grep -E '^(WIDTH|HEIGHT)=[0-9]+$')"
    echo "$((WIDTH * 3 / 4)) $((HEIGHT * 2 / 3))"
}

# Drags with mouse button $1 over the scene, in a few moves a frame or so apart (the demo
# reads the pointer once a frame).
drag() {
    local point move chain=()
    point=$(scene_point)
    chain=(mousemove --window "$window" --sync ${point} mousedown "$1")
    for move in "40 0" "40 20" "-20 30" "0 -40"; do chain+=(sleep 0.08 mousemove_relative -- ${move}); done
    xdo "${chain[@]}" sleep 0.08 mouseup "$1"
}

# Turns the wheel over the scene: $1 clicks of button 4 (up), then $1 of button 5 (down).
scroll() {
    local point
    point=$(scene_point)
    xdo mousemove --window "$window" --sync ${point} click --repeat "$1" --delay 50 4 click --repeat "$1" --delay 50 5
}

# Prints the centre "x y" of HUD button $1 from the layout file ("id x0 y0 x1 y1" lines).
button_centre() {
    awk -v id="$1" '$1 == id { printf "%d %d\n", ($2 + $4) / 2, ($3 + $5) / 2; found = 1 } END { exit !found }' "$layout"
}

# Clicks HUD button $1 where the demo last drew it. Every step before a click ends when the
# demo has drawn a frame after it, so the file is up to date.
click() {
    local centre
    centre=$(button_centre "$1") || fail_step "no button '$1' in the HUD layout $layout"
    used_buttons[$1]=1
    xdo mousemove --window "$window" --sync ${centre} click 1
}

# Gives the demo a few frames to finish with a click before the next input. Dear ImGui (1.86,
# Debian's) acts on a click one frame after the press and wants the keyboard while the button
# is held, so the demo drops keys pressed in the frame after that (a P pressed 0-0.2 s after
# clicking "Halve crowd" was lost in 7 of 14 tries under load); and a second click within a
# frame of the first merges with it. A step that waits for a change of the HUD layout needs
# no settling: the layout is written two frames after the click, and that wait's time,
# layout_ms, is two or three frames. Twice that, 0.4 s at least: no fixed time fits frame
# rates from 7 to 35 fps (a fixed time costs frames of --frames, more at a high rate).
layout_ms=200
settle_after_click() {
    local ms=$((2 * layout_ms))
    [ "$ms" -ge 400 ] || ms=400
    [ "$ms" -le 5000 ] || ms=5000
    sleep "$((ms / 1000)).$(printf '%03d' $((ms % 1000)))"
}

# True when the layout file stayed the same for 0.25 s (a few frames): ImGui sizes a
# panel that reappears over a frame or two, and the demo rewrites the file when it does.
layout_settled() {
    local before
    before=$(cat "$layout")
    sleep 0.25
    [ "$(cat "$layout")" = "$before" ]
}

# ---------------------------------------------------------------------------------------------
# Checks that the demo still renders.

log_has() {
    grep -q -F -x -e "$1" "$log"
}

now_ms() {
    echo $((${EPOCHREALTIME/./} / 1000))
}

# Asks for a screenshot with P and waits for the demo to save it: a frame was acquired,
# recorded, submitted and read back, so the demo did not freeze at the step before.
probe() {
    shots=$((shots + 1))
    press p
    saved "P"
}

# Waits, at most step_wait_s, for screenshot number $shots, asked for by $1 (P or the button).
saved() {
    local name="throng-screenshot-$shots.png" deadline=$((SECONDS + step_wait_s))
    until log_has "throng: saved $name"; do
        require_alive ""
        [ "$SECONDS" -lt "$deadline" ] || no_screenshot "$name" "$1"
        sleep 0.05
    done
    [ -s "$name" ] || fail_step "the demo logged saving $name, but there is no such file"
}

# Fails the step for a screenshot $1 asked for by $2 that did not come, saying whether the
# demo froze or only missed the input: one more P, and a screenshot within 10 s means the
# demo still renders.
no_screenshot() {
    local before
    before=$(grep -c "^throng: saved " "$log" || true)
    xdo key p
    sleep 10
    if [ "$(grep -c "^throng: saved " "$log" || true)" -gt "$before" ]; then
        fail_step "no $1 (asked for by $2) within ${step_wait_s} s, though the demo still renders" \
            "(one more P was saved): the input was lost"
    fi
    fail_step "no $1 (asked for by $2) within ${step_wait_s} s, nor after one more P: the demo stopped rendering"
}

# One step: a name for the messages, then the input (a function and its arguments).
act() {
    step=$1
    shift
    note "$run_name: $step"
    "$@"
}

# A step, then a probe: the demo must render after it.
do_step() {
    act "$@"
    probe
}

# A step of key taps $2... with the probe's P in the same xdotool command (one start saved):
# the demo applies a frame's actions before it records it, so even a P that lands in the
# same frame saves a frame drawn after them. Not for F1/H: the HUD is built before the
# actions, so that frame still shows it.
key_step() {
    if [ "$keys_only" -eq 1 ]; then
        do_step "$1" press "${@:2}"
        return
    fi
    used_key "${@:2}"
    act "$1" xdo key --delay 30 "${@:2}" p
    shots=$((shots + 1))
    saved "P"
}

# The HUD must be shown ($1 = shown) or hidden ($1 = hidden) in the last screenshot:
# check_screenshot reports "no HUD" for a frame without the panel. Its other checks (crowd,
# not blank) do not apply to every camera the steps leave, so only that line is read.
# A probe's P can land in the same frame as the F1/H before it when the demo runs slowly (the
# sanitizer build on a busy machine), and that frame's HUD was built before the toggle: so a
# screenshot that still shows the old state gets two more probes, each a frame later at least.
expect_hud() {
    [ -n "$check_screenshot" ] || return 0
    local shot report tries
    for tries in 1 2 3; do
        shot="throng-screenshot-$shots.png"
        report=$("$check_screenshot" "$shot" 2>&1) || true
        case $1 in
            shown) ! grep -q "no HUD" <<<"$report" && return 0 ;;
            hidden) grep -q "no HUD" <<<"$report" && return 0 ;;
        esac
        [ "$tries" -lt 3 ] && probe
    done
    case $1 in
        shown) fail_step "the HUD is missing from $shot (and the two screenshots before it): $report" ;;
        hidden) fail_step "the HUD is still shown in $shot (and the two screenshots before it): $report" ;;
    esac
}

# Waits until the HUD layout differs from $1 (a button moved or changed its label).
layout_changed() {
    [ "$(cat "$layout")" != "$1" ]
}
expect_layout_change() {
    wait_until "$step_wait_s" "the HUD layout did not change ($2)" layout_changed "$1"
}

