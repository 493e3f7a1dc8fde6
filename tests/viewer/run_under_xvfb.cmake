# Runs `tessera view` scripted under a virtual X server (xvfb-run), then viewer_check on what it
# wrote. MODE picture: --screenshot, the picture must show a mesh; MODE mesh: --dump-frame, the
# frame must have no T-junction. The viewer runs with --validation: any message fails it.
# Without xvfb-run the test FAILS (a GPU run that cannot run the viewer must not pass quietly);
# a CPU-only run (ctest -LE gpu) leaves these tests out by their label.
find_program(XVFB_RUN xvfb-run)
if(NOT XVFB_RUN)
  message(FATAL_ERROR "xvfb-run is missing (apt-get install xvfb): the viewer tests need a "
                      "virtual X server. Run `ctest -LE gpu` for a deliberate CPU-only run.")
endif()
if(MODE STREQUAL "picture")
  set(output ${OUT_DIR}/viewer_frames.png)
  set(viewer_args --frames 30 --screenshot ${output})
  set(check_args picture ${output} 0.03 200)
else()
  set(output ${OUT_DIR}/viewer_frame.glb)
  set(viewer_args --frames 8 --dump-frame 7 ${output} --tolerance 0.5)
  set(check_args mesh ${output})
endif()
file(REMOVE ${output})
execute_process(
  COMMAND ${XVFB_RUN} -a -s "-screen 0 1280x800x24" ${TESSERA} view ${SCENE} --validation
          --size 640x360 ${viewer_args}
  RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT code EQUAL 0)
  message(FATAL_ERROR "tessera view exited with ${code}")
endif()
execute_process(COMMAND ${CHECK} ${check_args} RESULT_VARIABLE code)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "viewer_check ${MODE} failed (${code})")
endif()
