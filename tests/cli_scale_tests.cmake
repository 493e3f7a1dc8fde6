# The same answer at any scale and position, through the CLI (issue 18; tests/
# test_scale_invariance.cpp has the trees): the teapot × 10⁻³⁰⁰ meshes to the origin's triangles
# (before the local frame fp32 flushed it to 0 and every triangle was dropped, exit 0), and the
# teapot moved by 10⁶ warns that its fp32 output cannot hold the tolerance, but not with
# --precision double. Inputs are written at test time (tests/make_placed_teapots.cmake).
# Included from tests/CMakeLists.txt.
set(PLACED_DIR ${CMAKE_CURRENT_BINARY_DIR}/placed_teapots)
add_test(NAME "cli scale: write the scaled and moved teapots"
  COMMAND ${CMAKE_COMMAND} -DDIR=${PLACED_DIR} -DTEAPOT=${PROJECT_SOURCE_DIR}/data/teapot.bpt
          -P ${CMAKE_CURRENT_SOURCE_DIR}/make_placed_teapots.cmake)
set_tests_properties("cli scale: write the scaled and moved teapots" PROPERTIES LABELS cpu
  FIXTURES_SETUP placed_teapots)

foreach(rule B T)
  add_test(NAME "cli scale: the teapot at 1e-300 keeps the origin's triangles, rule ${rule}"
    COMMAND ${CMAKE_COMMAND} -DCMD=$<TARGET_FILE:tessera> -DINPUT=${PLACED_DIR}/teapot_1e-300.bpt
            -DREFERENCE=${PROJECT_SOURCE_DIR}/data/teapot.bpt "-DARGS=-m;${rule};--backend;cpu"
            -P ${CMAKE_CURRENT_SOURCE_DIR}/expect_same_triangles.cmake)
  set_tests_properties("cli scale: the teapot at 1e-300 keeps the origin's triangles, rule ${rule}"
    PROPERTIES LABELS cpu FIXTURES_REQUIRED placed_teapots)
endforeach()

set(fp32_warning "tessera: warning: the fp32 mesh cannot hold the accuracy asked for: its coordinates reach 1e\\+06")
add_test(NAME "cli scale: the teapot at 1e6 warns that fp32 cannot hold the tolerance"
  COMMAND tessera tessellate ${PLACED_DIR}/teapot_1e6.bpt --backend cpu
          -o ${CMAKE_CURRENT_BINARY_DIR}/cli_teapot_1e6.obj)
set_tests_properties("cli scale: the teapot at 1e6 warns that fp32 cannot hold the tolerance"
  PROPERTIES LABELS cpu FIXTURES_REQUIRED placed_teapots
  PASS_REGULAR_EXPRESSION "${fp32_warning}.*more than 10% of the tolerance.*--precision double")
add_test(NAME "cli scale: the teapot at 1e6 warns with rule B, against its size"
  COMMAND tessera tessellate ${PLACED_DIR}/teapot_1e6.bpt -m B --backend cpu --stats -
          -o ${CMAKE_CURRENT_BINARY_DIR}/cli_teapot_1e6_B.ply)
set_tests_properties("cli scale: the teapot at 1e6 warns with rule B, against its size"
  PROPERTIES LABELS cpu FIXTURES_REQUIRED placed_teapots
  PASS_REGULAR_EXPRESSION "\"code\": \"fp32-output\",[^}]*0.01% of the model's size")
add_test(NAME "cli scale: the teapot at 1e6 written in double does not warn"
  COMMAND tessera tessellate ${PLACED_DIR}/teapot_1e6.bpt --backend cpu --precision double
          -o ${CMAKE_CURRENT_BINARY_DIR}/cli_teapot_1e6_double.obj)
set_tests_properties("cli scale: the teapot at 1e6 written in double does not warn"
  PROPERTIES LABELS cpu FIXTURES_REQUIRED placed_teapots
  PASS_REGULAR_EXPRESSION "wrote " FAIL_REGULAR_EXPRESSION "warning")
