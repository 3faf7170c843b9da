# Hostile input (issue #10): values that are finite but out of range, NaN and overflow paths,
# library exceptions, reads that never end, special output files, leftovers, quadratic work.
# Every refusal exits 2 with one stderr line naming the input (file:line:column for BVH, the
# JSON path for scenes, the option on the command line) and writes no output. These run in
# the Release build, where -O3 turned a NaN frame position into an endless loop that the
# sanitizer build never showed, so each has a timeout: a hang fails instead of waiting.
# The inputs are written by tests/data/hostile/make_data.cmake into the build tree.
set(hostile "${CMAKE_CURRENT_BINARY_DIR}/hostile")
set(hostile_out "${CMAKE_CURRENT_BINARY_DIR}/hostile-out")
set(never "${hostile_out}/never.png")
set(never_json "${hostile_out}/never.json")
set(walk "${THRONG_ASSET_DIR}/walk.bvh")
if(CMAKE_BUILD_TYPE STREQUAL "Release")
  set(hostile_timeout 10)
else()
  set(hostile_timeout 120)  # sanitizer builds are many times slower; a hang still fails
endif()

add_test(NAME hostile.make_data
         COMMAND ${CMAKE_COMMAND} -DOUT=${hostile} -DWALK=${walk} -P ${THRONG_TEST_DATA_DIR}/hostile/make_data.cmake)
add_test(NAME hostile.make_output_dir COMMAND ${CMAKE_COMMAND} -E make_directory ${hostile_out})
set_tests_properties(hostile.make_data hostile.make_output_dir PROPERTIES FIXTURES_SETUP hostile_data LABELS "cli;hostile")

set(hostile_tests "")
# hostile_test(NAME ...): throng_cli_test with the data fixture, a timeout and the hostile label.
function(hostile_test name)
  throng_cli_test(hostile.${name} ${ARGN})
  set(hostile_tests ${hostile_tests} hostile.${name} PARENT_SCOPE)
endfunction()
# A scene that must be refused with `message` (a regex) at its JSON path.
function(hostile_scene name message)
  hostile_test(scene.${name} EXIT 2 STDERR "${name}\\.json[:0-9]*: error: ${message}" NO_FILE ${never}
               ARGS render --device llvmpipe --width 16 --height 16 --time 1 --scene ${hostile}/${name}.json --out ${never})
  set(hostile_tests ${hostile_tests} PARENT_SCOPE)
endfunction()
# A BVH file that must be refused at `where` (line:column) with `message`.
function(hostile_bvh name where message)
  hostile_test(bvh.${name} EXIT 2 STDERR "${name}\\.bvh:${where}: error: ${message}" NO_FILE ${never_json}
               ARGS bvh info ${hostile}/${name}.bvh --json ${never_json})
  set(hostile_tests ${hostile_tests} PARENT_SCOPE)
endfunction()
set(coordinate "expected a coordinate from -1000000 to 1000000 m")
string(ASCII 239 191 189 239 191 189 two_replacements)  # U+FFFD twice, as UTF-8
set(bvh_range "from -1000000 to 1000000, found '[^']*' \\(outside the supported range\\)")

# --- From the issue: NaN and overflow after the finiteness check ----------------------------
# A waypoint of 1e39 became an infinite float and a NaN frame position: a hang at -O3.
hostile_scene(unknown_scene_field "at /sed: unknown field \"sed\" \\(a scene takes clips, groups, seed, area, waypoints, events, camera, camera_path\\)")
hostile_scene(unknown_group_field "at /groups/0/haeding: unknown field \"haeding\" \\(a group takes count, mode, region, ")
hostile_scene(unknown_region_field "at /groups/0/region/center: unknown field \"center\" \\(a region takes centre, size\\)")
hostile_scene(unknown_camera_field "at /camera/fvo: unknown field \"fvo\" \\(a camera takes eye, target, fov\\)")
hostile_scene(unknown_keyframe_field "at /camera_path/0/tme: unknown field \"tme\" \\(a keyframe takes time, eye, target, fov\\)")
hostile_scene(waypoint_1e39 "at /waypoints/0/0: ${coordinate}, found 1e\\+39")
# JSON the parser took in part, or messages that misled: a key given twice (the last won), a
# NUL byte (the parser's end of text) or a \u0000 in a clip's path (opened the file before it),
# a count written 5.0 ("found number"), a unit past its limit shown rounded into it.
hostile_scene(speed_1e-300 "at /groups/0/speed/0: expected a speed above 0 as a float holds it, found 1e-300")
# The crowd's own checks name a scene's group by its file and path, not as "group 0".
hostile_test(scene.region_too_small EXIT 2 STDERR "^throng: error: [^\n]*region_too_small\\.json at /groups/0: its 1 x 1 m region is too small for 50 characters"
             NO_FILE ${never} ARGS render --device llvmpipe --width 16 --height 16 --scene ${hostile}/region_too_small.json --out ${never})
