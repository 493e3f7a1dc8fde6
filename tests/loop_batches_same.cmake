# `tessera loop|limit ... --backend vulkan --batch-bytes SIZE` against the same run without it: a
# bound far below the table's size sends the stencils in batches of rows (host/loop/
# stencil_slices.h), as a table past the device's storage buffer range goes, and the file must be
# byte for byte the one the single-submission run writes.
# -DCMD=tessera -DCOMMAND=loop|limit -DINPUT=<control mesh> -DLEVELS=n -DBYTES=4K -DWORK_DIR=<dir>
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})
execute_process(COMMAND ${CMD} ${COMMAND} ${INPUT} -l ${LEVELS} --backend vulkan -o ${WORK_DIR}/whole.obj
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0 OR out MATCHES " in [0-9]+ batches")
  message(FATAL_ERROR "the run without --batch-bytes failed (${code}) or went in batches: ${out}${err}")
endif()
execute_process(COMMAND ${CMD} ${COMMAND} ${INPUT} -l ${LEVELS} --backend vulkan --batch-bytes ${BYTES}
                        -o ${WORK_DIR}/batched.obj
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0 OR NOT out MATCHES "on vulkan:.* in [0-9]+ batches: wrote")
  message(FATAL_ERROR "the run with --batch-bytes ${BYTES} failed (${code}) or did not batch: ${out}${err}")
endif()
file(SHA256 ${WORK_DIR}/whole.obj expected)
file(SHA256 ${WORK_DIR}/batched.obj actual)
if(NOT expected STREQUAL actual)
  message(FATAL_ERROR "the batched run's mesh differs from the whole run's")
endif()
message(STATUS "${out}")
