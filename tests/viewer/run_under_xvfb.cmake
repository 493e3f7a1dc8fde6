# Runs `tessera view` scripted under a virtual X server (xvfb-run), then viewer_check on what it
# wrote. MODE picture: --screenshot, the picture must show a mesh; MODE mesh: --dump-frame, the
# frame must have no T-junction; MODE keys: --script SCRIPT in OUT_DIR/keys, whose log and
# files viewer_check keys reads; MODE real: real_input.sh sends real X input with xdotool and
# viewer_check keys-log reads the log. The viewer runs with --validation: any message fails it.
# Without xvfb-run the test FAILS (a GPU run that cannot run the viewer must not pass quietly);
# a CPU-only run (ctest -LE gpu) leaves these tests out by their label.
find_program(XVFB_RUN xvfb-run)
if(NOT XVFB_RUN)
  message(FATAL_ERROR "xvfb-run is missing (apt-get install xvfb): the viewer tests need a "
                      "virtual X server. Run `ctest -LE gpu` for a deliberate CPU-only run.")
endif()
if(MODE STREQUAL "real")
  find_program(XDOTOOL xdotool)
  if(NOT XDOTOOL)
    message(FATAL_ERROR "xdotool is missing (apt-get install xdotool, scripts/deps.sh): the "
                        "viewer's real-input test needs it.")
  endif()
  get_filename_component(here ${CMAKE_CURRENT_LIST_FILE} DIRECTORY)
  set(workdir ${OUT_DIR}/real)
  execute_process(
    COMMAND ${XVFB_RUN} -a -s "-screen 0 1280x800x24" bash ${here}/real_input.sh ${TESSERA}
            ${SCENE} ${workdir}
    RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message("${out}${err}")
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "real_input.sh failed (${code})")
  endif()
  execute_process(COMMAND ${CHECK} keys-log ${workdir}/real.log 60 -20 RESULT_VARIABLE code)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "viewer_check keys-log failed (${code})")
  endif()
  return()
endif()
set(workdir ${OUT_DIR})
set(size 640x360)
if(MODE STREQUAL "keys")
  set(workdir ${OUT_DIR}/keys)
  set(output ${workdir}/view.log)
  file(REMOVE_RECURSE ${workdir})
  file(MAKE_DIRECTORY ${workdir})
  set(size 480x270)
  set(viewer_args --script ${SCRIPT})
  set(check_args keys ${output} ${workdir})
elseif(MODE STREQUAL "picture")
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
          --size ${size} ${viewer_args}
  WORKING_DIRECTORY ${workdir} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(MODE STREQUAL "keys")
  file(WRITE ${output} "${out}")
endif()
if(NOT code EQUAL 0)
  message(FATAL_ERROR "tessera view exited with ${code}")
endif()
execute_process(COMMAND ${CHECK} ${check_args} RESULT_VARIABLE code)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "viewer_check ${MODE} failed (${code})")
endif()