hostile_scene(duplicate_seed "at /: the key 'seed' is given twice")
hostile_scene(duplicate_count "at /groups/0: the key 'count' is given twice")
hostile_scene(nul_after "a NUL byte: a scene file is JSON text")
hostile_scene(clip_path_nul "a string holds a NUL character \\(.u0000\\)")
hostile_scene(count_written_5_0 "at /groups/0/count: expected a whole number, found 5\\.0 \\(a whole number is written without a point or an exponent\\)")
hostile_scene(units_past_1e6 "at /clips/0/units: expected a positive number of metres per file unit, at most 1e6, found 1000000\\.1")
# A BVH root position of 1e300 in avoid mode: the same hang, through render and bench.
hostile_test(bvh.root_position_1e300_render_avoid EXIT 2
             STDERR "root_position_1e300\\.bvh:19:1: error: expected a number ${bvh_range}" NO_FILE ${never}
             ARGS render --device llvmpipe --mode avoid --characters 20 --time 1 --bvh ${hostile}/root_position_1e300.bvh --out ${never})
hostile_test(bvh.root_position_1e300_bench_sim_only EXIT 2
             STDERR "root_position_1e300\\.bvh:19:1: error: expected a number ${bvh_range}" NO_FILE ${hostile_out}/never.csv
             ARGS bench --sim-only --bvh ${hostile}/root_position_1e300.bvh --csv ${hostile_out}/never.csv)
# A heading of 1e300 drew characters at NaN; any finite heading is a direction (mod 360).
hostile_test(scene.heading_1e300_is_a_direction EXIT 0 STDOUT "\"positions\":..[-0-9]" STDOUT_NOT "null|nan|inf"
             ARGS render --device llvmpipe --width 16 --height 16 --scene ${hostile}/heading_1e300.json
                  --dump-instances - --out ${hostile_out}/heading.png)
hostile_scene(camera_eye_1e39 "at /camera/eye/0: ${coordinate}, found 1e\\+39")
hostile_scene(centre_1e39 "at /groups/0/region/centre/0: ${coordinate}, found 1e\\+39")
hostile_scene(centre_1e10 "at /groups/0/region/centre/1: ${coordinate}, found 1e\\+10")
# BVH values whose forward kinematics overflowed ("height_m": null, exit 0).
hostile_bvh(offset_overflows_fk 8:14 "expected an OFFSET coordinate ${bvh_range}")
hostile_bvh(offset_1e300 8:14 "expected an OFFSET coordinate ${bvh_range}")

# --- From the issue: library exceptions -----------------------------------------------------
hostile_scene(seed_1e999 "invalid JSON: number overflow parsing '1e999'")
hostile_test(scene.seed_1e999_located EXIT 2 STDERR "seed_1e999\\.json:3:14: error" NO_FILE ${never}
             ARGS render --scene ${hostile}/seed_1e999.json --out ${never})
# Invalid UTF-8 in a joint name: every JSON writer threw type_error.316; now U+FFFD stands in.
hostile_test(bvh.invalid_utf8_name_info_json EXIT 0 STDOUT "\"name\":\"Spine${two_replacements}\""
             ARGS bvh info ${hostile}/invalid_utf8_name.bvh --json -)
hostile_test(bvh.invalid_utf8_name_bake_json EXIT 0 STDOUT "\"joints\":\\[\"Hips\",\"Spine${two_replacements}\"\\]"
             ARGS bvh bake ${hostile}/invalid_utf8_name.bvh --json -)
