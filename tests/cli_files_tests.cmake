# Files through the CLI (issue 18): extensions in any case. Included from tests/CMakeLists.txt.
set(FILES_TEST_DIR ${CMAKE_CURRENT_BINARY_DIR}/cli_files)
file(MAKE_DIRECTORY ${FILES_TEST_DIR})
configure_file(${PROJECT_SOURCE_DIR}/data/teacup.bpt ${FILES_TEST_DIR}/TEACUP.BPT COPYONLY)
add_test(NAME "cli: upper-case extensions choose the formats"
  COMMAND tessera tessellate ${FILES_TEST_DIR}/TEACUP.BPT --backend cpu -m B
          -o ${FILES_TEST_DIR}/TEACUP.OBJ)
set_tests_properties("cli: upper-case extensions choose the formats" PROPERTIES LABELS cpu
  PASS_REGULAR_EXPRESSION "method B, .*wrote .*TEACUP.OBJ")
