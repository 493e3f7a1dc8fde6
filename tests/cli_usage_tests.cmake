# Command-line values (issue 18): out-of-range, negative-for-unsigned and non-finite values are
# a bad command line, exit 1, checked before any input is read (the input here need not exist:
# reading it would exit 2), with a message naming the option or the rule; no output written.
# Included from tests/CMakeLists.txt.
set(USAGE_DATA ${PROJECT_SOURCE_DIR}/data)

# tessera_usage_error(<test name> <expected stderr regex> <arguments...>): exit 1, no output.
function(tessera_usage_error name text)
  set(output ${CMAKE_CURRENT_BINARY_DIR}/cli_usage_never_written.obj)
  if(NOT ARGN MATCHES "^(tessellate|loop|limit|fit|join|render);")
    set(output NONE)  # commands without -o
  endif()
  string(REPLACE ";" "\\;" text_escaped "${text}")
  add_test(NAME "cli usage: ${name}"
    COMMAND ${CMAKE_COMMAND} -DCMD=$<TARGET_FILE:tessera> "-DARGS=${ARGN}" -DOUTPUT=${output}
            -DEXPECT_CODE=1 "-DEXPECT_TEXT=${text}" -P ${CMAKE_CURRENT_SOURCE_DIR}/expect_exit.cmake)
  set_tests_properties("cli usage: ${name}" PROPERTIES LABELS cpu)
endfunction()

# Quad-tree options, checked by the library's own validateQuadtreeOptions before reading.
tessera_usage_error("--linearity -1" "linearity and flatness must be finite and > 0"
                    tessellate nofile.bpt -m B --linearity -1)
tessera_usage_error("-m E" "unknown split rule 'E'" tessellate nofile.bpt -m E)
tessera_usage_error("--samples 0" "the sample count S of rules C and D must be 1..32"
                    tessellate nofile.bpt -m C --samples 0)
tessera_usage_error("--max-depth 1000" "the maximum depth is at most 32 for rule T"
                    tessellate nofile.bpt --max-depth 1000)
tessera_usage_error("-m B --max-depth 25" "the maximum depth is at most 24"
                    tessellate nofile.bpt -m B --max-depth 25)
tessera_usage_error("--node-budget 0" "the node budget must be > 0"
                    tessellate nofile.bpt --node-budget 0)
tessera_usage_error("stats -m E" "unknown split rule 'E'" stats nofile.bpt -m E)
# Unsigned options: CLI11 would wrap -1 to the largest value.
tessera_usage_error("--node-budget -1" "--node-budget: '-1' is negative"
                    tessellate nofile.bpt --node-budget -1)
tessera_usage_error("--max-depth -1" "--max-depth: '-1' is negative"
                    tessellate nofile.bpt --max-depth -1)
# Non-finite numbers, on every floating-point option (single values and lists).
foreach(case "tessellate;nofile.bpt;--frontier-budget;nan;--frontier-budget: 'nan' is not a finite number"
             "tessellate;nofile.bpt;-m;B;--linearity;inf;--linearity: 'inf' is not a finite number"
             "tessellate;nofile.bpt;-m;B;--flatness;1e400;--flatness: '1e400' is not a finite number"
             "fit;${USAGE_DATA}/loop/ball.obj;${USAGE_DATA}/loop/torus.obj;--threshold;nan;--threshold: 'nan' is not a finite number"
             "join;${USAGE_DATA}/loop/ball.obj;${USAGE_DATA}/loop/torus.obj;--paste-plane;nan;0;0;0;--paste-plane: 'nan' is not a finite number"
             "paper-table;--thresholds;0.1,nan;--thresholds: 'nan' is not a finite number")
  list(POP_BACK case text)
  list(JOIN case " " name)
  string(REPLACE "${USAGE_DATA}/" "" name "${name}")
  tessera_usage_error("${name}" "${text}" ${case})
endforeach()
tessera_usage_error("fit --lambda 0" "--lambda: λ must be in \\(0, 2\\], got 0"
                    fit ${USAGE_DATA}/loop/ball.obj ${USAGE_DATA}/loop/torus.obj --lambda 0)
tessera_usage_error("paper-table --thresholds -1" "linearity and flatness must be finite and > 0"
                    paper-table nofile.bpt --thresholds -1)
tessera_usage_error("divisions --viewport 8" "--viewport must be 16..16384 pixels"
                    divisions --viewport 8)

# join's local refinement levels: 0..kMaxLoopJoinLevels (6); 0 joins the unrefined meshes (it
# crashed with exit 139), -1 no longer silently means the default, 1000 no longer runs unbounded.
foreach(option --levels-first --levels-second)
  foreach(bad -1 7 1000)
    tessera_usage_error("join ${option} ${bad}" "${option}: Value ${bad} not in range 0 to 6"
                        join ${USAGE_DATA}/loop/ball.obj ${USAGE_DATA}/loop/torus.obj ${option} ${bad})
  endforeach()
endforeach()
add_test(NAME "cli: join --levels-first 0 joins the unrefined first mesh"
  COMMAND tessera join ${USAGE_DATA}/loop/ball.obj ${USAGE_DATA}/loop/torus.obj --levels-first 0
          -o ${CMAKE_CURRENT_BINARY_DIR}/cli_join_levels_first_0.obj)
