# Files through the CLI (issue 18): extensions in any case. Included from tests/CMakeLists.txt.
set(FILES_TEST_DIR ${CMAKE_CURRENT_BINARY_DIR}/cli_files)
file(MAKE_DIRECTORY ${FILES_TEST_DIR})
configure_file(${PROJECT_SOURCE_DIR}/data/teacup.bpt ${FILES_TEST_DIR}/TEACUP.BPT COPYONLY)
add_test(NAME "cli: upper-case extensions choose the formats"
  COMMAND tessera tessellate ${FILES_TEST_DIR}/TEACUP.BPT --backend cpu -m B
          -o ${FILES_TEST_DIR}/TEACUP.OBJ)
set_tests_properties("cli: upper-case extensions choose the formats" PROPERTIES LABELS cpu
  PASS_REGULAR_EXPRESSION "method B, .*wrote .*TEACUP.OBJ")

# Output collisions, checked before any work: an output that is an input (by identity: the
# same name, another spelling, a hard link) or another output is a bad command line (exit 1);
# an output that cannot be written is exit 5 before the input is even read; the outputs of a
# run are written together or not at all; a symbolic link as output is written through.
# tessera_files_case(<name> <code> <text> ARGS ... [COPY ...] [HARDLINK ...] [SYMLINK ...]
#                    [DIRS ...] [UNCHANGED ...] [ABSENT ...] [PRESENT ...] [LINKS ...])
function(tessera_files_case name code text)
  cmake_parse_arguments(PARSE_ARGV 3 C "" "" "ARGS;COPY;HARDLINK;SYMLINK;DIRS;UNCHANGED;ABSENT;PRESENT;LINKS")
  string(MAKE_C_IDENTIFIER "${name}" dir)
  set(defs)
  foreach(list COPY HARDLINK SYMLINK DIRS UNCHANGED ABSENT PRESENT LINKS)
    string(REPLACE ";" "|" value "${C_${list}}")  # one argument each; the script splits at |
    list(APPEND defs "-D${list}=${value}")
  endforeach()
  add_test(NAME "cli files: ${name}"
    COMMAND ${CMAKE_COMMAND} -DCMD=$<TARGET_FILE:tessera> "-DARGS=${C_ARGS}"
            -DWORK_DIR=${FILES_TEST_DIR}/${dir} -DEXPECT_CODE=${code} "-DEXPECT_TEXT=${text}" ${defs}
            -P ${CMAKE_CURRENT_SOURCE_DIR}/expect_files_kept.cmake)
  set_tests_properties("cli files: ${name}" PROPERTIES LABELS cpu)
endfunction()

set(BALL ${PROJECT_SOURCE_DIR}/data/loop/ball.obj)
set(CUP ${PROJECT_SOURCE_DIR}/data/teacup.bpt)
tessera_files_case("loop in.obj -o in.obj keeps the control mesh" 1
  "-o: 'in.obj' is the input 'in.obj': writing it would destroy the input"
  ARGS loop in.obj -o in.obj --backend cpu COPY ${BALL}=in.obj UNCHANGED in.obj)
tessera_files_case("loop in.obj -o ./in.obj keeps the control mesh" 1 "is the input 'in.obj'"
  ARGS loop in.obj -o ./in.obj --backend cpu COPY ${BALL}=in.obj UNCHANGED in.obj)
tessera_files_case("loop onto a hard link of the input keeps it" 1 "'hard.obj' is the input 'in.obj'"
  ARGS loop in.obj -o hard.obj --backend cpu COPY ${BALL}=in.obj HARDLINK in.obj=hard.obj
  UNCHANGED in.obj)
tessera_files_case("fit onto its target keeps it" 1 "'target.obj' is the target 'target.obj'"
  ARGS fit in.obj target.obj -o target.obj COPY ${BALL}=in.obj ${BALL}=target.obj
  UNCHANGED target.obj)
tessera_files_case("-o m.obj --stats m.obj is refused" 1
  "--stats: 'm.obj' is also the -o output 'm.obj'"
  ARGS tessellate ${CUP} --backend cpu -o m.obj --stats m.obj ABSENT m.obj)
tessera_files_case("a --stats that cannot be written leaves no mesh" 5
  "stats.json: is a directory, not a file"
  ARGS tessellate ${CUP} --backend cpu -o m.obj --stats stats.json DIRS stats.json ABSENT m.obj)
tessera_files_case("an output folder that does not exist is found before the input is read" 5
  "missing/m.obj: cannot create a temporary file in directory 'missing'"
  ARGS tessellate nofile.bpt -o missing/m.obj)
tessera_files_case("a symbolic link as output is written through" 0 "wrote link.obj"
  ARGS tessellate ${CUP} --backend cpu -m B -o link.obj SYMLINK real.obj=link.obj LINKS link.obj PRESENT real.obj)

# Ctrl-C or kill during a run whose mesh is staged: the temporary file is removed and tessera
# dies of the signal (exit 128 + signal number).
foreach(sig INT TERM)
  add_test(NAME "cli files: SIG${sig} removes the staged temporary file"
    COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/expect_signal_cleanup.sh $<TARGET_FILE:tessera>
            ${PROJECT_SOURCE_DIR}/data/teapot.bpt ${FILES_TEST_DIR}/signal_${sig} ${sig})
  set_tests_properties("cli files: SIG${sig} removes the staged temporary file" PROPERTIES
    LABELS cpu)
endforeach()
