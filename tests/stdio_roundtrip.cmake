# `tessera tessellate - -o - --format ...` against the same run through files: the mesh read
# from stdin and written to stdout must be byte for byte the file the path-based run writes,
# and the summary must go to stderr (naming <stdin>), not into the mesh.
# -DCMD=tessera -DINPUT=<surface file> -DFORMATS=bpt,obj -DEXT=.obj -DWORK_DIR=<scratch dir>
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})
set(common --backend cpu -m D --flatness 0.2 --linearity 0.2)
execute_process(COMMAND ${CMD} tessellate ${INPUT} ${common} -q -o ${WORK_DIR}/by_path${EXT}
                RESULT_VARIABLE code ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "the path-based run failed (${code}): ${err}")
endif()
execute_process(COMMAND ${CMD} tessellate - -o - --format ${FORMATS} ${common}
                INPUT_FILE ${INPUT} OUTPUT_FILE ${WORK_DIR}/by_pipe${EXT}
                RESULT_VARIABLE code ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "the stdin/stdout run failed (${code}): ${err}")
endif()
if(NOT err MATCHES "<stdin>: [0-9]+ patches, method D")
  message(FATAL_ERROR "the summary did not go to stderr naming <stdin>: ${err}")
endif()
file(SHA256 ${WORK_DIR}/by_path${EXT} expected)
file(SHA256 ${WORK_DIR}/by_pipe${EXT} actual)
file(SIZE ${WORK_DIR}/by_pipe${EXT} size)
if(NOT expected STREQUAL actual OR size EQUAL 0)
  message(FATAL_ERROR "stdout (${size} bytes) differs from the file written by path")
endif()
