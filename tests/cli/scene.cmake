# Scene files: bad ones are refused with exit 2, naming the file and the JSON path of the
# bad field, and leave no output; the example scene renders.
set(scenes "${THRONG_TEST_DATA_DIR}/scenes")
set(scene_out "${CMAKE_CURRENT_BINARY_DIR}/scene-never.png")
function(throng_bad_scene name stderr_regex)
  throng_cli_test(scene.${name} EXIT 2 STDERR "${name}\\.json.*error: ${stderr_regex}" NO_FILE ${scene_out}
                  ARGS render --scene ${scenes}/${name}.json --out ${scene_out})
endfunction()
throng_bad_scene(negative_count "at /groups/0/count: expected a count from 1")
throng_bad_scene(missing_count "at /groups/0: missing required field \"count\"")
throng_bad_scene(count_wrong_type "at /groups/0/count: expected a whole number, found string")
throng_bad_scene(unknown_clip_path "at /clips/0: clip file .*no-such-clip\\.bvh' does not exist")
throng_bad_scene(unknown_clip_name "at /groups/0/clips/0: no clip is named 'run'")
throng_bad_scene(bad_mode "at /groups/0/mode: expected \"group\", \"goals\" or \"avoid\"")
throng_bad_scene(negative_size "at /groups/0/region/size/1: sizes must be positive")
throng_bad_scene(missing_groups "at /: missing required field \"groups\"")
throng_bad_scene(missing_region_size "at /groups/0/region: missing required field \"size\"")
throng_bad_scene(camera_wrong_shape "at /camera/eye: expected an eye position as \\[x, y, z\\]")
# A clip's bake overrides (the fields of `--bvh FILE:key=value`): a bad value or an unknown
# field is refused at its JSON path; good ones bake each clip its own way.
throng_bad_scene(clip_unknown_field "at /clips/0: unknown field \"colour\" \\(a clip takes name, path, units, up")
throng_bad_scene(clip_bad_up "at /clips/0/up: expected the file's up axis: y, -y, z, -z, x or -x")
throng_bad_scene(clip_bad_loop "at /clips/0/loop: expected frame indices with 0 <= FIRST < LAST, found \\[50,10\\]")
throng_bad_scene(clip_bad_units "at /clips/0/units: expected a positive number of metres per file unit, at most 1e6, found -0.01")
throng_cli_test(scene.clip_overrides_render EXIT 0 STDERR "wrote .*4 characters"
                ARGS render --device llvmpipe --scene ${scenes}/clip_overrides.json --width 32 --height 32
                     --out ${CMAKE_CURRENT_BINARY_DIR}/clip_overrides.png)
set_tests_properties(scene.clip_overrides_render PROPERTIES ENVIRONMENT "ASAN_OPTIONS=detect_leaks=0;LP_NUM_THREADS=2")
throng_cli_test(scene.syntax_error EXIT 2 STDERR "syntax_error\\.json:2:[0-9]+: error: invalid JSON" NO_FILE ${scene_out}
                ARGS render --scene ${scenes}/syntax_error.json --out ${scene_out})
throng_cli_test(scene.region_too_small EXIT 2 STDERR "region_too_small\\.json at /groups/0: its 2 x 2 m region is too small for 400 characters" NO_FILE ${scene_out}
                ARGS render --scene ${scenes}/region_too_small.json --out ${scene_out})
# The crowd is spawned once the device's memory has been checked, so this opens a Vulkan
# context first; lavapipe's one-time driver allocation then reads as a leak under LSan.
set_tests_properties(scene.region_too_small PROPERTIES ENVIRONMENT "ASAN_OPTIONS=detect_leaks=0;LP_NUM_THREADS=2")
throng_cli_test(scene.missing_file EXIT 2 STDERR "nope\\.json: error: cannot open scene file" NO_FILE ${scene_out}
                ARGS render --scene ${scenes}/nope.json --out ${scene_out})
throng_cli_test(scene.conflicts_with_crowd_options EXIT 2 STDERR "don't combine it with --bvh, --characters" NO_FILE ${scene_out}
                ARGS render --scene ${THRONG_ASSET_DIR}/scenes/plaza.json --characters 5 --out ${scene_out})
throng_cli_test(scene.example_renders EXIT 0 STDERR "wrote .*164 characters"
                ARGS render --device llvmpipe --validation --scene ${THRONG_ASSET_DIR}/scenes/plaza.json --time 3
                     --width 160 --height 90 --out ${CMAKE_CURRENT_BINARY_DIR}/plaza.png)
set_tests_properties(scene.example_renders PROPERTIES ENVIRONMENT "ASAN_OPTIONS=detect_leaks=0;LP_NUM_THREADS=2")
throng_cli_test(render.bad_mode EXIT 2 STDERR "--mode takes group, goals or avoid" ARGS render --mode flock --out ${scene_out})
throng_cli_test(render.bad_area EXIT 2 STDERR "--area takes WIDTHxDEPTH" ARGS render --area 10 --out ${scene_out})
throng_cli_test(bench.bad_render_mode EXIT 2 STDERR "--modes takes paper, cpu, compute, fast or visibility" ARGS bench --modes warp)
# Without --modes the sweep is the default body and the path render picks for it (on lavapipe,
# a CPU device: visibility).
throng_cli_test(bench.render_sweep_prints_rows EXIT 0 STDOUT "visibility/auto +10 " ARGS bench --device llvmpipe --characters 10 --frames 1 --warmup 0 --width 64 --height 64)
set_tests_properties(bench.render_sweep_prints_rows PROPERTIES ENVIRONMENT "ASAN_OPTIONS=detect_leaks=0;LP_NUM_THREADS=2")
throng_cli_test(render.bad_path EXIT 2 STDERR "--path takes paper, cpu, compute, fast or visibility" ARGS render --path warp --out ${scene_out})
throng_cli_test(bench.sim_only_prints_rows EXIT 0 STDOUT "avoid +50 " ARGS bench --sim-only --characters 50 --frames 2 --warmup 0)
