# Runs `${CMD} tessellate ${INPUT} -o <empty dir>/out${EXT}` and checks what a user relies on
# when the input is bad: exit code 2, a message on stderr of the form "<file>:<line>: <reason>"
# matching ${EXPECT_TEXT}, and the output directory left empty (no mesh, no temporary file).
set(out_dir ${WORK_DIR}/bad_input_output)
file(REMOVE_RECURSE ${out_dir})
file(MAKE_DIRECTORY ${out_dir})
execute_process(COMMAND ${CMD} tessellate ${INPUT} --backend cpu -o ${out_dir}/out${EXT}
                RESULT_VARIABLE code ERROR_VARIABLE err OUTPUT_VARIABLE out)
if(NOT code EQUAL 2)
  message(FATAL_ERROR "exit code ${code}, expected 2: ${err}${out}")
endif()
if(NOT err MATCHES "${EXPECT_TEXT}")
  message(FATAL_ERROR "stderr does not match '${EXPECT_TEXT}': ${err}")
endif()
file(GLOB left ${out_dir}/* ${out_dir}/.*)
if(left)
  message(FATAL_ERROR "files left in the output directory despite the error: ${left}")
endif()
message(STATUS "exit 2, ${err}")
