# Locomotion sets and speeds from the command line (#12): each bad set or speed is refused
# with exit 2 and one line, and leaves no file; the project's set and the shared CMU set blend.
set(loco_out "${CMAKE_CURRENT_BINARY_DIR}/locomotion.png")
set(walk "${THRONG_ASSET_DIR}/walk.bvh")
set(idle "${THRONG_ASSET_DIR}/idle.bvh")
foreach(case
    "absurd|1e39" "nan|nan" "negative|-1" "reversed|5:1" "half|1:" "too_fast|21")
  string(REPLACE "|" ";" parts "${case}")
  list(GET parts 0 label)
  list(GET parts 1 value)
  throng_cli_test(locomotion.speed_refused_${label} EXIT 2 STDERR "^throng: error: --speed takes MIN\\[:MAX\\] in m/s[^\n]*\n$"
                  NO_FILE ${loco_out} ARGS render -n 2 --speed ${value} --out ${loco_out})
endforeach()
throng_cli_test(locomotion.speed_needs_a_set EXIT 2 STDERR "--speed needs a locomotion set" NO_FILE ${loco_out}
                ARGS render -n 2 --bvh ${walk} --speed 1 --out ${loco_out})
throng_cli_test(locomotion.not_with_bvh EXIT 2 STDERR "give one or the other" NO_FILE ${loco_out}
                ARGS render -n 2 --bvh ${walk} --locomotion ${walk} --out ${loco_out})
throng_cli_test(locomotion.idle_alone_refused EXIT 2 STDERR "^throng: error: locomotion set: no clip shows a gait[^\n]*\n$"
                NO_FILE ${loco_out} ARGS render -n 2 --locomotion ${idle} --out ${loco_out})
throng_cli_test(locomotion.same_speed_refused EXIT 2 STDERR "walk at nearly the same speed" NO_FILE ${loco_out}
                ARGS render -n 2 --locomotion ${walk},${walk} --out ${loco_out})
throng_cli_test(locomotion.device_file_refused EXIT 2 STDERR "/dev/zero: error: cannot open BVH file" NO_FILE ${loco_out}
                ARGS render -n 2 --locomotion ${walk},/dev/zero --out ${loco_out})
throng_cli_test(locomotion.project_set_renders EXIT 0 STDERR "wrote .*3 characters x 31 joints"
                ARGS render --device llvmpipe --validation -n 3 -W 32 -H 32 --speed 0:3 --locomotion ${idle},${walk},${THRONG_ASSET_DIR}/run.bvh
                     --out ${CMAKE_CURRENT_BINARY_DIR}/locomotion_ok.png)
set_tests_properties(locomotion.project_set_renders PROPERTIES ENVIRONMENT "LP_NUM_THREADS=2;ASAN_OPTIONS=detect_leaks=0")
if(THRONG_HAVE_SHARED_MOCAP)
  set(cmu "${THRONG_SHARED_MOCAP_DIR}")
  # A different skeleton (19 joints against 31) in one set.
  throng_cli_test(locomotion.mismatched_skeletons_refused EXIT 2 STDERR "^throng: error: locomotion set: [^\n]*has a different skeleton[^\n]*\n$"
                  NO_FILE ${loco_out} ARGS render -n 2 --locomotion ${walk},${cmu}/bvhtoolbox_walk01_19j_zxy_24fps.bvh --out ${loco_out})
  # The shared CMU walks and run blend as a set.
  throng_cli_test(locomotion.cmu_set_renders EXIT 0 STDERR "wrote .*3 characters x 31 joints"
                  ARGS render --device llvmpipe --validation -n 3 -W 32 -H 32 --speed 0.5:4
                       --locomotion ${cmu}/cmu_02_01_walk.bvh,${cmu}/cmu_07_01_walk.bvh,${cmu}/cmu_16_45_run.bvh
                       --out ${CMAKE_CURRENT_BINARY_DIR}/locomotion_cmu.png)
  set_tests_properties(locomotion.cmu_set_renders PROPERTIES ENVIRONMENT "LP_NUM_THREADS=2;ASAN_OPTIONS=detect_leaks=0")
else()
  throng_skipped_without_shared_mocap(locomotion.mismatched_skeletons_refused cli)
  throng_skipped_without_shared_mocap(locomotion.cmu_set_renders cli)
endif()
