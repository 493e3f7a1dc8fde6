# tessera and tessera-cad (host/cli/cad_job.h): tessera links no Open CASCADE and hands CAD
# models to tessera-cad. Included from tests/CMakeLists.txt.
set(handoff_needed -DREADELF=${CMAKE_READELF} -DLEAN=$<TARGET_FILE:tessera>)
if(TARGET tessera-cad)
  list(APPEND handoff_needed -DCAD=$<TARGET_FILE:tessera-cad>)
endif()
add_test(NAME "cli: tessera links no Open CASCADE, tessera-cad does"
  COMMAND ${CMAKE_COMMAND} ${handoff_needed} -P ${CMAKE_CURRENT_SOURCE_DIR}/expect_no_occt_linked.cmake)
set_tests_properties("cli: tessera links no Open CASCADE, tessera-cad does" PROPERTIES LABELS cpu)

if(TARGET tessera-cad)  # the model: freecad-common (scripts/deps.sh)
  add_test(NAME "cli: tessera hands a STEP model to tessera-cad: the same mesh, or exit 2 without it"
    COMMAND ${CMAKE_COMMAND} -DLEAN=$<TARGET_FILE:tessera> -DCAD=$<TARGET_FILE:tessera-cad>
            -DMODEL=/usr/share/freecad/Mod/Idf/Idflibs/1210_SMD.stp
            -DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/cli_cad_handoff
            -P ${CMAKE_CURRENT_SOURCE_DIR}/expect_cad_handoff.cmake)
  set_tests_properties("cli: tessera hands a STEP model to tessera-cad: the same mesh, or exit 2 without it"
    PROPERTIES LABELS cpu)
else()  # a build without Open CASCADE: no tessera-cad to hand the model to
  add_test(NAME "cli: without tessera-cad a STEP model exits 2 naming it"
    COMMAND ${CMAKE_COMMAND} -DCMD=$<TARGET_FILE:tessera> "-DARGS=tessellate;model.step"
            -DOUTPUT=${CMAKE_CURRENT_BINARY_DIR}/cli_no_cad.obj -DEXPECT_CODE=2
            "-DEXPECT_TEXT=model.step: .*tessera-cad, which is not there"
            -P ${CMAKE_CURRENT_SOURCE_DIR}/expect_exit.cmake)
  set_tests_properties("cli: without tessera-cad a STEP model exits 2 naming it" PROPERTIES
    LABELS cpu)
endif()
