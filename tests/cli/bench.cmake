# `throng bench` output contracts and tools/plot_bench.
set(bench_env "ASAN_OPTIONS=detect_leaks=0;LP_NUM_THREADS=2")
set(bench_small --device llvmpipe --characters 10 --modes fast --frames 2 --warmup 0 --width 64 --height 64)
string(JOIN " " bench_small ${bench_small})
set(bench_out "${CMAKE_CURRENT_BINARY_DIR}/bench-out")
file(MAKE_DIRECTORY "${bench_out}")

# --csv -: stdout holds the CSV only (the caption line, the header, one row); the table goes to stderr.
add_test(NAME bench.csv_to_stdout_is_only_csv
         COMMAND sh -c "out=$($<TARGET_FILE:throng> bench ${bench_small} --csv - 2>${bench_out}/csv.err) && printf '%s\\n' \"$out\" && [ \"$(printf '%s\\n' \"$out\" | wc -l)\" -eq 3 ] && printf '%s\\n' \"$out\" | head -1 | grep -q '^# device ' && printf '%s\\n' \"$out\" | sed -n 2p | grep -q '^mode,characters,frame_ms_median,' && printf '%s\\n' \"$out\" | sed -n 3p | grep -q '^fast,10,' && grep -q 'frame_ms' ${bench_out}/csv.err")
# --json -: stdout parses as one JSON document whose header says what ran.
add_test(NAME bench.json_to_stdout_is_only_json
         COMMAND sh -c "$<TARGET_FILE:throng> bench ${bench_small} --msaa 8 --json - 2>/dev/null | python3 -c 'import json,sys; d=json.load(sys.stdin); assert isinstance(d[\"threads\"], int) and d[\"lp_threads\"] == 2, d; assert d[\"msaa\"] in (1, 2, 4, 8) and d[\"msaa\"] != 8, d[\"msaa\"]; assert d[\"rows\"][0][\"mode\"] == \"fast\"; print(\"json ok, effective msaa\", d[\"msaa\"])'")
set_tests_properties(bench.csv_to_stdout_is_only_csv bench.json_to_stdout_is_only_json PROPERTIES LABELS cli ENVIRONMENT "${bench_env}")

# plot_bench: a plot from a CSV, help, and a clean refusal of a missing output folder.
add_test(NAME plot_bench.plots_a_sweep
         COMMAND sh -c "$<TARGET_FILE:throng> bench ${bench_small} --modes fast,compute --csv ${bench_out}/sweep.csv >/dev/null 2>&1 && rm -f ${bench_out}/sweep.png && ${PROJECT_SOURCE_DIR}/tools/plot_bench ${bench_out}/sweep.csv ${bench_out}/sweep.png && head -c 8 ${bench_out}/sweep.png | od -An -c | grep -q 'P   N   G'")
set_tests_properties(plot_bench.plots_a_sweep PROPERTIES LABELS cli ENVIRONMENT "${bench_env}")
add_test(NAME plot_bench.help COMMAND ${PROJECT_SOURCE_DIR}/tools/plot_bench --help)
set_tests_properties(plot_bench.help PROPERTIES LABELS cli PASS_REGULAR_EXPRESSION "usage: tools/plot_bench")
add_test(NAME plot_bench.missing_output_folder
         COMMAND sh -c "${PROJECT_SOURCE_DIR}/tools/plot_bench ${PROJECT_SOURCE_DIR}/docs/bench_lavapipe_msaa1.csv /no/such/folder/plot.png; [ $? -eq 2 ]")
set_tests_properties(plot_bench.missing_output_folder PROPERTIES LABELS cli)