hostile_test(bvh.invalid_utf8_name_instance_dump EXIT 0 STDOUT "\"joints\":\\[\"Hips\",\"Spine${two_replacements}\"\\]"
             ARGS render --device llvmpipe --characters 2 --width 16 --height 16 --bvh ${hostile}/invalid_utf8_name.bvh
                  --dump-instances - --out ${hostile_out}/utf8.png)

# --- From the issue: reads that never end ---------------------------------------------------
hostile_test(input.scene_dev_zero EXIT 2 STDERR "^throng: /dev/zero: error: cannot open scene file: not a regular file" NO_FILE ${never}
             ARGS render --scene /dev/zero --out ${never})
hostile_test(input.bvh_fifo EXIT 2 STDERR "hostile/fifo: error: cannot open BVH file: not a regular file" NO_FILE ${never_json}
             ARGS bvh info ${hostile}/fifo --json ${never_json})
hostile_test(input.scene_fifo EXIT 2 STDERR "hostile/fifo: error: cannot open scene file: not a regular file" NO_FILE ${never}
             ARGS render --scene ${hostile}/fifo --out ${never})
hostile_test(input.render_bvh_fifo EXIT 2 STDERR "/fifo: error: cannot open BVH file: not a regular file" NO_FILE ${never}
             ARGS render --bvh ${hostile}/fifo --out ${never})
hostile_test(input.bvh_symlink_loop EXIT 2 STDERR "/loop_a: error: cannot open BVH file: Too many levels of symbolic links"
             NO_FILE ${never_json} ARGS bvh bake ${hostile}/loop_a --json ${never_json})
hostile_test(input.scene_symlink_loop EXIT 2 STDERR "/loop_a: error: cannot open scene file: Too many levels of symbolic links"
             NO_FILE ${never} ARGS render --scene ${hostile}/loop_a --out ${never})
string(REPEAT "n" 300 long_component)
hostile_test(input.bvh_long_name EXIT 2 STDERR "${long_component}\\.bvh: error: cannot open BVH file: File name too long"
             NO_FILE ${never_json} ARGS bvh info ${hostile}/${long_component}.bvh --json ${never_json})
hostile_test(input.scene_long_name EXIT 2 STDERR "${long_component}\\.json: error: cannot open scene file: File name too long"
             NO_FILE ${never} ARGS render --scene ${hostile}/${long_component}.json --out ${never})
hostile_test(input.scene_directory EXIT 2 STDERR "a_directory: error: cannot open scene file: it is a directory" NO_FILE ${never}
             ARGS render --scene ${hostile}/a_directory --out ${never})
hostile_scene(clip_is_symlink_loop "at /clips/0: clip file '[^']*loop_a': Too many levels of symbolic links")
hostile_scene(clip_is_fifo "at /clips/0: clip file '[^']*fifo' is not a regular file")

# --- From the issue: the atomic writer and special files ------------------------------------
# Through links of our own to /dev/full and /dev/null (see make_data.cmake): written in
# place, never replaced. /dev/full fails with ENOSPC (exit 2: an output that cannot be
# written is bad input); /dev/null just works.
hostile_test(output.bake_json_dev_full EXIT 2 STDERR "/full: error: cannot write output file: No space left on device"
             STAYS_LINK ${hostile}/full ARGS bvh bake ${walk} --json ${hostile}/full)
hostile_test(output.bake_json_dev_null EXIT 0 STAYS_LINK ${hostile}/null ARGS bvh bake ${walk} --json ${hostile}/null)
hostile_test(output.render_png_dev_full EXIT 2 STDERR "/full: error: cannot write output file: No space left on device"
             STAYS_LINK ${hostile}/full ARGS render --device llvmpipe --characters 2 --width 16 --height 16 --out ${hostile}/full)
hostile_test(output.render_png_dev_null EXIT 0 STAYS_LINK ${hostile}/null
             ARGS render --device llvmpipe --characters 2 --width 16 --height 16 --out ${hostile}/null)
