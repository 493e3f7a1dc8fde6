# A bench's command line is checked before any work: `${CMD} --help` prints the usage and exits
# 0; `${CMD} ${BAD}` names what is wrong (BAD_TEXT) and the usage on stderr and exits 2.
get_filename_component(name ${CMD} NAME)
execute_process(COMMAND ${CMD} --help RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err
                TIMEOUT 20)
if(NOT code EQUAL 0 OR NOT out MATCHES "usage: ${name} ")
  message(FATAL_ERROR "--help: exit code ${code}, expected 0 and the usage: ${out}${err}")
endif()
execute_process(COMMAND ${CMD} ${BAD} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err
                TIMEOUT 20)
if(NOT code EQUAL 2)
  message(FATAL_ERROR "${BAD}: exit code ${code}, expected 2: ${err}")
endif()
if(NOT err MATCHES "${BAD_TEXT}" OR NOT err MATCHES "usage: ${name} ")
  message(FATAL_ERROR "${BAD}: stderr does not name '${BAD_TEXT}' and the usage: ${err}")
endif()
