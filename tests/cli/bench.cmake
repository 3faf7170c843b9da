# `throng bench` output contracts and tools/plot_bench.
set(bench_env "ASAN_OPTIONS=detect_leaks=0;LP_NUM_THREADS=2")
set(bench_small --device llvmpipe --characters 10 --modes fast --frames 2 --warmup 0 --width 64 --height 64)
string(JOIN " " bench_small ${bench_small})
# The same, less what tools/bench_motion_cost.sh sets itself (--characters, --modes).
set(bench_small_flags "--device llvmpipe --frames 2 --warmup 0 --width 64 --height 64")
set(bench_out "${CMAKE_CURRENT_BINARY_DIR}/bench-out")
file(MAKE_DIRECTORY "${bench_out}")

# --csv -: stdout holds the CSV only (the caption line, the header, one row); the table goes to stderr.
add_test(NAME bench.csv_to_stdout_is_only_csv
         COMMAND sh -c "out=$($<TARGET_FILE:throng> bench ${bench_small} --csv - 2>${bench_out}/csv.err) && printf '%s\\n' \"$out\" && [ \"$(printf '%s\\n' \"$out\" | wc -l)\" -eq 3 ] && printf '%s\\n' \"$out\" | head -1 | grep -q '^# device ' && printf '%s\\n' \"$out\" | sed -n 2p | grep -q '^mode,characters,frame_ms_median,' && printf '%s\\n' \"$out\" | sed -n 3p | grep -q '^fast,10,' && grep -q 'frame_ms' ${bench_out}/csv.err")
# --json -: stdout parses as one JSON document whose header says what ran.
add_test(NAME bench.json_to_stdout_is_only_json
         COMMAND sh -c "$<TARGET_FILE:throng> bench ${bench_small} --msaa 8 --json - 2>/dev/null | python3 -c 'import json,sys; d=json.load(sys.stdin); assert isinstance(d[\"threads\"], int) and d[\"lp_threads\"] == 2, d; assert d[\"msaa\"] in (1, 2, 4, 8) and d[\"msaa\"] != 8, d[\"msaa\"]; assert d[\"rows\"][0][\"mode\"] == \"fast\"; assert d[\"motion\"] == \"clips\" and d[\"ground_speed\"] is None and d[\"scene\"] is None and [c.split(\"/\")[-1] for c in d[\"clips\"]] == [\"walk.bvh\"], d; print(\"json ok, effective msaa\", d[\"msaa\"])'")
set_tests_properties(bench.csv_to_stdout_is_only_csv bench.json_to_stdout_is_only_json PROPERTIES LABELS cli ENVIRONMENT "${bench_env}")
# #14's figures per pass: the visibility path's splat within the compute pass, its shading within
# the draw; the fast path has neither, and says 0. Under the validation layer, which must stay
# silent with the timestamps between the passes. The passes are timed in frames of their own,
# between the timed frames (lavapipe flushes at each timestamp), and the caption and JSON say so.
add_test(NAME bench.rows_time_each_pass
         COMMAND sh -c "out=$($<TARGET_FILE:throng> bench --device llvmpipe --characters 10 --modes fast,visibility --frames 2 --warmup 0 --width 64 --height 64 --json - 2>${bench_out}/passes.err) && printf '%s\\n' \"$out\" | python3 -c 'import json,sys; d = json.load(sys.stdin); assert d[\"passes_timed_apart\"] is True, d; rows = {r[\"mode\"]: r for r in d[\"rows\"]}; f, v = rows[\"fast\"], rows[\"visibility\"]; assert f[\"visibility_ms_median\"] == 0 and f[\"shading_ms_median\"] == 0, f; assert 0 < v[\"visibility_ms_median\"] <= v[\"compute_ms_median\"] and 0 < v[\"shading_ms_median\"] <= v[\"draw_ms_median\"], v; print(\"passes ok\", v[\"visibility_ms_median\"], v[\"shading_ms_median\"])' && grep -q 'gpu_vis  *gpu_shade' ${bench_out}/passes.err && grep -q 'frames timed without GPU timestamps, passes in as many between them' ${bench_out}/passes.err && ! grep -q 'throng: validation' ${bench_out}/passes.err")