# A failed --out leaves no --dump-instances behind (both are written, or neither).
hostile_test(output.failed_out_leaves_no_dump EXIT 2 STDERR "/full: error: cannot write output file" NO_FILE ${never_json}
             ARGS render --device llvmpipe --characters 2 --width 16 --height 16 --out ${hostile}/full --dump-instances ${never_json})
hostile_test(output.failed_dump_leaves_no_png EXIT 2 STDERR "/full: error: cannot write output file" NO_FILE ${never}
             ARGS render --device llvmpipe --characters 2 --width 16 --height 16 --out ${never} --dump-instances ${hostile}/full)
hostile_test(output.out_and_dump_same_file EXIT 2 STDERR "same\\.png: error: --out and --dump-instances name the same file"
             NO_FILE ${hostile_out}/same.png
             ARGS render --characters 2 --out ${hostile_out}/same.png --dump-instances ${hostile_out}/./same.png)
hostile_test(output.png_to_stdout EXIT 0 STDOUT "^.PNG" STDERR "wrote stdout: 16x16"
             ARGS render --device llvmpipe --characters 2 --width 16 --height 16 --out -)
hostile_test(output.jpeg_name_refused EXIT 2 STDERR "x\\.jpg: error: --out writes PNG images only" NO_FILE ${hostile_out}/x.jpg
             ARGS render --characters 2 --out ${hostile_out}/x.jpg)
hostile_test(output.long_name_refused EXIT 2 STDERR "--out: File name too long"
             ARGS render --characters 2 --out ${hostile_out}/${long_component}.png)
hostile_test(output.directory_through_symlink_loop EXIT 2 STDERR "--out: Too many levels of symbolic links"
             ARGS render --characters 2 --out ${hostile}/loop_a/x.png)
# bench and bvh check their output files before any work: a sweep took minutes to find that
# its CSV had nowhere to go, and `bvh info` printed its summary first.
set(tiny_bench bench --device llvmpipe -n 10 --frames 2 --warmup 0 --width 160 --height 96)
hostile_test(output.bench_csv_nowhere_refused_first EXIT 2 STDERR "--csv: directory '[^']*' does not exist" STDOUT_NOT "median"
             ARGS ${tiny_bench} --csv ${hostile_out}/no/such/table.csv)
hostile_test(output.bench_csv_and_json_same_file EXIT 2 STDERR "--csv and --json name the same file" STDOUT_NOT "median"
             NO_FILE ${hostile_out}/same_table.csv ARGS ${tiny_bench} --csv ${hostile_out}/same_table.csv --json ${hostile_out}/./same_table.csv)
hostile_test(output.bench_csv_and_json_both_stdout EXIT 2 STDERR "--csv and --json name the same file" STDOUT_NOT "median"
             ARGS ${tiny_bench} --csv - --json -)
hostile_test(output.bvh_info_json_nowhere_refused_first EXIT 2 STDERR "--json: directory '[^']*' does not exist" STDOUT_NOT "Joints"
             ARGS bvh info ${walk} --json ${hostile_out}/no/such/info.json)
hostile_test(output.bvh_bake_json_is_a_directory EXIT 2 STDERR "--json: is a directory" ARGS bvh bake ${walk} --json ${hostile_out})
# The demo's --screenshot too, before any window opens (with --frames it ran the whole run first).
hostile_test(output.demo_screenshot_nowhere_refused_first EXIT 2 STDERR "--screenshot: directory '[^']*' does not exist"
             ARGS demo --frames 1 --screenshot ${hostile_out}/no/such/shot.png)
# SIGINT, SIGTERM or SIGHUP while a temporary exists: it is removed, the signal re-raised.
foreach(signal INT TERM HUP)
  add_test(NAME hostile.output.signal_${signal}_removes_temporary
           COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/signal_cleanup.sh $<TARGET_FILE:throng> ${hostile_out}/signal-${signal} ${signal})
  set_tests_properties(hostile.output.signal_${signal}_removes_temporary PROPERTIES PASS_REGULAR_EXPRESSION ": PASS")
  list(APPEND hostile_tests hostile.output.signal_${signal}_removes_temporary)
endforeach()

