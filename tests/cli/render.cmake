# `throng render` bad input: refused with exit code 2, one clear line, and no output file.
set(render_out "${CMAKE_CURRENT_BINARY_DIR}/render-never.png")
throng_cli_test(render.help EXIT 0 STDOUT "Usage: throng render" ARGS render --help)
throng_cli_test(render.devices_help EXIT 0 STDOUT "Usage: throng devices" ARGS devices --help)
throng_cli_test(render.needs_out EXIT 2 STDERR "needs --out" ARGS render --characters 5)
throng_cli_test(render.zero_characters EXIT 2 STDERR "--characters takes a count from 1" NO_FILE ${render_out}
                ARGS render --characters 0 --out ${render_out})
throng_cli_test(render.negative_characters EXIT 2 STDERR "--characters takes a count from 1" NO_FILE ${render_out}
                ARGS render --characters -5 --out ${render_out})
throng_cli_test(render.absurd_characters EXIT 2 STDERR "--characters takes a count from 1 to 1000000" NO_FILE ${render_out}
                ARGS render --characters 99999999999 --out ${render_out})
throng_cli_test(render.zero_width EXIT 2 STDERR "--width takes pixels from 16" NO_FILE ${render_out}
                ARGS render --width 0 --out ${render_out})
throng_cli_test(render.negative_height EXIT 2 STDERR "--height takes pixels from 16" NO_FILE ${render_out}
                ARGS render --height -720 --out ${render_out})
throng_cli_test(render.absurd_width EXIT 2 STDERR "--width takes pixels from 16 to 8192" NO_FILE ${render_out}
                ARGS render --width 100000 --out ${render_out})
throng_cli_test(render.bad_time EXIT 2 STDERR "--time takes seconds" NO_FILE ${render_out}
                ARGS render --time -1 --out ${render_out})
throng_cli_test(render.bad_camera EXIT 2 STDERR "--camera takes EX,EY,EZ,TX,TY,TZ" NO_FILE ${render_out}
                ARGS render --camera 1,2,3 --out ${render_out})
throng_cli_test(render.bad_msaa EXIT 2 STDERR "--msaa takes 1, 2, 4 or 8" NO_FILE ${render_out}
                ARGS render --msaa 3 --out ${render_out})
throng_cli_test(render.missing_clip EXIT 2 STDERR "no-such-clip\\.bvh: error: cannot open BVH file" NO_FILE ${render_out}
                ARGS render --bvh ${CMAKE_CURRENT_BINARY_DIR}/no-such-clip.bvh --out ${render_out})
throng_cli_test(render.malformed_clip EXIT 2 STDERR "nan_in_data\\.bvh:[0-9]+:[0-9]+: error" NO_FILE ${render_out}
                ARGS render --bvh ${THRONG_TEST_DATA_DIR}/malformed/nan_in_data.bvh --out ${render_out})
throng_cli_test(render.missing_output_directory EXIT 2 STDERR "directory .* does not exist"
                ARGS render --characters 1 --out ${CMAKE_CURRENT_BINARY_DIR}/no-such-dir/x.png)
throng_cli_test(render.unknown_device EXIT 2 STDERR "no Vulkan 1\\.3 device matches --device 'no-such-gpu'" NO_FILE ${render_out}
                ARGS render --characters 1 --device no-such-gpu --out ${render_out})
# A crowd past one storage buffer is drawn in batches; what refuses one is the device's memory,
# here lowered to 100 MB (THRONG_DEVICE_MEMORY_LIMIT) so 100,000 characters are too many.
throng_cli_test(render.crowd_over_device_memory EXIT 2 STDERR "100000 characters drawn as spheres need about [0-9]+ MiB of GPU memory; this device has 95 MiB"
                NO_FILE ${render_out} ARGS render --device llvmpipe --body spheres --characters 100000 --width 32 --height 32 --out ${render_out})
throng_cli_test(render.bone_crowd_over_device_memory EXIT 2 STDERR "100000 characters drawn as bones need about [0-9]+ MiB of GPU memory; this device has 95 MiB"
                NO_FILE ${render_out} ARGS render --device llvmpipe --body bones --characters 100000 --width 32 --height 32 --out ${render_out})
throng_cli_test(render.bad_memory_limit EXIT 2 STDERR "THRONG_DEVICE_MEMORY_LIMIT: expected a byte count from 4096 to [0-9]+, found '12x'"
                NO_FILE ${render_out} ARGS render --device llvmpipe --characters 1 --out ${render_out})
throng_cli_test(render.bad_body EXIT 2 STDERR "--body takes spheres, bones, skin or auto, not 'mesh'" NO_FILE ${render_out}
                ARGS render --body mesh --out ${render_out})
