# Builds TARGET in BUILD_DIR and passes only when the build fails with EXPECT_TEXT in its output
# (a build that fails for another reason, or succeeds, fails the test).
execute_process(COMMAND ${CMAKE_COMMAND} --build "${BUILD_DIR}" --target "${TARGET}"
  RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(code EQUAL 0)
  message(FATAL_ERROR "${TARGET} compiled, but it must not: core code reached the Vulkan layer")
endif()
string(FIND "${out}${err}" "${EXPECT_TEXT}" at)
if(at EQUAL -1)
  message(FATAL_ERROR "${TARGET} failed to build, but not with \"${EXPECT_TEXT}\":\n${out}${err}")
endif()
message(STATUS "${TARGET} refused as expected: ${EXPECT_TEXT}")
