# Scene files' locomotion sets (#12): groups blending the project's set and the shared CMU set
# render under validation; each bad set or ground speed is refused with exit 2 and one line
# naming the scene file and the JSON path, and leaves no file.
set(scenes "${THRONG_TEST_DATA_DIR}/scenes")
set(loco_scene_out "${CMAKE_CURRENT_BINARY_DIR}/scene-locomotion-never.png")

# throng_locomotion_scene_refused(NAME SCENE_FILE STDERR_REGEX): exit 2, exactly one line on
# stderr, "throng: SCENE_FILE[:line:column]: error: " then the regex, and no output image.
function(throng_locomotion_scene_refused name scene stderr_regex)
  get_filename_component(file "${scene}" NAME_WE)
  throng_cli_test(scene.locomotion_${name} EXIT 2 STDERR "^throng: [^\n]*${file}\\.json(:[0-9]+:[0-9]+)?: error: ${stderr_regex}[^\n]*\n$"
                  NO_FILE ${loco_scene_out} ARGS render --scene ${scene} --out ${loco_scene_out})
endfunction()

throng_locomotion_scene_refused(unknown_clip ${scenes}/locomotion_unknown_clip.json "at /groups/0/locomotion/walk: no clip is named 'wlak'")
throng_locomotion_scene_refused(with_clips ${scenes}/locomotion_with_clips.json
                                "at /groups/0/clips: a group blends its \"locomotion\" set or plays \"clips\". give one or the other")
throng_locomotion_scene_refused(with_speed ${scenes}/locomotion_with_speed.json
                                "at /groups/0/speed: \"speed\" is a playback multiplier for \"clips\"")
throng_locomotion_scene_refused(ground_speed_alone ${scenes}/locomotion_ground_speed_alone.json
                                "at /groups/0/ground_speed: a ground speed needs \"locomotion\"")
throng_locomotion_scene_refused(ground_speed_reversed ${scenes}/locomotion_ground_speed_reversed.json
                                "at /groups/0/ground_speed: expected 0 <= min <= max <= 20 m/s, found \\[2,1\\]")
throng_locomotion_scene_refused(ground_speed_negative ${scenes}/locomotion_ground_speed_negative.json
                                "at /groups/0/ground_speed: expected 0 <= min <= max <= 20 m/s, found \\[-1,1\\]")
throng_locomotion_scene_refused(ground_speed_too_fast ${scenes}/locomotion_ground_speed_too_fast.json
                                "at /groups/0/ground_speed: expected 0 <= min <= max <= 20 m/s, found \\[1,25\\]")
# JSON has no NaN: the reader refuses the text itself, at its line and column.
throng_locomotion_scene_refused(ground_speed_nan ${scenes}/locomotion_ground_speed_nan.json "invalid JSON: ")
# Refused once the clips are baked: a part that isn't what it is called, a set the bake refuses.
throng_locomotion_scene_refused(idle_walks ${scenes}/locomotion_idle_walks.json
                                "at /groups/0/locomotion/idle: clip 'walk' walks \\(a gait at 1.30 m/s\\): an idle stands still")
throng_locomotion_scene_refused(parts_swapped ${scenes}/locomotion_parts_swapped.json
                                "at /groups/0/locomotion/run: clip 'walk' goes 1.30 m/s, slower than the walk 'run' \\(2.80 m/s\\)")
throng_locomotion_scene_refused(same_speed ${scenes}/locomotion_same_speed.json
                                "at /groups/1/locomotion: locomotion set: [^\n]* walk at nearly the same speed")

# Two groups blend the project's whole set (one shared set entry), one plays the walk.
throng_cli_test(scene.locomotion_project_set_renders EXIT 0 STDERR "wrote .*12 characters x 31 joints"
                ARGS render --device llvmpipe --validation --scene ${scenes}/locomotion_project_set.json --time 2
                     --width 64 --height 48 --out ${CMAKE_CURRENT_BINARY_DIR}/scene_locomotion_project.png)
set_tests_properties(scene.locomotion_project_set_renders PROPERTIES ENVIRONMENT "ASAN_OPTIONS=detect_leaks=0;LP_NUM_THREADS=2")
# The example scene in assets/scenes.
throng_cli_test(scene.locomotion_example_renders EXIT 0 STDERR "wrote .*characters x 31 joints"
                ARGS render --device llvmpipe --validation --scene ${THRONG_ASSET_DIR}/scenes/paces.json --time 2
                     --width 160 --height 90 --out ${CMAKE_CURRENT_BINARY_DIR}/paces.png)
set_tests_properties(scene.locomotion_example_renders PROPERTIES ENVIRONMENT "ASAN_OPTIONS=detect_leaks=0;LP_NUM_THREADS=2")

if(THRONG_HAVE_SHARED_MOCAP)
  # Scenes naming the shared captures by absolute path, written at configure time.
  set(cmu "${THRONG_SHARED_MOCAP_DIR}")
  set(cmu_scene "${CMAKE_CURRENT_BINARY_DIR}/locomotion_cmu_set.json")
  file(WRITE "${cmu_scene}" "{\"clips\": [{\"name\": \"02_01\", \"path\": \"${cmu}/cmu_02_01_walk.bvh\"},
  {\"name\": \"07_01\", \"path\": \"${cmu}/cmu_07_01_walk.bvh\"}, {\"name\": \"16_45\", \"path\": \"${cmu}/cmu_16_45_run.bvh\"}],
 \"groups\": [{\"count\": 3, \"mode\": \"goals\", \"locomotion\": {\"slow_walk\": \"02_01\", \"walk\": \"07_01\", \"run\": \"16_45\"},
              \"ground_speed\": [0.5, 4], \"region\": {\"centre\": [0, 0], \"size\": [6, 6]}},
             {\"count\": 2, \"locomotion\": {\"walk\": \"02_01\", \"run\": \"16_45\"}, \"ground_speed\": 3,
              \"region\": {\"centre\": [0, 8], \"size\": [6, 6]}}]}\n")
  throng_cli_test(scene.locomotion_cmu_set_renders EXIT 0 STDERR "wrote .*5 characters x 31 joints"
                  ARGS render --device llvmpipe --validation --scene ${cmu_scene} --time 1 --width 64 --height 48
                       --out ${CMAKE_CURRENT_BINARY_DIR}/scene_locomotion_cmu.png)
  set_tests_properties(scene.locomotion_cmu_set_renders PROPERTIES ENVIRONMENT "ASAN_OPTIONS=detect_leaks=0;LP_NUM_THREADS=2")
  # A 19-joint walk in a set with the project's 31-joint walk.
  set(mismatched_scene "${CMAKE_CURRENT_BINARY_DIR}/locomotion_mismatched_skeleton.json")
  file(WRITE "${mismatched_scene}" "{\"clips\": [{\"name\": \"walk\", \"path\": \"${THRONG_ASSET_DIR}/walk.bvh\"},
  {\"name\": \"walk19\", \"path\": \"${cmu}/bvhtoolbox_walk01_19j_zxy_24fps.bvh\"}],
 \"groups\": [{\"count\": 3, \"locomotion\": {\"walk\": \"walk\", \"run\": \"walk19\"}, \"region\": {\"centre\": [0, 0], \"size\": [6, 6]}}]}\n")
  throng_locomotion_scene_refused(mismatched_skeleton ${mismatched_scene}
                                  "at /groups/0/locomotion: locomotion set: [^\n]*has a different skeleton")
else()
  throng_skipped_without_shared_mocap(scene.locomotion_cmu_set_renders cli)
  throng_skipped_without_shared_mocap(scene.locomotion_mismatched_skeleton cli)
endif()
