# Runs `${CMD} tessellate ${INPUT} ${ARGS} -o <dir>/held.<FORMAT>` (FORMAT ply unless given,
# or glb) and the same with STREAM_ARGS added (a --memory-budget the held mesh exceeds, or
# --stream-patches) into streamed.<FORMAT>, both with exit 0; checks that the streamed run
# streamed (its summary says so, and with a budget stderr says why), and that both files have
# the same vertex and face counts (PLY: its header; GLB: the POSITION accessor's count and the
# indices accessor's count / 3, read from the JSON chunk), and more than 0: each seam vertex
# written once, every triangle there (tests/CMakeLists.txt; the triangle sets themselves are
# compared in tests/test_streamed_tessellation.cpp).
if(NOT DEFINED FORMAT)
  set(FORMAT ply)
endif()
file(MAKE_DIRECTORY ${DIR})  # one per test: CTest may run them at once
foreach(run held streamed)
  set(args ${ARGS})
  if(run STREQUAL "streamed")
    list(APPEND args ${STREAM_ARGS})
  endif()
  set(path ${DIR}/${run}.${FORMAT})
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
  if(FORMAT STREQUAL "glb")
    # The JSON chunk follows the binary "JSON" chunk type: the printable run that holds it.
    file(STRINGS ${path} texts REGEX "JSON{" LIMIT_COUNT 1)
    string(REGEX REPLACE "^.*JSON{" "{" document "${texts}")
    string(JSON position GET "${document}" meshes 0 primitives 0 attributes POSITION)
    string(JSON indices GET "${document}" meshes 0 primitives 0 indices)
    string(JSON vertices GET "${document}" accessors ${position} count)
    string(JSON corners GET "${document}" accessors ${indices} count)
    math(EXPR faces "${corners} / 3")
    list(APPEND counts "${vertices} vertices, ${faces} faces")
  else()
    file(READ ${path} header LIMIT 400)
    if(NOT header MATCHES "element vertex ([0-9]+)\n.*element face ([0-9]+)\n")
      message(FATAL_ERROR "${path}: no PLY header counts")
    endif()
    list(APPEND counts "${CMAKE_MATCH_1} vertices, ${CMAKE_MATCH_2} faces")
  endif()
endforeach()
list(GET counts 0 held)
list(GET counts 1 streamed)
if(NOT held STREQUAL streamed OR held MATCHES "^0 ")
  message(FATAL_ERROR "held: ${held}; streamed: ${streamed}")
endif()
message(STATUS "held and streamed: ${held}")
