# One image-regression test: render a scene with throng, then compare it with its golden
# image, tests/golden/<scene>/<W>x<H>.png. With THRONG_UPDATE_GOLDEN=1 in the environment
# the render replaces the golden instead (blessing; commit it on its own, saying why).
#   cmake -DTHRONG=... -DIMAGE_COMPARE=... -DSCENE=name -DWIDTH=w -DHEIGHT=h -DGOLDEN_DIR=...
#         -DOUT_DIR=... -DARGS="a|b|c" -P run_golden.cmake
string(REPLACE "|" ";" args "${ARGS}")
set(result "${OUT_DIR}/${SCENE}/${WIDTH}x${HEIGHT}.png")
set(golden "${GOLDEN_DIR}/${SCENE}/${WIDTH}x${HEIGHT}.png")
file(MAKE_DIRECTORY "${OUT_DIR}/${SCENE}")
file(REMOVE "${result}")
execute_process(COMMAND "${THRONG}" render --device llvmpipe --validation --width ${WIDTH} --height ${HEIGHT} ${args}
                        --out "${result}"
                RESULT_VARIABLE code ERROR_VARIABLE err)
message("${err}")
if(NOT code EQUAL 0)
  message(FATAL_ERROR "throng render failed with exit code ${code}")
endif()
if("$ENV{THRONG_UPDATE_GOLDEN}" STREQUAL "1")
  file(MAKE_DIRECTORY "${GOLDEN_DIR}/${SCENE}")
  file(COPY_FILE "${result}" "${golden}")
  message("blessed ${golden}: review it, then commit it on its own with the reason")
  return()
endif()
if(NOT EXISTS "${golden}")
  message(FATAL_ERROR "no golden image ${golden}; render and review it, then bless with "
                      "THRONG_UPDATE_GOLDEN=1 ctest --preset release -L golden")
endif()
# Same driver and thread count give the same bytes; the small tolerance only absorbs
# rounding differences between lavapipe builds, while any real change moves far more.
execute_process(COMMAND "${IMAGE_COMPARE}" "${result}" "${golden}" --tolerance 2 --max-fraction 0.001
                        --failure-dir "${OUT_DIR}/${SCENE}/failure"
                RESULT_VARIABLE compared OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT compared EQUAL 0)
  message(FATAL_ERROR "image differs from ${golden}; see ${OUT_DIR}/${SCENE}/failure")
endif()
