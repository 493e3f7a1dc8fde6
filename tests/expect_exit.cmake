# Runs `${CMD} tessellate nofile.bpt` and checks its exit code and that stderr names the file.
execute_process(COMMAND ${CMD} tessellate nofile.bpt -o /tmp/tessera_never_written.obj
                RESULT_VARIABLE code ERROR_VARIABLE err OUTPUT_VARIABLE out)
if(NOT code EQUAL ${EXPECT_CODE})
  message(FATAL_ERROR "exit code ${code}, expected ${EXPECT_CODE}: ${err}")
endif()
if(NOT err MATCHES "${EXPECT_TEXT}")
  message(FATAL_ERROR "stderr does not name ${EXPECT_TEXT}: ${err}")
endif()
if(EXISTS /tmp/tessera_never_written.obj)
  message(FATAL_ERROR "an output file was written despite the error")
endif()