set_tests_properties(bench.rows_time_each_pass PROPERTIES LABELS cli ENVIRONMENT "${bench_env};THRONG_VALIDATION=1")
# #14's "peak GPU memory per character": each row counts every per-character buffer of its path
# and body, so bodies cost at least their bone instances (4 vec4s each, as many as the bench says
# the body has quads) more than joint spheres, which cost at least a joint instance (3 vec4s) each.
add_test(NAME bench.bytes_per_character_counts_every_buffer
         COMMAND sh -c "out=$($<TARGET_FILE:throng> bench --device llvmpipe --characters 10 --modes visibility --body spheres,auto --frames 1 --warmup 0 --width 64 --height 64 --json - 2>${bench_out}/bytes.err) && bones=$(sed -n 's/.*bones \\([0-9]*\\) quads.*/\\1/p' ${bench_out}/bytes.err | head -1) && joints=$(sed -n 's/.*spheres \\([0-9]*\\) point sprites.*/\\1/p' ${bench_out}/bytes.err | head -1) && printf '%s\\n' \"$out\" | python3 -c 'import json,sys; rows = {r[\"body\"]: r[\"gpu_bytes_per_character\"] for r in json.load(sys.stdin)[\"rows\"]}; bones, joints = int(sys.argv[1]), int(sys.argv[2]); assert bones > 0 and joints > 0; assert rows[\"spheres\"] >= 48 * joints, rows; assert rows[\"auto\"] - rows[\"spheres\"] >= 64 * bones, rows; print(\"bytes ok\", rows)' \"$bones\" \"$joints\"")
set_tests_properties(bench.bytes_per_character_counts_every_buffer PROPERTIES LABELS cli ENVIRONMENT "${bench_env}" PASS_REGULAR_EXPRESSION "bytes ok")
# --no-readback: frames end at the draw, as ../shared/probe's timed frames do; the readback
# reads 0, and the header and caption say so.
add_test(NAME bench.no_readback_skips_the_copy
         COMMAND sh -c "out=$($<TARGET_FILE:throng> bench ${bench_small} --no-readback --json - 2>${bench_out}/noread.err) && printf '%s\\n' \"$out\" | python3 -c 'import json,sys; d = json.load(sys.stdin); assert d[\"readback\"] is False, d; r = d[\"rows\"][0]; assert r[\"readback_ms_median\"] == 0 and r[\"frame_ms_median\"] > 0, r; print(\"no readback ok\")' && grep -q '; no readback' ${bench_out}/noread.err && $<TARGET_FILE:throng> bench ${bench_small} --json - 2>/dev/null | python3 -c 'import json,sys; d = json.load(sys.stdin); assert d[\"readback\"] is True and d[\"rows\"][0][\"readback_ms_median\"] > 0, d'")
set_tests_properties(bench.no_readback_skips_the_copy PROPERTIES LABELS cli ENVIRONMENT "${bench_env};THRONG_VALIDATION=1")

# --overlap-simulation: the next frame's step runs while the GPU draws. The frames draw the
# same crowd as serial ones (the shares of blending and transitioning characters the frames'
# compute passes mixed are equal), the step is still timed, and the header and caption say so.
add_test(NAME bench.overlapped_simulation_draws_the_same_crowd
         COMMAND sh -c "common='--device llvmpipe --characters 60 --modes visibility --frames 6 --warmup 1 --width 64 --height 64 --locomotion ${THRONG_ASSET_DIR}/idle.bvh,${THRONG_ASSET_DIR}/walk.bvh,${THRONG_ASSET_DIR}/run.bvh --json -' && serial=$($<TARGET_FILE:throng> bench $common 2>/dev/null) && overlapped=$($<TARGET_FILE:throng> bench $common --overlap-simulation 2>${bench_out}/overlap.err) && python3 -c 'import json,sys; s, o = json.loads(sys.argv[1]), json.loads(sys.argv[2]); assert s[\"overlap_simulation\"] is False and o[\"overlap_simulation\"] is True, (s, o); a, b = s[\"rows\"][0], o[\"rows\"][0]; assert a[\"blend_share\"] > 0 and (a[\"blend_share\"], a[\"transition_share\"]) == (b[\"blend_share\"], b[\"transition_share\"]), (a, b); assert b[\"sim_ms_median\"] > 0 and b[\"frame_ms_median\"] > 0, b; print(\"overlap ok\", b[\"blend_share\"])' \"$serial\" \"$overlapped\" && grep -q \"; the next frame's step overlapped with each frame's GPU work\" ${bench_out}/overlap.err && ! grep -q 'throng: validation' ${bench_out}/overlap.err")
