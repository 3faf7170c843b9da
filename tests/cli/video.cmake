# `throng render --duration` (#15): videos out. Bad combinations are refused with exit 2 and
# one line, before any work, leaving no file (10 s timeouts); video_test.py makes the videos
# and checks them with FFmpeg's tools and GNU parallel (Debian packages ffmpeg, parallel).
set(video_dir "${CMAKE_CURRENT_BINARY_DIR}/video")
file(MAKE_DIRECTORY "${video_dir}")
set(video_help " \\(see 'throng render --help'\\)\n$")
throng_cli_test(video.mp4_needs_duration EXIT 2 STDERR "^throng: error: --out [^\n]*never.mp4 is a video: give --duration SECONDS${video_help}"
                NO_FILE ${video_dir}/never.mp4 ARGS render -n 1 --out ${video_dir}/never.mp4)
throng_cli_test(video.duration_needs_a_video EXIT 2 STDERR "^throng: error: --duration writes a video: give --out FILE.mp4, FILE.gif or a frame pattern"
                NO_FILE ${video_dir}/never.png ARGS render -n 1 --duration 2 --out ${video_dir}/never.png)
throng_cli_test(video.fps_needs_duration EXIT 2 STDERR "^throng: error: --fps and --frames shape a video: give --duration SECONDS too"
                NO_FILE ${video_dir}/never.png ARGS render -n 1 --fps 25 --out ${video_dir}/never.png)
throng_cli_test(video.frames_past_the_end EXIT 2 STDERR "^throng: error: --frames 30:60 passes the video's last frame, 59${video_help}"
                NO_FILE ${video_dir}/never.mp4 ARGS render -n 1 --duration 2 --frames 30:60 --out ${video_dir}/never.mp4)
throng_cli_test(video.frames_backwards EXIT 2 STDERR "^throng: error: --frames takes A:B, whole frame numbers with 0 <= A <= B, not '9:3'"
                NO_FILE ${video_dir}/never.mp4 ARGS render -n 1 --duration 2 --frames 9:3 --out ${video_dir}/never.mp4)
throng_cli_test(video.absurd_fps EXIT 2 STDERR "^throng: error: --fps takes whole frames per second from 1 to 240, not '1e9'"
                NO_FILE ${video_dir}/never.mp4 ARGS render -n 1 --duration 2 --fps 1e9 --out ${video_dir}/never.mp4)
throng_cli_test(video.nan_duration EXIT 2 STDERR "^throng: error: --duration takes seconds, more than 0 and at most 600, not 'nan'"
                NO_FILE ${video_dir}/never.mp4 ARGS render -n 1 --duration nan --out ${video_dir}/never.mp4)
throng_cli_test(video.too_long EXIT 2 STDERR "^throng: error: --time plus --duration pass 600 s" NO_FILE ${video_dir}/never.mp4
                ARGS render -n 1 --time 500 --duration 200 --out ${video_dir}/never.mp4)
throng_cli_test(video.odd_size_mp4 EXIT 2 STDERR "^throng: [^\n]*never.mp4: error: an MP4 [(]H.264, 4:2:0[)] needs an even width and height, not 161x90"
                NO_FILE ${video_dir}/never.mp4 ARGS render -n 1 --width 161 --height 90 --duration 1 --out ${video_dir}/never.mp4)
throng_cli_test(video.bad_pattern EXIT 2 STDERR "a frame pattern takes one frame number, %d or %05d, and no other '%'"
                NO_FILE ${video_dir}/0_%s.png ARGS render -n 1 --width 16 --height 16 --duration 1 --out ${video_dir}/%d_%s.png)
throng_cli_test(video.gif_fps EXIT 2 STDERR "^throng: [^\n]*never.gif: error: a GIF times its frames in hundredths of a second, [^\n]*--fps 50 at most"
                NO_FILE ${video_dir}/never.gif ARGS render -n 1 --width 32 --height 32 --duration 0.1 --fps 120 --out ${video_dir}/never.gif)
throng_cli_test(video.no_dumps EXIT 2 STDERR "^throng: error: --dump-instances and --dump-bodies write one frame: not with --duration"
                NO_FILE ${video_dir}/never.mp4 ARGS render -n 1 --duration 1 --dump-instances ${video_dir}/d.json --out ${video_dir}/never.mp4)
set_tests_properties(video.mp4_needs_duration video.duration_needs_a_video video.fps_needs_duration video.frames_past_the_end
                     video.frames_backwards video.absurd_fps video.nan_duration video.too_long video.odd_size_mp4 video.bad_pattern video.gif_fps video.no_dumps
                     PROPERTIES TIMEOUT 10 ENVIRONMENT "ASAN_OPTIONS=detect_leaks=0;LP_NUM_THREADS=2")

find_package(Python3 REQUIRED COMPONENTS Interpreter)
add_test(NAME video.files COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/video_test.py --throng $<TARGET_FILE:throng> --dir ${video_dir}/files)
set_tests_properties(video.files PROPERTIES LABELS "cli;gpu" TIMEOUT 600 PASS_REGULAR_EXPRESSION "video_test: PASS"
                     ENVIRONMENT "LP_NUM_THREADS=2;THRONG_VALIDATION=1;ASAN_OPTIONS=detect_leaks=0")

# --camera-path: not beside --camera; a bad keyframe is refused naming the file and JSON path.
file(WRITE "${video_dir}/bad_camera_path.json" "{\"camera_path\": [{\"time\": 0, \"eye\": [0, 1, 2], \"target\": [0, 0, 0]}, {\"time\": 0, \"eye\": [1, 1, 2], \"target\": [0, 0, 0]}]}")
throng_cli_test(video.camera_and_camera_path EXIT 2 STDERR "^throng: error: --camera places the camera and --camera-path moves it: give one"
                NO_FILE ${video_dir}/never.mp4
                ARGS render -n 1 --duration 1 --camera 0,1,2,0,0,0 --camera-path ${video_dir}/bad_camera_path.json --out ${video_dir}/never.mp4)
throng_cli_test(video.bad_camera_path EXIT 2
                STDERR "^throng: [^\n]*bad_camera_path.json: error: at /camera_path/1/time: expected a time after the keyframe before [(]0 s[)], found 0\n$"
                NO_FILE ${video_dir}/never.mp4 ARGS render -n 1 --duration 1 --camera-path ${video_dir}/bad_camera_path.json --out ${video_dir}/never.mp4)
set_tests_properties(video.camera_and_camera_path video.bad_camera_path PROPERTIES TIMEOUT 10 ENVIRONMENT "ASAN_OPTIONS=detect_leaks=0;LP_NUM_THREADS=2")
