# A malformed surface on stdin: exit 2, the error names "<stdin>:<line>: ", stdout stays empty.
# -DCMD=tessera -DINPUT=<bad file> -DFORMATS=bpt,obj -DEXPECT_TEXT=<regex>
execute_process(COMMAND ${CMD} tessellate - -o - --format ${FORMATS} --backend cpu
                INPUT_FILE ${INPUT} RESULT_VARIABLE code ERROR_VARIABLE err OUTPUT_VARIABLE out)
if(NOT code EQUAL 2)
  message(FATAL_ERROR "exit code ${code}, expected 2: ${err}")
endif()
if(NOT err MATCHES "${EXPECT_TEXT}")
  message(FATAL_ERROR "stderr does not match ${EXPECT_TEXT}: ${err}")
endif()
if(NOT out STREQUAL "")
  message(FATAL_ERROR "something was written to stdout despite the error")
endif()