throng_cli_test(render.bones_need_a_body_path EXIT 2 STDERR "--body bones is drawn by the fast and visibility paths: give --path fast or visibility, or leave --path out"
                NO_FILE ${render_out} ARGS render --body bones --path compute --out ${render_out})
throng_cli_test(render.auto_needs_a_body_path EXIT 2 STDERR "--body auto is drawn by the fast and visibility paths: give --path fast or visibility, or leave --path out"
                NO_FILE ${render_out} ARGS render --body auto --path paper --out ${render_out})
throng_cli_test(render.dump_needs_spheres EXIT 2 STDERR "--dump-instances writes joint spheres: give --body spheres" NO_FILE ${render_out}
                ARGS render --body auto --dump-instances ${CMAKE_CURRENT_BINARY_DIR}/never.json --out ${render_out})
throng_cli_test(render.body_dump_needs_bodies EXIT 2 STDERR "--dump-bodies writes bone and skinned bodies: give --body bones, skin or auto" NO_FILE ${render_out}
                ARGS render --body spheres --dump-bodies ${render_out}.json --out ${render_out})
throng_cli_test(render.devices_lists_lavapipe EXIT 0 STDOUT "llvmpipe.*CPU.*Vulkan 1\\.3" ARGS devices)

# These reach the Vulkan driver, whose loader keeps a few allocations until exit; LeakSanitizer
# would report those as leaks in the sanitizer build. Threads are pinned as in every GPU test.
set_tests_properties(render.unknown_device render.devices_lists_lavapipe PROPERTIES ENVIRONMENT "ASAN_OPTIONS=detect_leaks=0;LP_NUM_THREADS=2")
set_tests_properties(render.crowd_over_device_memory render.bone_crowd_over_device_memory
                     PROPERTIES ENVIRONMENT "ASAN_OPTIONS=detect_leaks=0;LP_NUM_THREADS=2;THRONG_DEVICE_MEMORY_LIMIT=100000000")
throng_cli_test(render.dump_of_a_split_crowd EXIT 2 STDERR "--dump-instances and --dump-bodies take at most 470 characters on this device"
                NO_FILE "${render_out}|${render_out}.json" ARGS render --device llvmpipe --body spheres --path fast --characters 1000 --width 32 --height 32
                --dump-instances ${render_out}.json --out ${render_out})
set_tests_properties(render.dump_of_a_split_crowd PROPERTIES ENVIRONMENT "ASAN_OPTIONS=detect_leaks=0;LP_NUM_THREADS=2;THRONG_STORAGE_BUFFER_LIMIT=700000")
# One visibility buffer names one batch's joints: a split crowd is refused, with the limit.
throng_cli_test(render.visibility_path_split_crowd EXIT 2 STDERR "the visibility path draws at most 470 characters on this device"
                NO_FILE "${render_out}" ARGS render --device llvmpipe --path visibility --body spheres --characters 1000 --width 32 --height 32 --out ${render_out})
set_tests_properties(render.visibility_path_split_crowd PROPERTIES ENVIRONMENT "ASAN_OPTIONS=detect_leaks=0;LP_NUM_THREADS=2;THRONG_STORAGE_BUFFER_LIMIT=700000")
set_tests_properties(render.bad_memory_limit PROPERTIES ENVIRONMENT "ASAN_OPTIONS=detect_leaks=0;LP_NUM_THREADS=2;THRONG_DEVICE_MEMORY_LIMIT=12x")
# The demo's --screenshot is a PNG too; bench refuses a crowd the device can't hold before any row runs.
throng_cli_test(demo.screenshot_must_be_png EXIT 2 STDERR "--screenshot writes PNG images only" ARGS demo --frames 2 --screenshot shot.jpg)
throng_cli_test(bench.crowd_over_device_memory EXIT 2 STDERR "--characters 1000000 with --body spheres: more than this device's 953 MiB of memory holds"
                ARGS bench --device llvmpipe --characters 1000000 --modes fast)
set_tests_properties(bench.crowd_over_device_memory PROPERTIES TIMEOUT 10 ENVIRONMENT "ASAN_OPTIONS=detect_leaks=0;THRONG_DEVICE_MEMORY_LIMIT=1000000000")
throng_cli_test(render.bad_view EXIT 2 STDERR "--view takes street or overview, not 'aerial'" NO_FILE ${render_out}
                ARGS render --view aerial --out ${render_out})
