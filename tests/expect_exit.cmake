# Runs `${CMD} ${ARGS} -o ${OUTPUT}` (by default `tessellate nofile.bpt`) and checks its exit
# code, that stderr matches EXPECT_TEXT (e.g. names the file), and that no output was written.
if(NOT DEFINED ARGS)
  set(ARGS tessellate nofile.bpt)
endif()
if(NOT DEFINED OUTPUT)
  set(OUTPUT /tmp/tessera_never_written.obj)
endif()
execute_process(COMMAND ${CMD} ${ARGS} -o ${OUTPUT}
                RESULT_VARIABLE code ERROR_VARIABLE err OUTPUT_VARIABLE out)
if(NOT code EQUAL ${EXPECT_CODE})
  message(FATAL_ERROR "exit code ${code}, expected ${EXPECT_CODE}: ${err}")
endif()
if(NOT err MATCHES "${EXPECT_TEXT}")
  message(FATAL_ERROR "stderr does not name ${EXPECT_TEXT}: ${err}")
endif()
if(EXISTS ${OUTPUT})
  message(FATAL_ERROR "an output file was written despite the error")
endif()