# --- From the issue: quadratic work and late refusal ----------------------------------------
# 160,000 frames (1.9 MB): `bvh bake --json` took 32 s; the acceptance is under 5 s (Release).
hostile_test(perf.bake_160k_frames EXIT 0 ARGS bvh bake ${hostile}/frames_160k.bvh --json ${hostile_out}/frames_160k.json)
hostile_test(perf.info_160k_frames EXIT 0 STDOUT "Frames: +160000" ARGS bvh info ${hostile}/frames_160k.bvh)
hostile_test(perf.info_160k_frames_at_1mhz EXIT 0 STDOUT "Frames: +160000" ARGS bvh info ${hostile}/frames_160k_at_1mhz.bvh)
# A million characters on a device of 1 GB (THRONG_DEVICE_MEMORY_LIMIT, below): refused for
# want of memory before one is spawned or simulated for 600 s.
hostile_test(perf.million_characters_refused_before_spawning EXIT 2 STDERR "1000000 characters drawn as .* need about [0-9]+ MiB of GPU memory" NO_FILE ${never}
             ARGS render --device llvmpipe --characters 1000000 --mode avoid --time 600 --out ${never})

# --- Our own: every scene number, out of range ----------------------------------------------
hostile_scene(waypoint_1e7 "at /waypoints/1/1: ${coordinate}, found 1e\\+07")
hostile_scene(waypoint_minus_1e39 "at /waypoints/0/0: ${coordinate}, found -1e\\+39")
hostile_scene(waypoints_1e6 "at /waypoints: expected at most 10000 waypoints, found 1000000")
hostile_scene(camera_target_1e39 "at /camera/target/1: ${coordinate}, found 1e\\+39")
hostile_scene(camera_fov_1e300 "at /camera/fov: expected 1 to 170 degrees")
hostile_scene(fov_nan "invalid JSON: syntax error while parsing value - invalid literal")
hostile_scene(seed_negative "at /seed: expected a non-negative whole number")
hostile_scene(seed_1e30 "at /seed: expected a non-negative whole number")
hostile_scene(area_1e39 "at /area/0: sizes must be positive, from 0.01 to 100000 m, found 1e\\+39")
hostile_scene(size_1e-50 "at /groups/0/region/size/0: sizes must be positive, from 0.01 to 100000 m, found 1e-50")
hostile_scene(count_1e300 "at /groups/0/count: expected a whole number, found 1e\\+300 \\(a whole number is written without a point or an exponent\\)")
hostile_scene(count_uint64_max "at /groups/0/count: expected a count from 1 to 1000000, found 18446744073709551615")
hostile_scene(total_over_a_million "at /groups/1/count: the scene has more than 1000000 characters")
hostile_scene(speed_1e39 "at /groups/0/speed: expected 0 < min <= max <= 4")
hostile_scene(speed_negative "at /groups/0/speed: expected 0 < min <= max <= 4")
hostile_scene(nesting_100000 "JSON nested deeper than 64 levels")
hostile_scene(empty "invalid JSON: syntax error")

# --- Our own: the command line --------------------------------------------------------------
function(hostile_option name message)
  hostile_test(cli.${name} EXIT 2 STDERR "^throng: error: ${message}" NO_FILE ${never} ARGS render ${ARGN} --out ${never})
  set(hostile_tests ${hostile_tests} PARENT_SCOPE)
endfunction()
hostile_option(camera_1e39 "--camera takes EX,EY,EZ" --camera 1e39,0,0,0,0,0)
hostile_option(camera_1e30 "--camera takes eye and target coordinates from -1000000 to 1000000 m" --camera 0,1e30,0,0,0,0)
hostile_option(camera_target_minus_1e7 "--camera takes eye and target coordinates" --camera 0,1,0,0,0,-1e7)
hostile_option(area_1e30 "--area takes WIDTHxDEPTH in metres" --area 1e30x1)
hostile_option(area_1e-30 "--area takes WIDTHxDEPTH in metres" --area 1e-30x1)
hostile_option(time_1e308 "--time takes seconds from 0 to 600" --time 1e308)
hostile_option(time_nan "--time takes seconds from 0 to 600" --time nan)
hostile_option(time_inf "--time takes seconds from 0 to 600" --time inf)
hostile_option(seed_2_pow_64 "--seed takes a non-negative whole number" --seed 18446744073709551616)
hostile_option(seed_negative "--seed takes a non-negative whole number" --seed -1)
hostile_option(characters_exponent "--characters takes a count from 1" --characters 1e6)
hostile_option(lod_pixels_1e39 "--lod-pixels takes 0" --lod-pixels 1e39)
# Per-clip overrides, `--bvh FILE:key=value,...`: each bad one names the key and what it takes.
set(walk_re "[^ ]*walk\\.bvh")
hostile_option(bvh_units_1e400 "--bvh ${walk_re}:units=1e400: units takes a positive number of metres per file unit, at most 1e6"
               --bvh ${walk}:units=1e400)
