# Runs `${CMD} tessellate ${INPUT} ${ARGS} -o <dir>/held.ply` and the same with STREAM_ARGS
# added (a --memory-budget the held mesh exceeds, or --stream-patches) into streamed.ply, both
# with exit 0; checks that the streamed run streamed (its summary says so, and with a budget
# stderr says why), and that both files have the same vertex and face counts in their headers,
# and more than 0: each seam vertex written once, every triangle there (tests/CMakeLists.txt;
# the triangle sets themselves are compared in tests/test_streamed_tessellation.cpp).
file(MAKE_DIRECTORY ${DIR})  # one per test: CTest may run them at once
foreach(run held streamed)
  set(args ${ARGS})
  if(run STREQUAL "streamed")
    list(APPEND args ${STREAM_ARGS})
  endif()
  set(path ${DIR}/${run}.ply)
  file(REMOVE ${path})
  execute_process(COMMAND ${CMD} tessellate ${INPUT} ${args} -o ${path}
                  RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "${run}: exit code ${code}: ${err}")
  endif()
  if(run STREQUAL "streamed" AND NOT out MATCHES "streamed in [0-9]+ groups of up to [0-9]+ patches")
    message(FATAL_ERROR "the run did not stream: ${out}")
  endif()
  if(run STREQUAL "streamed" AND DEFINED EXPECT_TEXT AND NOT err MATCHES "${EXPECT_TEXT}")
    message(FATAL_ERROR "stderr does not say ${EXPECT_TEXT}: ${err}")
  endif()
  file(READ ${path} header LIMIT 400)
  if(NOT header MATCHES "element vertex ([0-9]+)\n.*element face ([0-9]+)\n")
    message(FATAL_ERROR "${path}: no PLY header counts")
  endif()
  list(APPEND counts "${CMAKE_MATCH_1} vertices, ${CMAKE_MATCH_2} faces")
endforeach()
list(GET counts 0 held)
list(GET counts 1 streamed)
if(NOT held STREQUAL streamed OR held MATCHES "^0 ")
  message(FATAL_ERROR "held: ${held}; streamed: ${streamed}")
endif()
message(STATUS "held and streamed: ${held}")
