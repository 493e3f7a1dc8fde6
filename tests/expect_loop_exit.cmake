# Runs `${CMD} ${ARGS}` (ARGS a ;-list) and checks the exit code, that stderr matches
# EXPECT_TEXT, and that no output ${OUTPUT} was left behind. For the Loop subcommands' errors.
execute_process(COMMAND ${CMD} ${ARGS} -o ${OUTPUT}
                RESULT_VARIABLE code ERROR_VARIABLE err OUTPUT_VARIABLE out)
if(NOT code EQUAL ${EXPECT_CODE})
  message(FATAL_ERROR "exit code ${code}, expected ${EXPECT_CODE}: ${err}")
endif()
if(NOT err MATCHES "${EXPECT_TEXT}")
  message(FATAL_ERROR "stderr does not match ${EXPECT_TEXT}: ${err}")
endif()
if(EXISTS ${OUTPUT})
  message(FATAL_ERROR "an output file was written despite the error")
endif()