set_tests_properties("cli: join --levels-first 0 joins the unrefined first mesh" PROPERTIES
  LABELS cpu PASS_REGULAR_EXPRESSION "levels 0/2, .*wrote ")
add_test(NAME "cli: join --levels-second 0 joins the unrefined second mesh"
  COMMAND tessera join ${USAGE_DATA}/loop/ball.obj ${USAGE_DATA}/loop/torus.obj --levels-second 0
          -o ${CMAKE_CURRENT_BINARY_DIR}/cli_join_levels_second_0.obj)
set_tests_properties("cli: join --levels-second 0 joins the unrefined second mesh" PROPERTIES
  LABELS cpu PASS_REGULAR_EXPRESSION "levels 1/0, .*wrote ")

# --precision double is for OBJ and PLY: glTF has no double attributes (issue 18).
foreach(command tessellate limit)
  set(input ${USAGE_DATA}/teapot.bpt)
  if(command STREQUAL "limit")
    set(input ${USAGE_DATA}/loop/ball.obj)
  endif()
  add_test(NAME "cli usage: ${command} --precision double with .glb"
    COMMAND ${CMAKE_COMMAND} -DCMD=$<TARGET_FILE:tessera> "-DARGS=${command};${input};--precision;double"
            -DOUTPUT=${CMAKE_CURRENT_BINARY_DIR}/cli_usage_never_written.glb -DEXPECT_CODE=1
            "-DEXPECT_TEXT=glTF \\(.glb\\) has no double vertex attributes"
            -P ${CMAKE_CURRENT_SOURCE_DIR}/expect_exit.cmake)
  set_tests_properties("cli usage: ${command} --precision double with .glb" PROPERTIES LABELS cpu)
endforeach()
tessera_usage_error("loop --precision double on Vulkan" "Vulkan computes in fp32"
                    loop ${USAGE_DATA}/loop/ball.obj --precision double --backend vulkan)
tessera_usage_error("--precision half" "--precision: half not in"
                    tessellate nofile.bpt --precision half)
tessera_usage_error("loop --boundary both" "--boundary: both not in"
                    loop ${USAGE_DATA}/loop/ball.obj --boundary both)
tessera_usage_error("CAD --precision double" "--precision: double: not for CAD models"
                    tessellate nofile.step --precision double)
tessera_usage_error("CAD --metadata" "--metadata: not for CAD models"
                    tessellate nofile.step --metadata)
# loop/limit --batch-bytes: a byte size as --memory-budget takes.
foreach(bad 0 12Q -5)
  tessera_usage_error("loop --batch-bytes ${bad}" "--batch-bytes"
                      loop ${USAGE_DATA}/loop/ball.obj --batch-bytes ${bad})
endforeach()
# join --paste-vertices: the list's form before any input is read, its numbers against the
# first mesh (92 vertices) after; one paste mode at a time.
tessera_usage_error("join --paste-vertices 3,x" "--paste-vertices: 'x' is not a vertex number"
                    join nofile.obj nofile2.obj --paste-vertices 3,x)
tessera_usage_error("join --paste-vertices 0" "--paste-vertices: vertex '0': OBJ vertex numbers start at 1"
                    join nofile.obj nofile2.obj --paste-vertices 0)
tessera_usage_error("join --paste-vertices 93" "--paste-vertices: vertex '93' is past the mesh's 92 vertices"
                    join ${USAGE_DATA}/loop/ball.obj ${USAGE_DATA}/loop/torus.obj --paste-vertices 93)
tessera_usage_error("join --paste-vertices 1,2" "--paste-vertices: .*hold no whole triangle"
                    join ${USAGE_DATA}/loop/ball.obj ${USAGE_DATA}/loop/torus.obj --paste-vertices 1,2)
tessera_usage_error("join --paste-plane with --paste-vertices" "--paste-plane excludes --paste-vertices"
                    join ${USAGE_DATA}/loop/ball.obj ${USAGE_DATA}/loop/torus.obj
                    --paste-plane 1 0 0 1 --paste-vertices 1-5)
# fit --tolerance (a distance or a percentage; no pixels), --max-rounds 1..10, --max-triangles.
tessera_usage_error("fit --tolerance 2px" "--tolerance: fit takes a distance or a percentage"
                    fit nofile.obj nofile2.obj --tolerance 2px)
tessera_usage_error("fit --tolerance 0" "the tolerance '0' is not a distance > 0"
                    fit nofile.obj nofile2.obj --tolerance 0)
tessera_usage_error("fit --max-rounds 0" "--max-rounds: Value 0 not in range 1 to 10"
                    fit nofile.obj nofile2.obj --max-rounds 0)
tessera_usage_error("fit --max-triangles 0" "--max-triangles: Value 0 not in range"
                    fit nofile.obj nofile2.obj --max-triangles 0)

# --stream-patches (docs/cli.md): what needs the whole mesh is refused before the work.
tessera_usage_error("--stream-patches with --metadata"
                    "--stream-patches: --metadata is not written while streaming"
                    tessellate nofile.bpt --stream-patches 3 --metadata)
tessera_usage_error("--stream-patches with --deviation"
                    "--stream-patches: --deviation measures the whole mesh"
                    tessellate nofile.bpt --stream-patches 3 --deviation)
tessera_usage_error("--stream-patches 0" "--stream-patches" tessellate nofile.bpt --stream-patches 0)
