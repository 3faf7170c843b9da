#!/usr/bin/env bash
# window.demo_every_control: every control of `throng demo` used the way a person uses it, by
# real key presses and mouse clicks (XTest, through xdotool) on an Xvfb display, with the
# validation layer on. It exists because pressing [ ] or M, or clicking "Halve crowd",
# "Double crowd" or "Next mode", once froze the demo for good, and no test pressed them.
#
#   run_controls_test.sh --throng T --xvfb-run X --out-dir D --frames N
#                        [--check-screenshot C] [--keys-only]
#
# Three runs of the demo, each in its own scratch working directory under D:
#   every_control  --frames N: every key of the controls table (Esc aside), W A S D Q E held,
#                  left and right drags and the wheel over the scene, then a click on every HUD
#                  button (Quit aside). Each step ends when the demo has drawn a frame after
#                  it, waiting at most step_wait_s: the test presses P and waits for the
#                  screenshot the demo then saves, or, for a step that changes the HUD (pause,
#                  follow, ...), waits for the HUD layout file to change. So a frozen demo
#                  fails the step that froze it, by name. At the end the demo must exit 0 by
#                  itself with "N frames" in its summary, have saved exactly the screenshots
#                  asked for (P and the Screenshot button), and log no error. R and the Record
#                  button each make a recording that decodes.
#   escape         no --frames: Esc must make the demo exit 0 within quit_wait_s.
#   quit_button    no --frames: a click on the Quit button must do the same.
# Then every key of the controls table (as `throng demo --help` lists it) must have been
# pressed and every HUD button clicked, so a new control fails this test until it is used.
#
# --keys-only is for demos built before the HUD wrote its layout (THRONG_HUD_LAYOUT), such
# as the old binary that froze: only the every_control run, keys only, no clicks, no F1/H,
# no summary line. Its demo read the keys' state once a frame, so a tap between two frames was
# lost: keys are held for a while instead of tapped.
#
# xvfb-run runs this script again (--inner) on the new display; everything the demo writes
# goes to D, and its stderr is printed when a step fails.
set -euo pipefail

# The options, the display, the demo process, input and checks.
source "$(dirname "${BASH_SOURCE[0]}")/demo_driver.sh" "$@"

# ---------------------------------------------------------------------------------------------
# The runs.

# The demo logs one "throng: pace ..." line per press of a pace key or button: $1 so far.
expect_pace_lines() {
    local found
    found=$(grep -c "^throng: pace " "$log" || true)
    [ "$found" -eq "$1" ] || fail_step "expected $1 'throng: pace' lines from the pace keys and buttons so far, found $found"
}

# The X keysyms of a key of the controls table, as `throng demo --help` names it ("" for the
# mouse, which the drags and the wheel use); fails for a name it does not know.
keysyms_of() {
    case $1 in
        *mouse*) echo "" ;;
        "W A S D, Q E (held)") echo "w a s d q e" ;;
        space | Up | Down) echo "$1" ;;
        -) echo minus ;;
        +) echo plus ;;
        "[") echo bracketleft ;;
        "]") echo bracketright ;;
        F1/H) echo "F1 h" ;;
        Esc) echo Escape ;;
        [A-Z]) echo "${1,,}" ;;
        *) return 1 ;;
    esac
}

# Every control was used: each key of the controls table (read from the demo's own --help,
# so a control added there fails here until this test uses it) and each HUD button of the
# every_control run's layout.
check_every_control_used() {
    step="checking that every control was used"
    local label keysyms key id
    while read -r label; do
        keysyms=$(keysyms_of "$label") || fail "no keysym known for '$label' of the controls table: teach keysyms_of and press it"
        for key in $keysyms; do
            [ -n "${used_keys[$key]:-}" ] || fail "key $key ('$label' in the controls table) was never pressed"
        done
    done < <("$throng" demo --help | awk -F '  +' 'listing && NF >= 3 { print $2 } /^Controls:$/ { listing = 1 }')
    while read -r id _; do
        [ -n "${used_buttons[$id]:-}" ] || fail "the HUD button '$id' was never clicked"
    done <"$out_dir/every_control/hud_layout.txt"
    note "every control was used: keys ${!used_keys[*]}; buttons ${!used_buttons[*]}"
}

