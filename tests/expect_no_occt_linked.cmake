# Checks the dynamic libraries the two executables name (ELF NEEDED entries, ${READELF} -d):
# LEAN (tessera) none of Open CASCADE's (libTK*) nor TBB, which OCCT brings; CAD (tessera-cad),
# when given, Open CASCADE's kernel and STEP reader. host/cli/cad_job.h says why.
function(needed_libraries binary out)
  execute_process(COMMAND ${READELF} -d ${binary} RESULT_VARIABLE code OUTPUT_VARIABLE text
                  ERROR_VARIABLE err)
  if(NOT code EQUAL 0 OR NOT text MATCHES "\\(NEEDED\\)")
    message(FATAL_ERROR "${READELF} -d ${binary}: exit ${code}, no NEEDED entries: ${err}")
  endif()
  string(REGEX MATCHALL "Shared library: \\[[^]]+\\]" needed "${text}")
  set(${out} "${needed}" PARENT_SCOPE)
endfunction()

needed_libraries(${LEAN} lean)
if(lean MATCHES "libTK|libtbb")
  message(FATAL_ERROR "${LEAN} links Open CASCADE or TBB: ${lean}")
endif()
message(STATUS "${LEAN}: ${lean}")
if(DEFINED CAD)
  needed_libraries(${CAD} cad)
  if(NOT cad MATCHES "libTKernel" OR NOT cad MATCHES "libTKSTEP")
    message(FATAL_ERROR "${CAD} does not link Open CASCADE's kernel and STEP reader: ${cad}")
  endif()
  message(STATUS "${CAD}: ${cad}")
endif()
