# Writes the hostile inputs of tests/cli/hostile.cmake into OUT (the build tree), so nothing
# large or odd (FIFOs, symlink loops, a 7 MB scene) lives in git. Every file is small text
# built from the templates below; each name says what is wrong with it.
#   cmake -DOUT=dir -DWALK=path/to/walk.bvh -P make_data.cmake
if(NOT OUT OR NOT WALK)
  message(FATAL_ERROR "usage: cmake -DOUT=dir -DWALK=walk.bvh -P make_data.cmake")
endif()
file(REMOVE_RECURSE "${OUT}")
file(MAKE_DIRECTORY "${OUT}" "${OUT}/a_directory")

# --- BVH: a two-joint skeleton with one defect each ----------------------------------------
# Line 14 is the first frame row; its first value is the root's X position.
function(bvh name)
  cmake_parse_arguments(B "" "OFFSET;SPINE;TIME;ROW" "" ${ARGN})
  if(NOT DEFINED B_OFFSET)
    set(B_OFFSET "0 10 0")
  endif()
  if(NOT DEFINED B_SPINE)
    set(B_SPINE "Spine")
  endif()
  if(NOT DEFINED B_TIME)
    set(B_TIME "0.0333333")
  endif()
  if(NOT DEFINED B_ROW)
    set(B_ROW "0 90 0 0 0 0 1.5 -2 3")
  endif()
  file(WRITE "${OUT}/${name}.bvh"
       "HIERARCHY\nROOT Hips\n{\n  OFFSET 0 0 0\n  CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n"
       "  JOINT ${B_SPINE}\n  {\n    OFFSET ${B_OFFSET}\n    CHANNELS 3 Zrotation Xrotation Yrotation\n"
       "    End Site\n    {\n      OFFSET 0 10 0\n    }\n  }\n}\nMOTION\nFrames: 2\nFrame Time: ${B_TIME}\n"
       "${B_ROW}\n0 90 0 0 0 0 1.5 -2 3\n")
endfunction()
bvh(root_position_1e300 ROW "1e300 90 0 0 0 0 1.5 -2 3")
bvh(offset_1e300 OFFSET "0 1e300 0")
bvh(offset_overflows_fk OFFSET "0 1.7e308 0")
bvh(channel_1e308 ROW "0 90 0 0 0 0 1e308 -2 3")
bvh(rotation_1e7_degrees ROW "0 90 0 0 0 0 1e7 -2 3")
bvh(frame_time_1e-300 TIME "1e-300")
bvh(frame_time_1e308 TIME "1e308")
bvh(empty_joint_name SPINE "   ")
string(REPEAT "x" 300 long_name)
bvh(joint_name_300_bytes SPINE "${long_name}")
string(ASCII 255 ff)
string(ASCII 254 fe)
bvh(invalid_utf8_name SPINE "Spine${ff}${fe}")

# A chain of `count` nested joints below the root, each `offset` above its parent, 1 frame.
function(chain name count offset)
  string(REPEAT "JOINT j\n{\nOFFSET ${offset}\n" ${count} opening)
  math(EXPR closing_count "${count} + 1")
  string(REPEAT "}\n" ${closing_count} closing)
  file(WRITE "${OUT}/${name}.bvh"
       "HIERARCHY\nROOT Hips\n{\nOFFSET 0 0 0\nCHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n"
       "${opening}${closing}MOTION\nFrames: 1\nFrame Time: 0.0333333\n0 0 0 0 0 0\n")
endfunction()
chain(joints_100001 100000 "0 1 0")            # 100,001 joints: over the limit
chain(chain_reaches_1e11 99999 "0 1000000 0")  # every value allowed, the whole skeleton 1e11 units tall
chain(chain_99999 99999 "0 0.01 0")           # within every limit: 100,000 joints, 1000 units tall
# 2000 bones side by side from one root (allowed): no skinned body is made for it.
string(REPEAT "JOINT s\n{\nOFFSET 0.5 1 0\nEnd Site\n{\nOFFSET 0 1 0\n}\n}\n" 2000 siblings)
file(WRITE "${OUT}/siblings_2000.bvh"
     "HIERARCHY\nROOT Hips\n{\nOFFSET 0 0 0\nCHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n"
     "${siblings}}\nMOTION\nFrames: 1\nFrame Time: 0.0333333\n0 0 0 0 0 0\n")