# The demo's log has a line matching $1 at least $2 (default 1) times.
expect_log_line() {
    local found
    found=$(grep -c -E "$1" "$log" || true)
    [ "$found" -ge "${2:-1}" ] || fail_step "expected ${2:-1} log line(s) matching '$1', found $found"
}

# A step whose effect shows in the HUD layout: the pause button reads "Resume" while paused,
# and following a character adds a line above the buttons. The demo rewrites the layout
# after it presents a frame, so the change is also the proof that it still renders (and
# costs no screenshot).
step_changing_layout() {
    local before start
    before=$(cat "$layout")
    start=$(now_ms)
    act "$@"
    expect_layout_change "$before" "$step"
    layout_ms=$(($(now_ms) - start))
}

# A click on a button whose effect the layout does not show, then a probe.
click_step() {
    act "$1" click "$2"
    settle_after_click
    probe
}

# The every_control run. Every step ends in a proof that the demo rendered a frame after it
# (a probe, or a change of the layout); steps without a visible effect of their own share a
# probe. --keys-only: keys only, and a probe after each, as the old demo has no layout file.
every_control() {
    start_demo every_control --frames "$frames"
    local started=$SECONDS
    step="first screenshot (the demo renders and sees keys)"
    probe

    # Keys, in the controls table's order. [ ] and M rebuild the crowd, the step the old
    # demo froze in: a probe after each, which also waits for the rebuild.
    key_step "key [ (halve the crowd)" bracketleft
    key_step "key ] (double the crowd)" bracketright
    key_step "key M (next mode)" m
    key_step "key M (next mode again)" m
    if [ "$keys_only" -eq 0 ]; then
        # B rebuilds the renderer for the next body: from auto (the default), joint spheres, bone
        # capsules, skinned meshes, then auto again; on lavapipe the demo picked the visibility
        # path (a CPU device), which draws every body but bone bodies alone (the fast path's, as
        # in render: the visibility path clips a close-up's widest bones).
        key_step "key B (next body: spheres)" b
        expect_log_line "^throng: body: spheres "
        key_step "key B (next body: bones)" b
        expect_log_line "^throng: body: bones \(fast path\)"
        key_step "key B (next body: skin)" b
        expect_log_line "^throng: body: skin \(visibility path\)"
        key_step "key B (next body: auto again)" b
        expect_log_line "^throng: body: auto \(visibility path\)"
    fi
    if [ "$keys_only" -eq 1 ]; then
        do_step "key space (pause)" press space
        do_step "key space (resume)" press space
        do_step "keys + = keypad+ - keypad- (faster, slower)" press plus equal KP_Add minus KP_Subtract
        do_step "keys Down Up (walk slower, faster)" press Down Up
        do_step "key C (follow a character)" press c
        do_step "key F (frame the crowd)" press f
    else
        step_changing_layout "key space (pause)" press space
        step_changing_layout "key space (resume)" press space
        key_step "keys + = keypad+ - keypad- (faster, slower)" plus equal KP_Add minus KP_Subtract
        key_step "keys Down Up (walk slower, faster)" Down Up
        expect_pace_lines 2
        step_changing_layout "key C (follow a character)" press c
        step_changing_layout "key F (frame the crowd)" press f
        do_step "key F1 (hide the HUD)" press F1
        expect_hud hidden
        do_step "key H (show the HUD)" press h
        expect_hud shown
    fi
    act "keys W A S D Q E held (fly)" hold w a s d q e
    act "left drag (orbit)" drag 1
    act "right drag (pan)" drag 3
    do_step "wheel (zoom)" scroll 3

    if [ "$keys_only" -eq 0 ]; then
        # The HUD's buttons, clicked where the layout file says they are.
        click_step "button Halve crowd" halve
        click_step "button Double crowd" double
        click_step "button Next mode" mode
        click_step "button Next body" body
        expect_log_line "^throng: body: spheres " 2
        step_changing_layout "button Pause" click pause
        step_changing_layout "button Resume" click pause
        act "button Faster" click faster
        settle_after_click
        click_step "button Slower" slower
        act "button Walk faster" click walk_faster
        settle_after_click
        click_step "button Walk slower" walk_slower
        expect_pace_lines 4
        step_changing_layout "button Follow" click follow
        step_changing_layout "button Frame crowd" click frame
        # The screenshot is saved on the frame that acts on the click: its own proof.
        act "button Screenshot" click screenshot
        shots=$((shots + 1))
        saved "the Screenshot button"
        # R and the Record button start and stop recordings, each to the next free
        # throng-recording-N.mp4; what a recording holds is window.demo_records' to check.
        key_step "key R (start recording)" r
        expect_log_line "^throng: recording to throng-recording-1\.mp4 "
        key_step "key R (stop recording)" r
        expect_log_line "^throng: saved throng-recording-1\.mp4: [0-9]+ frames"
        # The REC line went: the buttons move up once the next frame lays the HUD out.
        wait_until "$step_wait_s" "the HUD layout kept changing" layout_settled
        step_changing_layout "button Record (start)" click record
        expect_log_line "^throng: recording to throng-recording-2\.mp4 "
        wait_until "$step_wait_s" "the HUD layout kept changing" layout_settled
        step_changing_layout "button Record (stop)" click record
        expect_log_line "^throng: saved throng-recording-2\.mp4: [0-9]+ frames"
        wait_until "$step_wait_s" "the HUD layout kept changing" layout_settled
        click_step "button Hide HUD" hud
        expect_hud hidden
        # Hidden, the HUD has no buttons to click: F1 brings it back, and the layout is
        # read again for the last click.
        do_step "key F1 (show the HUD again)" press F1
        expect_hud shown
        wait_until "$step_wait_s" "the HUD layout kept changing" layout_settled
        click_step "button Halve crowd, after the HUD came back" halve
    fi

    note "$run_name: input done after $((SECONDS - started)) s; waiting for the demo to finish its $frames frames"
    local input_done=$SECONDS
    expect_frames_done
    check_log_clean
    if [ "$keys_only" -eq 0 ]; then
        grep -q -E "^throng: demo: $frames frames in " "$log" || fail_step "no 'throng: demo: $frames frames in' line"
    fi
    # Every screenshot asked for was saved once, under its own name, and nothing else was.
    local logged files distinct
    logged=$(grep -c "^throng: saved throng-screenshot-" "$log" || true)
    distinct=$(grep "^throng: saved throng-screenshot-" "$log" | sort -u | wc -l)
    files=$(find . -maxdepth 1 -name 'throng-screenshot-*.png' | wc -l)
    [ "$logged" -eq "$shots" ] && [ "$distinct" -eq "$shots" ] && [ "$files" -eq "$shots" ] ||
        fail_step "asked for $shots screenshots; the demo logged $logged ($distinct names) and there are $files files"
    if [ "$keys_only" -eq 0 ]; then
        local recording
        for recording in throng-recording-1.mp4 throng-recording-2.mp4; do
            ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames -of csv=p=0 "$recording" |
                grep -q -E '^[1-9][0-9]*$' || fail_step "$recording does not decode to one frame or more"
        done
    fi
    # How much of the run the input left: the margin --frames gives.
    note "$run_name: the demo ran on for $((SECONDS - input_done)) s after the input"
    note "$run_name: PASS ($shots screenshots, $(grep "^throng: demo: " "$log" || echo "no summary"))"
}

# Esc (a key) or the Quit button (a click) ends a run that has no frame limit.
quit_by() {
    keep_older_screenshot=$([ "$1" = escape ] && echo 1 || echo 0) start_demo "$1"
    step="first screenshot"
    probe
    if [ "$1" = escape ]; then
        [ "$(cat throng-screenshot-1.png)" = "an older screenshot" ] || fail_step "the demo overwrote an older screenshot"
    fi
    step="$2"
    note "$run_name: $step"
    case $1 in
        escape) press Escape ;;
        quit_button) click quit ;;
    esac
    expect_exit 0
    check_log_clean
    note "$run_name: PASS (exited 0)"
}

every_control
if [ "$keys_only" -eq 0 ]; then
    quit_by escape "key Esc (quit)"
    quit_by quit_button "button Quit"
    check_every_control_used
fi
note "all runs passed"