hostile_option(bvh_units_zero "--bvh ${walk_re}:units=0: units takes a positive number" --bvh ${walk}:units=0)
hostile_option(bvh_up_w "--bvh ${walk_re}:up=w: up takes y, -y, z, -z, x or -x, not 'w'" --bvh ${walk}:up=w)
hostile_option(bvh_loop_backwards "--bvh ${walk_re}:loop=5-2: loop takes FIRST-LAST frame indices with FIRST < LAST"
               --bvh ${walk}:loop=5-2)
hostile_option(bvh_loop_overflow "--bvh ${walk_re}:loop=1-99999999999: loop takes FIRST-LAST" --bvh ${walk}:loop=1-99999999999)
hostile_option(bvh_root_empty "--bvh ${walk_re}:root=: root takes the name of a joint of the file" --bvh ${walk}:root=)
hostile_option(bvh_unknown_key "--bvh ${walk_re}:colour=red: unknown key 'colour'; the keys are units, up, root, loop"
               --bvh ${walk}:colour=red)
hostile_option(bvh_key_twice "--bvh ${walk_re}:up=z,up=y: up is given twice" --bvh ${walk}:up=z,up=y)
hostile_option(bvh_switch_value "--bvh ${walk_re}:foot-lock=maybe: foot-lock takes 0 or 1" --bvh ${walk}:foot-lock=maybe)
hostile_test(cli.bench_bvh_up_w EXIT 2 STDERR "^throng: error: --bvh ${walk_re}:up=w: up takes y, -y, z, -z, x or -x"
             NO_FILE ${hostile_out}/never.csv ARGS bench --sim-only --bvh ${walk}:up=w --csv ${hostile_out}/never.csv)
hostile_test(cli.bake_frame_index_overflow EXIT 2 STDERR "--frames takes 'all' or a comma-separated list" NO_FILE ${never_json}
             ARGS bvh bake ${walk} --json ${never_json} --frames 99999999999)
hostile_test(cli.units_1e6_reach EXIT 2 STDERR "walk\\.bvh: error: joints reach [0-9.e+]+ m from the origin" NO_FILE ${never_json}
             ARGS bvh info ${walk} --units 1e6 --json ${never_json})

# --- Our own: BVH files ---------------------------------------------------------------------
hostile_bvh(channel_1e308 19:14 "expected a number ${bvh_range}")
hostile_bvh(rotation_1e7_degrees 19:14 "expected a number ${bvh_range}")
hostile_bvh(frame_time_1e-300 18:13 "frame time must be between 1e-6 and 3600 seconds")
hostile_bvh(frame_time_1e308 18:13 "frame time must be between 1e-6 and 3600 seconds")
hostile_bvh(empty_joint_name 6:12 "expected a joint name after JOINT")
hostile_bvh(joint_name_300_bytes 6:9 "joint name is longer than 256 bytes")
hostile_bvh(joints_100001 300003:1 "more than 100000 joints")
hostile_test(bvh.chain_reaches_1e11 EXIT 2 STDERR "chain_reaches_1e11\\.bvh: error: joints reach 1e\\+08 m from the origin"
             NO_FILE ${never} ARGS render --bvh ${hostile}/chain_reaches_1e11.bvh --out ${never})

# A unit that shrinks the body to nothing: refused, not drawn as an empty picture with exit 0.
hostile_test(bvh.units_1e-300 EXIT 2 STDERR "walk\\.bvh: error: the body stands 1\\.[0-9]+e-298 m tall [^\n]*at least 0\\.01 m is supported; check the unit"
             NO_FILE ${never} ARGS render --bvh ${walk}:units=1e-300 --out ${never})