# A skeleton of one joint with no End Site: no bone at all, which the bodies must still draw.
file(WRITE "${OUT}/lone_root.bvh" "HIERARCHY\nROOT Hips\n{\n  OFFSET 0 0 0\n  CHANNELS 0\n}\nMOTION\nFrames: 1\nFrame Time: 0.0333333\n\n")

# 160,000 frames of one 6-channel root (1.9 MB): `bvh bake --json` must take well under 5 s.
function(long_clip name frame_time)
  string(REPEAT "0 1 2 0 3 0\n1 1 2 0 3 0\n2 1 3 0 3 0\n3 1 3 0 4 0\n" 40000 rows)
  file(WRITE "${OUT}/${name}.bvh"
       "HIERARCHY\nROOT Hips\n{\n  OFFSET 0 0 0\n  CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n"
       "  End Site\n  {\n    OFFSET 0 1 0\n  }\n}\nMOTION\nFrames: 160000\nFrame Time: ${frame_time}\n${rows}")
endfunction()
long_clip(frames_160k 0.0083333)
long_clip(frames_160k_at_1mhz 0.000001)  # heading smoothing over a window of a million frames

# --- Scene files: one bad field each (the clip is the project's walk.bvh) -------------------
set(group_avoid [=[{"count": 3, "mode": "avoid", "region": {"centre": [0, 0], "size": [10, 10]}}]=])
function(scene name)
  cmake_parse_arguments(S "" "GROUPS;EXTRA" "" ${ARGN})
  if(NOT DEFINED S_GROUPS)
    set(S_GROUPS "${group_avoid}")
  endif()
  file(WRITE "${OUT}/${name}.json" "{\"clips\": [\"${WALK}\"],\n \"groups\": [${S_GROUPS}]${S_EXTRA}}\n")
endfunction()
function(group name json)  # a scene whose one group is `json`
  scene(${name} GROUPS "${json}")
endfunction()
scene(waypoint_1e39 EXTRA [=[, "waypoints": [[1e39, 0], [0, 0]]]=])
scene(waypoint_1e7 EXTRA [=[, "waypoints": [[0, 0], [0, 1e7]]]=])
scene(waypoint_minus_1e39 EXTRA [=[, "waypoints": [[-1e39, 5]]]=])
scene(camera_eye_1e39 EXTRA [=[, "camera": {"eye": [1e39, 8, -19], "target": [0, 0, 0]}]=])
scene(camera_target_1e39 EXTRA [=[, "camera": {"eye": [0, 8, -19], "target": [0, 1e39, 0]}]=])
scene(camera_fov_1e300 EXTRA [=[, "camera": {"eye": [0, 8, -19], "target": [0, 0, 0], "fov": 1e300}]=])
scene(fov_nan EXTRA [=[, "camera": {"eye": [0, 8, -19], "target": [0, 0, 0], "fov": NaN}]=])
scene(seed_1e999 EXTRA [=[,
 "seed": 1e999]=])
