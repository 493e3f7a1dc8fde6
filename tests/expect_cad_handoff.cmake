# tessera hands a CAD model to the tessera-cad beside it (host/cli/cad_job.h). In WORK_DIR:
# 1. LEAN (build/tessera) and CAD (build/tessera-cad) on MODEL: exit 0, the same .obj byte for
#    byte, the same summary line;
# 2. a copy of tessera alone: exit 2, naming the missing tessera-cad, writing nothing;
# 3. a copy of tessera named tessera-cad: exit 2, no loop of execs;
# 4. a copy of tessera-cad alone: it meshes the model itself (it never execs).
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR}/alone ${WORK_DIR}/renamed ${WORK_DIR}/cad_alone)
get_filename_component(lean_name ${LEAN} NAME)
get_filename_component(cad_name ${CAD} NAME)

function(run_on_model binary obj)
  execute_process(COMMAND ${binary} tessellate ${MODEL} --backend cpu -o ${obj}
                  RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  set(code ${code} PARENT_SCOPE)
  set(out "${out}" PARENT_SCOPE)
  set(err "${err}" PARENT_SCOPE)
endfunction()

# The summary's first line: faces, edges, tolerance and backend (the later ones carry timings).
function(first_line text out)
  string(REGEX MATCH "^[^\n]*" line "${text}")
  set(${out} "${line}" PARENT_SCOPE)
endfunction()

run_on_model(${LEAN} ${WORK_DIR}/lean.obj)
if(NOT code EQUAL 0 OR NOT out MATCHES " faces \\(")
  message(FATAL_ERROR "tessera on ${MODEL}: exit ${code}: ${out}${err}")
endif()
first_line("${out}" lean_summary)
run_on_model(${CAD} ${WORK_DIR}/cad.obj)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "tessera-cad on ${MODEL}: exit ${code}: ${err}")
endif()
first_line("${out}" cad_summary)
file(SHA256 ${WORK_DIR}/lean.obj lean_hash)
file(SHA256 ${WORK_DIR}/cad.obj cad_hash)
file(SIZE ${WORK_DIR}/lean.obj size)
if(NOT lean_hash STREQUAL cad_hash OR NOT lean_summary STREQUAL cad_summary)
  message(FATAL_ERROR "tessera and tessera-cad differ on ${MODEL}:\n${lean_summary} (${lean_hash})\n"
                      "${cad_summary} (${cad_hash})")
endif()
message(STATUS "the same ${size}-byte mesh: ${lean_summary}")

file(COPY ${LEAN} DESTINATION ${WORK_DIR}/alone)
run_on_model(${WORK_DIR}/alone/${lean_name} ${WORK_DIR}/alone/never.obj)
if(NOT code EQUAL 2 OR NOT err MATCHES "${WORK_DIR}/alone/tessera-cad, which is not there"
   OR EXISTS ${WORK_DIR}/alone/never.obj)
  message(FATAL_ERROR "tessera without tessera-cad: exit ${code} (want 2, nothing written): ${err}")
endif()
message(STATUS "alone: ${err}")

file(COPY ${LEAN} DESTINATION ${WORK_DIR}/renamed)
file(RENAME ${WORK_DIR}/renamed/${lean_name} ${WORK_DIR}/renamed/tessera-cad)
run_on_model(${WORK_DIR}/renamed/tessera-cad ${WORK_DIR}/renamed/never.obj)
if(NOT code EQUAL 2 OR NOT err MATCHES "that is this executable")
  message(FATAL_ERROR "tessera named tessera-cad: exit ${code} (want 2): ${err}")
endif()

file(COPY ${CAD} DESTINATION ${WORK_DIR}/cad_alone)
run_on_model(${WORK_DIR}/cad_alone/${cad_name} ${WORK_DIR}/cad_alone/alone.obj)
file(SHA256 ${WORK_DIR}/cad_alone/alone.obj alone_hash)
if(NOT code EQUAL 0 OR NOT alone_hash STREQUAL cad_hash)
  message(FATAL_ERROR "tessera-cad alone: exit ${code}, mesh ${alone_hash}: ${err}")
endif()