set_tests_properties(bench.overlapped_simulation_draws_the_same_crowd PROPERTIES LABELS cli ENVIRONMENT "${bench_env};THRONG_VALIDATION=1" PASS_REGULAR_EXPRESSION "overlap ok")

# --locomotion (#12): every character blends the project's set; the header says so and gives
# the ground speeds, and each row has figures. --sim-only times every mode; the render sweep
# runs with the validation layer, which must stay silent.
set(bench_set "${THRONG_ASSET_DIR}/idle.bvh,${THRONG_ASSET_DIR}/slow_walk.bvh,${THRONG_ASSET_DIR}/walk.bvh,${THRONG_ASSET_DIR}/run.bvh")
set(bench_blend_check "d=json.load(sys.stdin); assert d[\"motion\"] == \"blend\", d; assert [c.split(\"/\")[-1] for c in d[\"clips\"]] == [\"idle.bvh\", \"slow_walk.bvh\", \"walk.bvh\", \"run.bvh\"], d[\"clips\"]")
add_test(NAME bench.sim_only_blends_a_set
         COMMAND sh -c "$<TARGET_FILE:throng> bench --sim-only --characters 100 --frames 3 --warmup 0 --locomotion ${bench_set} --json - 2>/dev/null | python3 -c 'import json,sys; ${bench_blend_check}; assert d[\"ground_speed\"] == [1.0, 1.6], d[\"ground_speed\"]; rows = d[\"rows\"]; assert [r[\"mode\"] for r in rows] == [\"group\", \"goals\", \"avoid\"], rows; assert all(r[\"characters\"] == 100 and r[\"step_ms_median\"] > 0 for r in rows), rows; print(\"blend ok\", [r[\"step_ms_median\"] for r in rows])'")
add_test(NAME bench.render_sweep_blends_a_set
         COMMAND sh -c "out=$($<TARGET_FILE:throng> bench ${bench_small} --locomotion ${bench_set} --speed 0:3 --json - 2>${bench_out}/blend.err) && printf '%s\\n' \"$out\" | python3 -c 'import json,sys; ${bench_blend_check}; assert d[\"ground_speed\"] == [0.0, 3.0], d[\"ground_speed\"]; r = d[\"rows\"][0]; assert r[\"mode\"] == \"fast\" and r[\"characters\"] == 10 and r[\"frame_ms_median\"] > 0 and r[\"fps\"] > 0, r; print(\"render blend ok\", r[\"frame_ms_median\"], \"ms\")' && grep -q 'motion: blend of 4 clips (idle.bvh, slow_walk.bvh, walk.bvh, run.bvh) at 0-3 m/s' ${bench_out}/blend.err && ! grep -q 'throng: validation' ${bench_out}/blend.err")
set_tests_properties(bench.sim_only_blends_a_set PROPERTIES LABELS cli ENVIRONMENT "${bench_env}")
set_tests_properties(bench.render_sweep_blends_a_set PROPERTIES LABELS cli ENVIRONMENT "${bench_env};THRONG_VALIDATION=1")
# The same refusals as render's; a set that can't blend is refused before any device or row.
throng_cli_test(bench.locomotion_not_with_bvh EXIT 2 STDERR "^throng: error: --bvh plays each clip as it is and --locomotion blends a set[^\n]*\n$"
                ARGS bench --sim-only --bvh ${THRONG_ASSET_DIR}/walk.bvh --locomotion ${bench_set})
throng_cli_test(bench.speed_needs_a_set EXIT 2 STDERR "^throng: error: --speed needs a locomotion set to blend \\(--locomotion\\)[^\n]*\n$"
                ARGS bench --sim-only --speed 1:2)
throng_cli_test(bench.speed_refused EXIT 2 STDERR "^throng: error: --speed takes MIN\\[:MAX\\] in m/s[^\n]*\n$"
                ARGS bench --locomotion ${bench_set} --speed 3:1)
throng_cli_test(bench.locomotion_idle_alone_refused EXIT 2 STDERR "^throng: error: locomotion set: no clip shows a gait[^\n]*\n$"
                NO_FILE ${bench_out}/never.csv ARGS bench --device llvmpipe --locomotion ${THRONG_ASSET_DIR}/idle.bvh --csv ${bench_out}/never.csv)
