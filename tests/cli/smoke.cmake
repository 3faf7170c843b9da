# Basic contract: help, version, usage errors.
throng_cli_test(cli.help EXIT 0 STDOUT "Usage: throng <command>" ARGS --help)
throng_cli_test(cli.bvh_info_help EXIT 0 STDOUT "Usage: throng bvh info" ARGS bvh info --help)
throng_cli_test(cli.bvh_bake_help EXIT 0 STDOUT "Usage: throng bvh bake" ARGS bvh bake --help)
throng_cli_test(cli.unknown_command EXIT 2 STDERR "unknown command 'frobnicate'" ARGS frobnicate)
throng_cli_test(cli.bake_needs_json EXIT 2 STDERR "needs --json" ARGS bvh bake ${THRONG_ASSET_DIR}/walk.bvh)
throng_cli_test(cli.missing_file EXIT 2 STDERR "no-such\\.bvh: error: cannot open BVH file: no such file"
                ARGS bvh info ${CMAKE_CURRENT_BINARY_DIR}/no-such.bvh)
throng_cli_test(cli.bake_missing_file_writes_nothing EXIT 2 STDERR "cannot open BVH file"
                NO_FILE ${CMAKE_CURRENT_BINARY_DIR}/never.json
                ARGS bvh bake ${CMAKE_CURRENT_BINARY_DIR}/no-such.bvh --json ${CMAKE_CURRENT_BINARY_DIR}/never.json)

# `bvh info` reports the root-motion reading: every JSON key scripts used stays ("height_m" is
# the stature), and the new ones follow; the text has a line for each.
set(number "[-0-9.e+]+")
throng_cli_test(cli.bvh_info_json_root_motion_keys EXIT 0
                STDOUT "\"height_m\":${number},.*\"first_frame_skipped\":(true|false),\"stature_m\":${number},\"up_axis\":\"y\",\"up_axis_inferred\":true,\"travel_joint\":\"Hips\",\"speed_mps\":${number},\"turn_rate_deg_s\":${number},\"locomotion\":(true|false),\"static\":(true|false),\"footfalls\":{\"left\":{\"ankle\":\"LeftFoot\",\"contacts\":\\[{\"strike\":[0-9]+,\"lift\":[0-9]+}\\]},\"right\":{\"ankle\":\"RightFoot\",\"contacts\":\\[{\"strike\":[0-9]+,\"lift\":[0-9]+}\\]}},\"gait_phase_zero_frame\":[0-9]+,\"right_strike_phases\":\\[${number}\\],\"warnings\":\\[(\"[^\"]*\"(,\"[^\"]*\")*)?\\]}"
                ARGS bvh info ${THRONG_ASSET_DIR}/walk.bvh --json -)
throng_cli_test(cli.bvh_info_text_root_motion_lines EXIT 0
                STDOUT "\nStature: +${number} m\nUp axis: +y \\(detected\\)\nTravel joint: Hips \\((found by structure|ROOT)\\)\nSpeed: +${number} m/s along the path, turns ${number} deg/s\n"
                ARGS bvh info ${THRONG_ASSET_DIR}/walk.bvh)
throng_cli_test(cli.bvh_info_options_given EXIT 0 STDOUT "Travel joint: Hips \\(given\\)"
                ARGS bvh info ${THRONG_ASSET_DIR}/walk.bvh --up y --root Hips --straighten --no-foot-lock)
throng_cli_test(cli.bvh_info_bad_up EXIT 2 STDERR "--up takes y, -y, z, -z, x or -x, not 'w'"
                ARGS bvh info ${THRONG_ASSET_DIR}/walk.bvh --up w)
# Overrides reach the bake: a unit given on the command line is the unit used.
throng_cli_test(render.bvh_overrides EXIT 0 STDERR "wrote .*3 characters"
                ARGS render --device llvmpipe -n 3 -W 16 -H 16 --bvh ${THRONG_ASSET_DIR}/walk.bvh:units=0.01,loop=30-96,keep-first-frame=1
                     -o ${CMAKE_CURRENT_BINARY_DIR}/bvh-overrides.png)
set_tests_properties(render.bvh_overrides PROPERTIES ENVIRONMENT "ASAN_OPTIONS=detect_leaks=0;LP_NUM_THREADS=2")

# `cmake --install` gives a relocatable throng: it finds its default clip in ../share/throng
# beside itself, with no source path compiled in, and renders from any working directory.
add_test(NAME install.relocatable_default_clip
         COMMAND sh -c "rm -rf ${CMAKE_CURRENT_BINARY_DIR}/install-test && ${CMAKE_COMMAND} --install ${PROJECT_BINARY_DIR} --prefix ${CMAKE_CURRENT_BINARY_DIR}/install-test/prefix >/dev/null && mv ${CMAKE_CURRENT_BINARY_DIR}/install-test/prefix ${CMAKE_CURRENT_BINARY_DIR}/install-test/moved && ! grep -q '${THRONG_ASSET_DIR}' ${CMAKE_CURRENT_BINARY_DIR}/install-test/moved/bin/throng && cd / && ${CMAKE_CURRENT_BINARY_DIR}/install-test/moved/bin/throng render --device llvmpipe -n 3 -W 64 -H 64 -o ${CMAKE_CURRENT_BINARY_DIR}/install-test/out.png && test -s ${CMAKE_CURRENT_BINARY_DIR}/install-test/out.png && test -f ${CMAKE_CURRENT_BINARY_DIR}/install-test/moved/share/doc/throng/LICENSE")
set_tests_properties(install.relocatable_default_clip PROPERTIES LABELS cli ENVIRONMENT "ASAN_OPTIONS=detect_leaks=0;LP_NUM_THREADS=2")
# THRONG_ASSET_DIR points the default clip elsewhere: a folder without walk.bvh is an error naming it.
throng_cli_test(env.asset_dir_overrides_the_default_clip EXIT 2 STDERR "no-assets-here/[a-z_]+\\.bvh: error: cannot open BVH file"
                ARGS render --characters 2 --out ${CMAKE_CURRENT_BINARY_DIR}/no-asset.png NO_FILE ${CMAKE_CURRENT_BINARY_DIR}/no-asset.png)
set_tests_properties(env.asset_dir_overrides_the_default_clip PROPERTIES ENVIRONMENT "THRONG_ASSET_DIR=/no-assets-here")
# THRONG_LOG=info adds diagnostics (the clip and the device chosen); by default there are none.
throng_cli_test(env.log_info_prints_diagnostics EXIT 0 STDERR "throng: info: [^\n]*run\\.bvh: 31 joints[^\n]*\nthrong: info: Vulkan device: "
                ARGS render --device llvmpipe -n 2 -W 16 -H 16 -o ${CMAKE_CURRENT_BINARY_DIR}/log-info.png)
set_tests_properties(env.log_info_prints_diagnostics PROPERTIES ENVIRONMENT "THRONG_LOG=info;LP_NUM_THREADS=2;ASAN_OPTIONS=detect_leaks=0")
add_test(NAME env.log_default_is_quiet
         COMMAND sh -c "! $<TARGET_FILE:throng> render --device llvmpipe -n 2 -W 16 -H 16 -o ${CMAKE_CURRENT_BINARY_DIR}/log-quiet.png 2>&1 | grep -q 'info:'")
set_tests_properties(env.log_default_is_quiet PROPERTIES LABELS cli ENVIRONMENT "LP_NUM_THREADS=2;ASAN_OPTIONS=detect_leaks=0")