scene(seed_negative EXTRA [=[, "seed": -1]=])
scene(seed_1e30 EXTRA [=[, "seed": 1e30]=])
scene(area_1e39 EXTRA [=[, "area": [1e39, 1]]=])
group(heading_1e300 [=[{"count": 3, "mode": "group", "region": {"centre": [0, 0], "size": [10, 10]}, "heading": 1e300}]=])
group(centre_1e39 [=[{"count": 3, "mode": "avoid", "region": {"centre": [1e39, 0], "size": [10, 10]}}]=])
group(centre_1e10 [=[{"count": 3, "mode": "avoid", "region": {"centre": [0, 1e10], "size": [10, 10]}}]=])
group(size_1e-50 [=[{"count": 1, "region": {"centre": [0, 0], "size": [1e-50, 1]}}]=])
group(count_1e300 [=[{"count": 1e300, "region": {"centre": [0, 0], "size": [10, 10]}}]=])
group(count_uint64_max [=[{"count": 18446744073709551615, "region": {"centre": [0, 0], "size": [10, 10]}}]=])
group(speed_1e39 [=[{"count": 3, "region": {"centre": [0, 0], "size": [10, 10]}, "speed": [1e39, 1e39]}]=])
group(speed_1e-300 [=[{"count": 3, "region": {"centre": [0, 0], "size": [10, 10]}, "speed": [1e-300, 1]}]=])
group(region_too_small [=[{"count": 50, "region": {"centre": [0, 0], "size": [1, 1]}}]=])
group(speed_negative [=[{"count": 3, "region": {"centre": [0, 0], "size": [10, 10]}, "speed": [-1, 1]}]=])
# Misspelt fields: each was read as absent, with no word said.
scene(unknown_scene_field EXTRA [=[, "sed": 4]=])
group(unknown_group_field [=[{"count": 3, "region": {"centre": [0, 0], "size": [10, 10]}, "haeding": 90}]=])
group(unknown_region_field [=[{"count": 3, "region": {"centre": [0, 0], "size": [10, 10], "center": [5, 5]}}]=])
scene(unknown_camera_field EXTRA [=[, "camera": {"eye": [0, 8, -19], "target": [0, 0, 0], "fvo": 20}]=])
scene(unknown_keyframe_field EXTRA [=[, "camera_path": [{"time": 0, "eye": [0, 8, -19], "target": [0, 0, 0], "tme": 2}]]=])
scene(total_over_a_million GROUPS [=[{"count": 600000, "region": {"centre": [0, 0], "size": [1000, 1000]}},
 {"count": 600000, "region": {"centre": [0, 0], "size": [1000, 1000]}}]=])
# JSON the parser took in part: a key given twice (the last won), a NUL (the end of the text to
# it), a clip path with \u0000 in it (cut there, so the file before it opened), a count written
# 5.0 (refused as "found number"), a unit just past its limit (shown rounded into range).
scene(duplicate_seed EXTRA [=[, "seed": 1, "seed": 2]=])
group(duplicate_count [=[{"count": 3, "region": {"centre": [0, 0], "size": [10, 10]}, "count": 400}]=])
file(WRITE "${OUT}/nul_after.json" "{\"clips\": [\"${WALK}\"], \"groups\": [${group_avoid}]}\n")
execute_process(COMMAND sh -c "printf '\\000garbage' >> '${OUT}/nul_after.json'")  # CMake strings hold no NUL
file(WRITE "${OUT}/clip_path_nul.json" "{\"clips\": [\"${WALK}\\u0000.txt\"], \"groups\": [${group_avoid}]}\n")
group(count_written_5_0 [=[{"count": 5.0, "region": {"centre": [0, 0], "size": [10, 10]}}]=])
file(WRITE "${OUT}/units_past_1e6.json" "{\"clips\": [{\"path\": \"${WALK}\", \"units\": 1000000.1}], \"groups\": [${group_avoid}]}\n")
# A million waypoints (7 MB): refused by count, not by memory.
string(REPEAT "[1, 2], " 999999 many)
scene(waypoints_1e6 EXTRA ", \"waypoints\": [${many}[3, 4]]")
# 100,000 nested arrays: refused at the first one too deep, before the parser builds them.
string(REPEAT "[" 100000 deep)
file(WRITE "${OUT}/nesting_100000.json" "{\"clips\": [\n${deep}")
file(WRITE "${OUT}/empty.json" "")

# --- Things that are not regular files -----------------------------------------------------
execute_process(COMMAND mkfifo "${OUT}/fifo" RESULT_VARIABLE fifo_failed)
if(fifo_failed)
  message(FATAL_ERROR "mkfifo failed (coreutils)")
endif()
file(CREATE_LINK "loop_b" "${OUT}/loop_a" SYMBOLIC)
file(CREATE_LINK "loop_a" "${OUT}/loop_b" SYMBOLIC)
file(WRITE "${OUT}/clip_is_symlink_loop.json" "{\"clips\": [\"${OUT}/loop_a\"], \"groups\": [${group_avoid}]}\n")
file(WRITE "${OUT}/clip_is_fifo.json" "{\"clips\": [\"${OUT}/fifo\"], \"groups\": [${group_avoid}]}\n")
# Output devices through links of our own: a writer that wrongly replaced its target would
# replace the link, never /dev/null itself, even when the tests run as root.
file(CREATE_LINK /dev/null "${OUT}/null" SYMBOLIC)
file(CREATE_LINK /dev/full "${OUT}/full" SYMBOLIC)
