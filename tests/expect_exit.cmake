# Runs `${CMD} ${ARGS} -o ${OUTPUT}` (by default `tessellate nofile.bpt`) and checks its exit
# code, that stderr matches EXPECT_TEXT (e.g. names the file), and that no output was written.
# OUTPUT=NONE runs `${CMD} ${ARGS}` alone, for commands without -o.
if(NOT DEFINED ARGS)
  set(ARGS tessellate nofile.bpt)
endif()
if(NOT DEFINED OUTPUT)
  set(OUTPUT /tmp/tessera_never_written.obj)
endif()
set(output_args -o ${OUTPUT})
if(OUTPUT STREQUAL "NONE")
  set(output_args "")
endif()
execute_process(COMMAND ${CMD} ${ARGS} ${output_args}
                RESULT_VARIABLE code ERROR_VARIABLE err OUTPUT_VARIABLE out)
if(NOT code EQUAL ${EXPECT_CODE})
  message(FATAL_ERROR "exit code ${code}, expected ${EXPECT_CODE}: ${err}")
endif()
if(NOT err MATCHES "${EXPECT_TEXT}")
  message(FATAL_ERROR "stderr does not name ${EXPECT_TEXT}: ${err}")
endif()
if(NOT OUTPUT STREQUAL "NONE" AND EXISTS ${OUTPUT})
  message(FATAL_ERROR "an output file was written despite the error")
endif()
