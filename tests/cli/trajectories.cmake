# --trajectories (#15): another tool's tracks in. Each kind of bad file is refused by exit 2 and
# one line naming file:line:column, before any work, leaving no output (10 s timeouts); the
# reading options are refused without the file or beside options that would shape the crowd.
# trajectory_round_trip.py renders Throng's own simulate output back and checks every body.
set(trj_dir "${CMAKE_CURRENT_BINARY_DIR}/trajectories")
file(MAKE_DIRECTORY "${trj_dir}")
set(trj_out "${trj_dir}/never.csv")
set(trj_tests "")
# name | file text (\n for line ends) | expected "line:column: error: message" | extra options
set(trj_cases
  "empty|\\n\\n|2:1: error: the trajectory file is empty|"
  "no_header|1,0,0,0\\n1,1,1,0\\n|1:1: error: the first line is data, not a header|"
  "missing_column|id,time,x\\n1,0,0\\n|1:1: error: the header has no 'y' column|"
  "short_row|id,time,x,y\\n1,0,0,0\\n1,1,2\\n|3:6: error: the row has 3 fields|"
  "not_a_number|id,time,x,y\\n1,0,0,0\\n1,1,abc,0\\n|3:5: error: x 'abc' is not a finite number|"
  "nan|id,time,x,y\\n1,0,0,0\\n1,1,0,nan\\n|3:7: error: y 'nan' is not a finite number|"
  "absurd_coordinate|id,time,x,y\\n1,0,0,0\\n1,1,0,1e39\\n|3:7: error: y 1e39 is out of range|"
  "fractional_id|id,time,x,y\\n1.5,0,0,0\\n|2:1: error: id '1.5' is not a whole number|"
  "duplicate_frame|id,frame,x,y\\n1,0,0,0\\n1,0,1,1\\n|3:1: error: id 1 has frame 0 twice [(]line 2[)]|--trajectory-fps|10"
  "unsorted_frames|id,frame,x,y\\n1,5,0,0\\n1,3,1,1\\n|3:1: error: id 1 goes back in time|--trajectory-fps|10"
  "one_sample|id,time,x,y\\n1,0,0,0\\n2,0,0,0\\n1,1,1,1\\n|3:1: error: id 2 has one sample|"
  "no_rate|# ID FR X Y Z\\n1 0 0 0 0\\n1 1 1 1 0\\n|1:1: error: the file numbers frames but gives no frame rate|"
  "too_fast|id,time,x,y\\n1,0,0,0\\n1,0.0001,1,1\\n|3:1: error: id 1's samples on lines 2 and 3 are 0.0001 s apart|"
  "rate_out_of_range|#framerate: 5000\\n1 0 0 0 0\\n1 1 1 1 0\\n|1:1: error: the framerate line gives 5000 frames per second|")
foreach(case IN LISTS trj_cases)
  string(REPLACE "|" ";" parts "${case}")
  list(GET parts 0 name)
  list(GET parts 1 text)
  list(GET parts 2 expected)
  list(SUBLIST parts 3 -1 extra)
  list(FILTER extra EXCLUDE REGEX "^$")
  string(REPLACE "\\n" "\n" text "${text}")
  file(WRITE "${trj_dir}/${name}.csv" "${text}")
  string(REPLACE "." "\\." file_regex "${trj_dir}/${name}.csv")
  throng_cli_test(trajectories.${name} EXIT 2 STDERR "^throng: ${file_regex}:${expected}[^\n]*\n$" NO_FILE ${trj_out}
                  ARGS simulate --trajectories ${trj_dir}/${name}.csv ${extra} --time 1 --fps 10 --out ${trj_out})
  list(APPEND trj_tests trajectories.${name})
endforeach()
# A bad file fails render the same way, before a device is opened.
throng_cli_test(trajectories.render_refuses_a_bad_file EXIT 2 STDERR "^throng: [^\n]*one_sample\\.csv:3:1: error: id 2 has one sample" NO_FILE ${trj_dir}/never.png
                ARGS render --trajectories ${trj_dir}/one_sample.csv --out ${trj_dir}/never.png)
throng_cli_test(trajectories.missing_file EXIT 2 STDERR "^throng: [^\n]*no_such\\.csv" NO_FILE ${trj_out}
                ARGS simulate --trajectories ${trj_dir}/no_such.csv --time 1 --fps 10 --out ${trj_out})
throng_cli_test(trajectories.not_with_characters EXIT 2
                STDERR "^throng: error: --trajectories gives the characters and where they walk; don't combine it with --characters"
                NO_FILE ${trj_out} ARGS simulate --trajectories ${trj_dir}/one_sample.csv -n 5 --time 1 --fps 10 --out ${trj_out})