set_tests_properties(bench.locomotion_idle_alone_refused PROPERTIES TIMEOUT 10)

# --scene (#12): the crowd from a scene file, its groups scaled to each --characters total (the
# scene's own without), its events applied; the header names the file and each row says how
# much of its motion blended and crossfaded. assets/scenes/bench_transitions.json must blend and
# crossfade at every character and timed frame, in the render sweep and for the 10 s it
# promises (299 steps; the unit tests check the same through the crowd's own accessors).
set(bench_scene "${THRONG_ASSET_DIR}/scenes/bench_transitions.json")
set(bench_scene_check "d=json.load(sys.stdin); assert d[\"motion\"] == \"scene\" and d[\"scene\"].endswith(\"/bench_transitions.json\"), d; assert [c.split(\"/\")[-1] for c in d[\"clips\"]] == [\"idle.bvh\", \"slow_walk.bvh\", \"walk.bvh\", \"run.bvh\"], d[\"clips\"]; rows = d[\"rows\"]; assert rows and all(r[\"blend_share\"] == 1 and r[\"transition_share\"] == 1 for r in rows), rows")
add_test(NAME bench.scene_blends_and_crossfades
         COMMAND sh -c "out=$($<TARGET_FILE:throng> bench ${bench_small} --scene ${bench_scene} --json - 2>${bench_out}/scene.err) && printf '%s\\n' \"$out\" | python3 -c 'import json,sys; ${bench_scene_check}; r = rows[0]; assert r[\"mode\"] == \"fast\" and r[\"characters\"] == 10 and r[\"frame_ms_median\"] > 0, r; print(\"scene ok\", r[\"compute_ms_median\"], \"ms compute\")' && grep -q 'motion: scene .*bench_transitions.json (idle.bvh, slow_walk.bvh, walk.bvh, run.bvh)' ${bench_out}/scene.err && ! grep -q 'throng: validation' ${bench_out}/scene.err")
set_tests_properties(bench.scene_blends_and_crossfades PROPERTIES LABELS cli ENVIRONMENT "${bench_env};THRONG_VALIDATION=1")
add_test(NAME bench.scene_keeps_crossfading_for_10_s
         COMMAND sh -c "$<TARGET_FILE:throng> bench --sim-only --scene ${bench_scene} --characters 100,7 --frames 299 --warmup 0 --json - 2>/dev/null | python3 -c 'import json,sys; ${bench_scene_check}; assert [(r[\"mode\"], r[\"characters\"]) for r in rows] == [(\"scene\", 100), (\"scene\", 7)], rows; print(\"10 s ok\")'")
add_test(NAME bench.scene_without_characters_is_its_own_size
         COMMAND sh -c "$<TARGET_FILE:throng> bench --sim-only --scene ${bench_scene} --frames 1 --warmup 0 --json - 2>/dev/null | python3 -c 'import json,sys; ${bench_scene_check}; assert [r[\"characters\"] for r in rows] == [10000], rows; print(\"own size ok\")'")
set_tests_properties(bench.scene_keeps_crossfading_for_10_s bench.scene_without_characters_is_its_own_size PROPERTIES LABELS cli ENVIRONMENT "${bench_env}")
throng_cli_test(bench.scene_missing_file EXIT 2 STDERR "^throng: [^\n]*/no-such-scene\\.json: error: cannot open scene file[^\n]*\n$"
                NO_FILE ${bench_out}/never-scene.json ARGS bench --device llvmpipe --scene ${bench_out}/no-such-scene.json --json ${bench_out}/never-scene.json)
throng_cli_test(bench.scene_too_few_characters EXIT 2 STDERR "^throng: [^\n]*paces\\.json: error: can't scale 3 group\\(s\\) to 2 characters[^\n]*\n$"
                NO_FILE ${bench_out}/never-scene.json ARGS bench --device llvmpipe --scene ${THRONG_ASSET_DIR}/scenes/paces.json --characters 50,2 --json ${bench_out}/never-scene.json)
