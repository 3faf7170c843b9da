# Test captures with known answers for the root-motion acceptance tests (issue #11). The
# project's walk generator writes them at test time into the build tree, never the source
# tree: `tools/make_walk_bvh.py --suite` writes each clip (tools/walk_variants.py SUITE),
# re-reads and checks it (every joint at C times its Y-up place, the loop, the feet, the
# known answers measured back from the file) and writes known_answers.json beside them:
# arc speed, turn rate, stature, up axis and travel joint of each clip, from the
# generator's parameters. A failed check fails the fixture, so no test reads a bad clip.
# THRONG_GENERATED_CLIPS_DIR is set in tests/CMakeLists.txt, for the tests that read them too.
add_test(NAME generated_clips.write
         COMMAND ${Python3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/tools/make_walk_bvh.py --suite ${THRONG_GENERATED_CLIPS_DIR})
set_tests_properties(generated_clips.write PROPERTIES FIXTURES_SETUP generated_clips LABELS generated_clips)

# The engine parses each clip (exit 0, its frame count). Nothing about root motion here:
# the acceptance tests that read known_answers.json assert that.
set(EXPECT "${CMAKE_CURRENT_SOURCE_DIR}/cli/expect_exit.cmake")  # for throng_cli_test
set(clips yup_walk static_root_walk zup_walk xup_walk curving_walk slow_walk two_frames)
set(frame_counts 199 199 199 199 265 265 2)
foreach(clip frames IN ZIP_LISTS clips frame_counts)
  throng_cli_test(generated_clips.parse.${clip} EXIT 0 STDOUT "\"frame_count\":${frames}[,}]"
                  ARGS bvh info ${THRONG_GENERATED_CLIPS_DIR}/${clip}.bvh --json -)
  set_tests_properties(generated_clips.parse.${clip} PROPERTIES FIXTURES_REQUIRED generated_clips
                       LABELS "cli;generated_clips")
endforeach()
# Two frames of a two-legged walk have no gait cycle: bvh info says so, not that it lacks legs.
throng_cli_test(generated_clips.two_frames_footfalls EXIT 0 STDOUT "Footfalls:   none \\(the clip is too short for a gait cycle\\)"
                ARGS bvh info ${THRONG_GENERATED_CLIPS_DIR}/two_frames.bvh)
set_tests_properties(generated_clips.two_frames_footfalls PROPERTIES FIXTURES_REQUIRED generated_clips LABELS "cli;generated_clips")
# known_answers.json parses and names every clip.
list(TRANSFORM clips APPEND .bvh OUTPUT_VARIABLE clip_files)
add_test(NAME generated_clips.parse.known_answers
         COMMAND ${Python3_EXECUTABLE} -c "import json, sys; d = json.load(open(sys.argv[1]))['clips']; assert sorted(d) == sorted(sys.argv[2:]), sorted(d); print('known answers for', len(d), 'clips')"
                 ${THRONG_GENERATED_CLIPS_DIR}/known_answers.json ${clip_files})
set_tests_properties(generated_clips.parse.known_answers PROPERTIES FIXTURES_REQUIRED generated_clips LABELS generated_clips)

# Without variant options the generator still writes the project's clip byte for byte.
add_test(NAME generated_clips.default_is_the_asset
         COMMAND sh -c "${Python3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/tools/make_walk_bvh.py --out ${CMAKE_CURRENT_BINARY_DIR}/default_walk.bvh --check && cmp ${CMAKE_CURRENT_BINARY_DIR}/default_walk.bvh ${THRONG_ASSET_DIR}/walk.bvh")
set_tests_properties(generated_clips.default_is_the_asset PROPERTIES LABELS generated_clips)

# The locomotion set's generator checks its clips and writes the project's idle, slow walk and
# run byte for byte.
add_test(NAME generated_clips.locomotion_set_is_the_assets
         COMMAND sh -c "${Python3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/tools/make_locomotion_set.py --dir ${CMAKE_CURRENT_BINARY_DIR}/locomotion_set --check && for c in idle slow_walk run; do cmp ${CMAKE_CURRENT_BINARY_DIR}/locomotion_set/$c.bvh ${THRONG_ASSET_DIR}/$c.bvh || exit 1; done")
set_tests_properties(generated_clips.locomotion_set_is_the_assets PROPERTIES LABELS generated_clips)