throng_cli_test(trajectories.not_with_scene EXIT 2 STDERR "don't combine it with --scene" NO_FILE ${trj_out}
                ARGS simulate --trajectories ${trj_dir}/one_sample.csv --scene x.json --time 1 --fps 10 --out ${trj_out})
throng_cli_test(trajectories.reading_options_need_the_file EXIT 2
                STDERR "^throng: error: --trajectory-axes says how to read --trajectories: give that too" NO_FILE ${trj_out}
                ARGS simulate -n 2 --trajectory-axes xz --time 1 --fps 10 --out ${trj_out})
throng_cli_test(trajectories.bad_axes EXIT 2 STDERR "--trajectory-axes takes xy, xz or auto, not 'yz'" NO_FILE ${trj_out}
                ARGS simulate --trajectories ${trj_dir}/one_sample.csv --trajectory-axes yz --time 1 --fps 10 --out ${trj_out})
list(APPEND trj_tests trajectories.render_refuses_a_bad_file trajectories.missing_file trajectories.not_with_characters
     trajectories.not_with_scene trajectories.reading_options_need_the_file trajectories.bad_axes)
set_tests_properties(${trj_tests} PROPERTIES TIMEOUT 10 ENVIRONMENT "ASAN_OPTIONS=detect_leaks=0")

find_package(Python3 REQUIRED COMPONENTS Interpreter)
add_test(NAME trajectories.round_trip
         COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/trajectory_round_trip.py --throng $<TARGET_FILE:throng>
                 --dir ${trj_dir}/round_trip)
set_tests_properties(trajectories.round_trip PROPERTIES LABELS "cli;gpu" TIMEOUT 300 PASS_REGULAR_EXPRESSION "trajectory_round_trip: PASS"
                     ENVIRONMENT "LP_NUM_THREADS=2;THRONG_VALIDATION=1;ASAN_OPTIONS=detect_leaks=0")

# bench --trajectories: the rows follow the file's tracks (the caption says so), at most as
# many characters as it has tracks.
file(WRITE "${trj_dir}/two_people.csv" "id,time,x,y\n1,0,0,0\n1,1,1.2,0\n1,2,2.4,0\n2,0,3,0\n2,1,3,1.2\n2,2,3,2.4\n")
throng_cli_test(trajectories.bench_sim_only EXIT 0
                STDOUT "motion: following [^\n]*two_people.csv, posed by idle.bvh, slow_walk.bvh, walk.bvh, run.bvh\nmode +characters[^\n]*\nfollow +2 "
                ARGS bench --sim-only --trajectories ${trj_dir}/two_people.csv --frames 5 --warmup 1)
# (The file is read, and said so, before the sizes can be checked: two lines, the error last.)
add_test(NAME trajectories.bench_more_than_the_tracks
         COMMAND sh -c "$<TARGET_FILE:throng> bench --sim-only --trajectories ${trj_dir}/two_people.csv --characters 3 --frames 5 2>&1; echo exit=$?")
set_tests_properties(trajectories.bench_more_than_the_tracks PROPERTIES LABELS cli
                     PASS_REGULAR_EXPRESSION "\nthrong: error: --characters 3 is more than the 2 tracks of [^\n]*two_people.csv\nexit=2\n$")
throng_cli_test(trajectories.bench_not_with_bvh EXIT 2 STDERR "--trajectories gives the characters and where they walk; don't combine it with --scene, --bvh or --speed"
                ARGS bench --sim-only --trajectories ${trj_dir}/two_people.csv --bvh ${THRONG_ASSET_DIR}/walk.bvh)
set_tests_properties(trajectories.bench_sim_only trajectories.bench_more_than_the_tracks trajectories.bench_not_with_bvh
                     PROPERTIES TIMEOUT 30 ENVIRONMENT "ASAN_OPTIONS=detect_leaks=0")

# The project's example (assets/trajectories/corridor.csv) is what its stated command makes.
add_test(NAME trajectories.example_is_reproducible
         COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/example_trajectories_test.py --throng $<TARGET_FILE:throng>
                 --source-dir ${PROJECT_SOURCE_DIR} --dir ${trj_dir}/example)
set_tests_properties(trajectories.example_is_reproducible PROPERTIES LABELS cli TIMEOUT 120
                     PASS_REGULAR_EXPRESSION "example_trajectories_test: PASS" ENVIRONMENT "ASAN_OPTIONS=detect_leaks=0")