# --- A skeleton with no bone: bodies (the default) draw it, on every path that draws them -----
# A lone ROOT without an End Site has no bone; the renderer divided by the bone count (SIGFPE).
set(bodies_without_bones "")
foreach(path visibility fast)
  foreach(body auto bones skin)
    hostile_test(bvh.lone_root_${path}_${body} EXIT 0 STDERR "wrote .*lone_${path}_${body}\\.png"
                 ARGS render --device llvmpipe --path ${path} --body ${body} -n 20 --width 160 --height 96 --time 1
                      --bvh ${hostile}/lone_root.bvh --out ${hostile_out}/lone_${path}_${body}.png)
    list(APPEND bodies_without_bones hostile.bvh.lone_root_${path}_${body})
  endforeach()
endforeach()
hostile_test(bvh.lone_root_bench EXIT 0 STDOUT "visibility" ARGS bench --device llvmpipe -n 10 --frames 2 --warmup 0
             --width 160 --height 96 --bvh ${hostile}/lone_root.bvh)
list(APPEND bodies_without_bones hostile.bvh.lone_root_bench)

# --- Skeletons far past a person's: bounded work, not minutes ---------------------------------
# A skinned body weighs every bone at every vertex (2000 joints, 4000 bones, took 35 s): past 256 bones the
# crowd is drawn with bones, and said so. bvh info indented each joint by walking to the root
# (55 s for a chain of 100,000).
foreach(body skin auto)
  hostile_test(bvh.siblings_2000_${body} EXIT 0
               STDERR "clip '[^']*siblings_2000\\.bvh' has 4000 body bones, more than the 256 a skinned body is made from: the crowd is drawn with bones instead of skin\n[^\n]*wrote "
               ARGS render --device llvmpipe --body ${body} -n 2 --width 160 --height 96 --bvh ${hostile}/siblings_2000.bvh
                    --out ${hostile_out}/siblings_${body}.png)
  list(APPEND bodies_without_bones hostile.bvh.siblings_2000_${body})
endforeach()
hostile_test(bvh.info_chain_99999 EXIT 0 STDOUT "Joints: +100000 " ARGS bvh info ${hostile}/chain_99999.bvh)

# --- THRONG_THREADS that is not a count from 1 to 256: refused, not ignored -------------------
foreach(threads abc 0 1000)
  hostile_test(env.threads_${threads} EXIT 2 STDERR "THRONG_THREADS: expected a thread count from 1 to 256, found '${threads}'"
               NO_FILE ${hostile_out}/never.csv ARGS simulate -n 5 --time 0.1 --fps 10 --out ${hostile_out}/never.csv)
endforeach()

# Every one above: the data fixture, the hostile label, a timeout; GPU ones pin lavapipe.
set_tests_properties(${hostile_tests} PROPERTIES FIXTURES_REQUIRED hostile_data LABELS "cli;hostile" TIMEOUT ${hostile_timeout}
                     ENVIRONMENT "ASAN_OPTIONS=detect_leaks=0;LP_NUM_THREADS=2")
set_tests_properties(hostile.perf.million_characters_refused_before_spawning
                     PROPERTIES ENVIRONMENT "ASAN_OPTIONS=detect_leaks=0;LP_NUM_THREADS=2;THRONG_DEVICE_MEMORY_LIMIT=1000000000")
set_tests_properties(${bodies_without_bones} PROPERTIES ENVIRONMENT "ASAN_OPTIONS=detect_leaks=0;LP_NUM_THREADS=2;THRONG_VALIDATION=1")
foreach(threads abc 0 1000)
  set_tests_properties(hostile.env.threads_${threads} PROPERTIES ENVIRONMENT "ASAN_OPTIONS=detect_leaks=0;THRONG_THREADS=${threads}")
endforeach()
if(CMAKE_BUILD_TYPE STREQUAL "Release")
  set_tests_properties(hostile.perf.bake_160k_frames PROPERTIES TIMEOUT 5)
endif()