set_tests_properties(bench.scene_missing_file bench.scene_too_few_characters PROPERTIES TIMEOUT 10)
throng_cli_test(bench.scene_not_with_locomotion EXIT 2 STDERR "^throng: error: --scene describes the clips and the crowd; don't combine it with --bvh, --locomotion or --speed[^\n]*\n$"
                ARGS bench --scene ${bench_scene} --locomotion ${bench_set})
throng_cli_test(bench.scene_sim_only_not_with_modes EXIT 2 STDERR "^throng: error: --modes with --sim-only names locomotion modes, and a scene's groups keep their own[^\n]*\n$"
                ARGS bench --sim-only --scene ${bench_scene} --modes avoid)

# tools/bench_motion_cost.sh: the three runs in turn, twice, a small crowd; a figure per path,
# each run's beneath, and no warning that the scene did not blend and crossfade throughout.
add_test(NAME bench_motion_cost.prints_ratios
         COMMAND sh -c "CHARACTERS=20 ROUNDS=2 THRONG=$<TARGET_FILE:throng> ${PROJECT_SOURCE_DIR}/tools/bench_motion_cost.sh ${bench_small_flags} >${bench_out}/cost.txt 2>${bench_out}/cost.err; code=$?; cat ${bench_out}/cost.txt; [ $code -eq 0 ] && grep -Eq '^compute +20 ' ${bench_out}/cost.txt && grep -Eq '^fast +20 ' ${bench_out}/cost.txt && grep -q 'c/a' ${bench_out}/cost.txt && grep -Eq '^ +runs +a: [0-9.]+, [0-9.]+  b: ' ${bench_out}/cost.txt && ! grep -q 'bench_motion_cost: warning' ${bench_out}/cost.err")
set_tests_properties(bench_motion_cost.prints_ratios PROPERTIES LABELS cli ENVIRONMENT "${bench_env}")
add_test(NAME bench_motion_cost.help COMMAND ${PROJECT_SOURCE_DIR}/tools/bench_motion_cost.sh --help)
set_tests_properties(bench_motion_cost.help PROPERTIES LABELS cli PASS_REGULAR_EXPRESSION "usage: tools/bench_motion_cost.sh")

# plot_bench: a plot from a CSV, help, and a clean refusal of a missing output folder.
add_test(NAME plot_bench.plots_a_sweep
         COMMAND sh -c "$<TARGET_FILE:throng> bench ${bench_small} --modes fast,compute --csv ${bench_out}/sweep.csv >/dev/null 2>&1 && rm -f ${bench_out}/sweep.png && ${PROJECT_SOURCE_DIR}/tools/plot_bench ${bench_out}/sweep.csv ${bench_out}/sweep.png && head -c 8 ${bench_out}/sweep.png | od -An -c | grep -q 'P   N   G'")
set_tests_properties(plot_bench.plots_a_sweep PROPERTIES LABELS cli ENVIRONMENT "${bench_env}")
add_test(NAME plot_bench.help COMMAND ${PROJECT_SOURCE_DIR}/tools/plot_bench --help)
set_tests_properties(plot_bench.help PROPERTIES LABELS cli PASS_REGULAR_EXPRESSION "usage: tools/plot_bench")
add_test(NAME plot_bench.missing_output_folder
         COMMAND sh -c "${PROJECT_SOURCE_DIR}/tools/plot_bench ${PROJECT_SOURCE_DIR}/docs/bench_lavapipe_msaa1.csv /no/such/folder/plot.png; [ $? -eq 2 ]")
set_tests_properties(plot_bench.missing_output_folder PROPERTIES LABELS cli)

# bench_against_probe.sh: its rounds' ratios and medians, with stand-ins for the probe and throng
# that print known times (no timing is asserted), and a clean refusal of a ROUNDS that is no count.
add_test(NAME bench_against_probe.rounds_and_medians
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/bench_against_probe_test.sh ${PROJECT_SOURCE_DIR} ${bench_out}/against-probe)
set_tests_properties(bench_against_probe.rounds_and_medians PROPERTIES LABELS cli PASS_REGULAR_EXPRESSION "bench_against_probe_test: ok")
add_test(NAME bench_against_probe.help COMMAND ${PROJECT_SOURCE_DIR}/tools/bench_against_probe.sh --help)
set_tests_properties(bench_against_probe.help PROPERTIES LABELS cli PASS_REGULAR_EXPRESSION "ROUNDS +Throng runs, each between two probe runs")