# simulate --trajectories writes what the file said back: each person under the file's own id,
# with rows only from the track's first sample to its last, both drawn (id 7 enters at 1 s, and
# at 2 s both tracks end); rows of PedPy's ID FR X Y read without a Z.
file(WRITE "${trj_dir}/late.csv" "id,time,x,y\n9,0,0,5\n9,2,2,5\n7,1,0,0\n7,2,1,0\n")
throng_cli_test(trajectories.simulate_keeps_ids_and_spans EXIT 0
                STDOUT "^id,frame,time,x,y,z,heading,speed\n9,0,0\\.000000,0\\.000000,0\\.000000,-5\\.000000,[^\n]*\n7,1,1\\.000000,0\\.000000,0\\.000000,0\\.000000,[^\n]*\n9,1,[^\n]*\n7,2,2\\.000000,1\\.000000,[^\n]*\n9,2,2\\.000000,2\\.000000,[^\n]*\n$"
                STDERR "wrote stdout: 5 rows [(]2 characters x 3 frames, each while its track lasts[)]"
                ARGS simulate --trajectories ${trj_dir}/late.csv --time 2 --fps 1 --out -)
file(WRITE "${trj_dir}/four_fields.txt" "#framerate: 2\n1 0 0 0\n1 2 1 0\n")
throng_cli_test(trajectories.pedpy_rows_without_z EXIT 0 STDOUT "\n1,1,0\\.500000,0\\.500000,0\\.000000,-?0\\.000000,"
                ARGS simulate --trajectories ${trj_dir}/four_fields.txt --time 1 --fps 2 --out -)
# Positions in centimetres read as metres: followed as read, with a warning that says why.
file(WRITE "${trj_dir}/centimetres.csv" "id,time,x,y\n1,0,0,0\n1,1,100,0\n")
throng_cli_test(trajectories.superhuman_speed_warns EXIT 0
                STDERR "throng: warning: trajectories [^\n]*centimetres\\.csv: id 1 moves at 100 m/s at 0\\.00 s, faster than people run: if the positions are not in metres, give --trajectory-units cm or mm\n"
                ARGS simulate --trajectories ${trj_dir}/centimetres.csv --time 1 --fps 1 --out ${trj_dir}/centimetres_out.csv)
set_tests_properties(trajectories.simulate_keeps_ids_and_spans trajectories.pedpy_rows_without_z trajectories.superhuman_speed_warns
                     PROPERTIES TIMEOUT 30 ENVIRONMENT "ASAN_OPTIONS=detect_leaks=0")
# A still after every track has ended draws no one, and says so.
throng_cli_test(trajectories.render_past_the_tracks EXIT 0
                STDERR "throng: warning: every track has ended by --time 3 s [(]the file spans 2\\.00 s from its first sample[)]: the picture shows no one\n"
                ARGS render --device llvmpipe --trajectories ${trj_dir}/late.csv --time 3 --width 16 --height 16 --out ${trj_dir}/past.png)
set_tests_properties(trajectories.render_past_the_tracks PROPERTIES TIMEOUT 60 ENVIRONMENT "ASAN_OPTIONS=detect_leaks=0;LP_NUM_THREADS=2")
# A video whose last frame is within the tracks says nothing (20 frames at 10 fps, the last at
# 1.9 s of tracks that end at 2 s); one that runs on past them says where they end.
add_test(NAME trajectories.video_within_the_tracks
         COMMAND $<TARGET_FILE:throng> render --device llvmpipe --trajectories ${trj_dir}/late.csv --duration 2.01 --fps 10
                 --width 16 --height 16 --out ${trj_dir}/within.gif)
set_tests_properties(trajectories.video_within_the_tracks PROPERTIES LABELS cli TIMEOUT 60 PASS_REGULAR_EXPRESSION "wrote [^\n]*within\\.gif"
                     FAIL_REGULAR_EXPRESSION "warning" ENVIRONMENT "ASAN_OPTIONS=detect_leaks=0;LP_NUM_THREADS=2")
throng_cli_test(trajectories.video_past_the_tracks EXIT 0
                STDERR "throng: warning: the tracks end at 2\\.00 s [(]from the file's first sample[)]: the video's frames after it show no one\n"
                ARGS render --device llvmpipe --trajectories ${trj_dir}/late.csv --duration 3 --fps 10 --width 16 --height 16 --out ${trj_dir}/past.gif)
set_tests_properties(trajectories.video_past_the_tracks PROPERTIES TIMEOUT 60 ENVIRONMENT "ASAN_OPTIONS=detect_leaks=0;LP_NUM_THREADS=2")
