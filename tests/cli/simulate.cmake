# `throng simulate` (#12): the crowd stepped without a device and written as CSV. Absurd,
# NaN, negative and zero values, a missing output folder and runs too large to write are
# refused with exit 2 and one line, before any work (10 s timeouts), leaving neither file;
# simulate_files.py runs the issue's example and checks the files themselves.
find_package(Python3 REQUIRED COMPONENTS Interpreter)
set(sim_dir "${CMAKE_CURRENT_BINARY_DIR}/simulate")
file(MAKE_DIRECTORY "${sim_dir}")
set(sim_t "${sim_dir}/never_t.csv")
set(sim_j "${sim_dir}/never_j.csv")
set(sim_help " \\(see 'throng simulate --help'\\)\n$")
set(sim_tests "")
function(throng_simulate_refused name stderr_regex)
  throng_cli_test(simulate.${name} EXIT 2 STDERR "${stderr_regex}" NO_FILE ${sim_t} ${sim_j}
                  ARGS simulate ${ARGN} --out ${sim_t} --joints-out ${sim_j})
  set(sim_tests ${sim_tests} simulate.${name} PARENT_SCOPE)
endfunction()
# Each bad --time and --fps, the other one good.
set(time_complaint "--time takes seconds, more than 0 and at most 600")
set(fps_complaint "--fps takes whole samples per second from 1 to 1000")
foreach(case "time|zero|0" "time|negative|-1" "time|nan|nan" "time|absurd|1e9" "time|infinite|inf"
             "fps|zero|0" "fps|absurd|100000" "fps|negative|-5" "fps|fraction|29.97" "fps|nan|nan")
  string(REPLACE "|" ";" parts "${case}")
  list(GET parts 0 option)
  list(GET parts 1 label)
  list(GET parts 2 value)
  set(time 1)
  set(fps 30)
  set(${option} ${value})
  throng_simulate_refused(${option}_refused_${label} "^throng: error: ${${option}_complaint}, not '${value}'${sim_help}"
                          -n 1 --time ${time} --fps ${fps})
endforeach()
throng_simulate_refused(less_than_a_frame "^throng: error: --time 0.001 is less than half a frame at --fps 30[^\n]*${sim_help}"
                        -n 1 --time 0.001 --fps 30)
throng_simulate_refused(needs_time "^throng: error: 'simulate' needs --time SECONDS${sim_help}" -n 1 --fps 30)
throng_simulate_refused(not_with_camera "^throng: error: unknown option '--camera' for 'simulate'${sim_help}"
                        -n 1 --time 1 --fps 30 --camera 1,2,3,0,0,0)
# A million characters for 600 s at 1000 fps, and joints of 10,000 for 10 s at 100 fps.
throng_simulate_refused(too_many_rows "^throng: error: 1000000 characters x 600001 frames make 600001000000 rows for --out, more than the 200000000 a file may hold[^\n]*${sim_help}"
                        -n 1000000 --time 600 --fps 1000)
throng_simulate_refused(too_many_joint_rows "^throng: error: 10000 characters x 1001 frames x 31 joints make 310310000 rows for --joints-out[^\n]*${sim_help}"
                        -n 10000 --time 10 --fps 100)
throng_simulate_refused(scene_conflict "don't combine it with --bvh, --characters"
                        --scene ${THRONG_ASSET_DIR}/scenes/plaza.json -n 5 --time 1 --fps 30)
throng_simulate_refused(bad_clip "no-such\\.bvh: error: cannot open BVH file" --bvh ${sim_dir}/no-such.bvh --time 1 --fps 30)
# A crowd too dense for its --area is named by the options that made it, not as a scene's group.
throng_simulate_refused(area_too_small "^throng: error: --area 1x1: its 1 x 1 m region is too small for 100 characters \\(placed [0-9]+ without overlaps\\)\n$"
                        -n 100 --area 1x1 --time 1 --fps 30)
# Outputs that can't be written are refused before the crowd is simulated, naming them.
throng_cli_test(simulate.out_dir_missing EXIT 2
                STDERR "^throng: [^\n]*no-such-dir/t\\.csv: error: --out: directory '[^']*no-such-dir' does not exist\n$"
                NO_FILE ${sim_j} ARGS simulate -n 1 --time 1 --fps 30 --out ${sim_dir}/no-such-dir/t.csv --joints-out ${sim_j})
throng_cli_test(simulate.joints_out_dir_missing EXIT 2
                STDERR "^throng: [^\n]*no-such-dir/j\\.csv: error: --joints-out: directory '[^']*no-such-dir' does not exist\n$"
                NO_FILE ${sim_t} ARGS simulate -n 1 --time 1 --fps 30 --out ${sim_t} --joints-out ${sim_dir}/no-such-dir/j.csv)
throng_cli_test(simulate.same_file_twice EXIT 2 STDERR "--out and --joints-out name the same file" NO_FILE ${sim_t}
                ARGS simulate -n 1 --time 1 --fps 30 --out ${sim_t} --joints-out ${sim_dir}/../simulate/never_t.csv)
list(APPEND sim_tests simulate.out_dir_missing simulate.joints_out_dir_missing simulate.same_file_twice)
set_tests_properties(${sim_tests} PROPERTIES TIMEOUT 10)

# The issue's example and a goals crowd: exact headers, row counts, byte-identical reruns and
# thread counts, both files or neither, progress and summary on stderr, no file after a signal.
add_test(NAME simulate.files
         COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/simulate_files.py --throng $<TARGET_FILE:throng>
                 --dir ${sim_dir}/files --asset-dir ${THRONG_ASSET_DIR})
set_tests_properties(simulate.files PROPERTIES LABELS cli TIMEOUT 120 PASS_REGULAR_EXPRESSION "simulate_files: PASS")
