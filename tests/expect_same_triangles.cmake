# Runs `${CMD} tessellate <input> ${ARGS}` for INPUT and for REFERENCE and checks that both
# summaries report the same number of triangles, and more than 0 (a model scaled or moved
# meshes as it does at the origin: tests/cli_scale_tests.cmake).
foreach(input ${INPUT} ${REFERENCE})
  execute_process(COMMAND ${CMD} tessellate ${input} ${ARGS}
                  RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "${input}: exit code ${code}: ${err}")
  endif()
  if(NOT out MATCHES "triangles ([0-9]+),")
    message(FATAL_ERROR "${input}: no triangle count in the summary: ${out}")
  endif()
  list(APPEND counts ${CMAKE_MATCH_1})
endforeach()
list(GET counts 0 scaled)
list(GET counts 1 reference)
if(NOT scaled EQUAL reference OR scaled EQUAL 0)
  message(FATAL_ERROR "${INPUT}: ${scaled} triangles, ${REFERENCE}: ${reference}")
endif()
message(STATUS "${scaled} triangles, as ${REFERENCE}")