# With no --path, render draws auto and skin bodies with the visibility path on a CPU device (lavapipe), with
# one sample whatever --msaa says; a --path given is kept; a crowd past what one of the
# visibility path's batches holds (the limit lowered by THRONG_STORAGE_BUFFER_LIMIT) gives way to
# the fast path, which draws it in batches, and says so.
set(path_out ${CMAKE_CURRENT_BINARY_DIR}/render_path)
throng_cli_test(render.default_path_on_cpu_is_visibility EXIT 0 STDERR "wrote .*, 40 characters x 31 joints, visibility path, 1x MSAA on llvmpipe"
                ARGS render --device llvmpipe --validation --characters 40 --width 64 --height 48 --out ${path_out}_default.png)
throng_cli_test(render.given_path_is_kept EXIT 0 STDERR "wrote .*, 40 characters x 31 joints, fast path, 4x MSAA on llvmpipe"
                ARGS render --device llvmpipe --validation --characters 40 --width 64 --height 48 --path fast --out ${path_out}_fast.png)
throng_cli_test(render.default_path_gives_way_past_one_buffer EXIT 0
                STDERR "1000 characters are more than the visibility path's [0-9]+ on this device: drawing with the fast path.*wrote .*1000 characters x 31 joints in [0-9]+ batches, fast path"
                ARGS render --device llvmpipe --validation --characters 1000 --width 64 --height 48 --out ${path_out}_split.png)
# A frame past what the visibility path's per-pixel buffer holds (one storage buffer, 8 bytes a
# pixel: 87,500 pixels under the lowered limit) gives way to the fast path too when Throng
# picked the path, and is refused, writing nothing, when the user asked for it.
throng_cli_test(render.default_path_gives_way_past_its_frame EXIT 0
                STDERR "a 400x300 frame is more than the visibility path's 87500 pixels on this device: drawing with the fast path.*wrote .*400x300, 40 characters x 31 joints, fast path"
                ARGS render --device llvmpipe --validation --characters 40 --width 400 --height 300 --out ${path_out}_large.png)
throng_cli_test(render.visibility_path_refuses_a_larger_frame EXIT 2
                STDERR "a 400x300 frame is more than the visibility path's 87500 pixels on device 'llvmpipe.*use --path fast or a smaller frame"
                NO_FILE "${path_out}_refused.png" ARGS render --device llvmpipe --validation --path visibility --characters 40 --width 400 --height 300
                --out ${path_out}_refused.png)
# The buffer holds the frame in whole 4 x 4-pixel blocks (visibility.glsl's pixelSlot): 350 x 250
# is the limit's 87,500 pixels, but 352 x 252 of them in blocks; 348 x 248 fits as it is.
throng_cli_test(render.visibility_path_refuses_a_frame_past_it_in_blocks EXIT 2
                STDERR "a 350x250 frame \\(88704 pixels in whole 4 x 4-pixel blocks\\) is more than the visibility path's 87500 pixels on device 'llvmpipe"
                NO_FILE "${path_out}_blocks.png" ARGS render --device llvmpipe --validation --path visibility --characters 40 --width 350 --height 250
                --out ${path_out}_blocks.png)
throng_cli_test(render.visibility_path_takes_a_frame_within_it_in_blocks EXIT 0 STDERR "wrote .*348x248, 40 characters x 31 joints, visibility path"
                ARGS render --device llvmpipe --validation --path visibility --characters 40 --width 348 --height 248 --out ${path_out}_in_blocks.png)
set_tests_properties(render.default_path_gives_way_past_its_frame render.visibility_path_refuses_a_larger_frame
                     render.visibility_path_refuses_a_frame_past_it_in_blocks render.visibility_path_takes_a_frame_within_it_in_blocks PROPERTIES
                     ENVIRONMENT "ASAN_OPTIONS=detect_leaks=0;LP_NUM_THREADS=2;THRONG_STORAGE_BUFFER_LIMIT=700000")
# Bone bodies alone keep the fast path (the visibility path clips a close-up's widest bones).
throng_cli_test(render.bone_bodies_keep_the_fast_path EXIT 0 STDERR "wrote .*, 40 characters x 31 joints, fast path, 4x MSAA on llvmpipe"
                ARGS render --device llvmpipe --validation --characters 40 --width 64 --height 48 --body bones --out ${path_out}_bones.png)
set_tests_properties(render.default_path_on_cpu_is_visibility render.given_path_is_kept render.bone_bodies_keep_the_fast_path
                     PROPERTIES ENVIRONMENT "ASAN_OPTIONS=detect_leaks=0;LP_NUM_THREADS=2")
set_tests_properties(render.default_path_gives_way_past_one_buffer PROPERTIES
                     ENVIRONMENT "ASAN_OPTIONS=detect_leaks=0;LP_NUM_THREADS=2;THRONG_STORAGE_BUFFER_LIMIT=700000")

