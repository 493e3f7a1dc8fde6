# The memory budget and the input-size limit through the CLI (issue 18, docs/hardening.md):
# issue 18's out-of-memory cases scaled down, each under a small --memory-budget so that it
# stops at the estimate within a second, with exit 4 and a message naming the budget and the
# option (never exit 70, never std::bad_alloc); /dev/zero behind each reader's extension stops
# at the input-size limit. Inputs are written at test time (tests/make_big_inputs.cmake).
# Included from tests/CMakeLists.txt.
set(BIG_DIR ${CMAKE_CURRENT_BINARY_DIR}/big_inputs)
add_test(NAME "cli memory: write the big inputs"
  COMMAND ${CMAKE_COMMAND} -DDIR=${BIG_DIR} -DTEAPOT=${PROJECT_SOURCE_DIR}/data/teapot.bpt
          -P ${CMAKE_CURRENT_SOURCE_DIR}/make_big_inputs.cmake)
set_tests_properties("cli memory: write the big inputs" PROPERTIES LABELS cpu
  FIXTURES_SETUP big_inputs)

# tessera_limit_case(<name> <code> <stderr regex> <arguments...>): run, expect the exit code
# and the text, and that no output was written.
function(tessera_limit_case name code text)
  set(output ${CMAKE_CURRENT_BINARY_DIR}/cli_memory_never_written.obj)
  if(NOT ARGN MATCHES "^(tessellate|loop|limit|fit|join|render);")
    set(output NONE)
  endif()
  add_test(NAME "cli memory: ${name}"
    COMMAND ${CMAKE_COMMAND} -DCMD=$<TARGET_FILE:tessera> "-DARGS=${ARGN}" -DOUTPUT=${output}
            -DEXPECT_CODE=${code} "-DEXPECT_TEXT=${text}"
            -P ${CMAKE_CURRENT_SOURCE_DIR}/expect_exit.cmake)
  set_tests_properties("cli memory: ${name}" PROPERTIES LABELS cpu
    FIXTURES_REQUIRED big_inputs TIMEOUT 60)
endfunction()

set(budget_text "more than the memory budget of .* \\(raise it with --memory-budget SIZE\\)")
tessera_limit_case("a 4096x4096 grid is refused at its header" 4
  "the 4096×4096 grid and its 16769025 bicubic patches needs about .*${budget_text}"
  tessellate ${BIG_DIR}/grid_4096.grid --backend cpu --memory-budget 64M)
tessera_limit_case("a degree-7 B-spline of 200x200 points is refused before its pieces" 4
  "B-spline of 200×200 control points as 37249 Bézier pieces needs about .*${budget_text}"
  tessellate ${BIG_DIR}/bspline_200.json --backend cpu --memory-budget 64M)
tessera_limit_case("30000 patches are refused before the tree" 4
  "the quad-tree of 30000 patches and their mesh needs about .*${budget_text}"
  tessellate ${BIG_DIR}/patches_30k.bpt --backend cpu --memory-budget 16M)
tessera_limit_case("100 teapots with a raised node budget stop in the frontier" 4
  "the quad-tree's [0-9]+ nodes at level [0-9]+ and their mesh needs about .*${budget_text}"
  tessellate ${BIG_DIR}/teapots_100.bpt -m B --node-budget 1000000000 --backend cpu
  --memory-budget 32M)
tessera_limit_case("loop -l 8 on the torus is refused before refining" 4
  "Loop subdivision of [0-9]+ triangles to level 8 .*${budget_text}"
  loop ${PROJECT_SOURCE_DIR}/data/loop/torus.obj -l 8 --backend cpu --memory-budget 64M)
tessera_limit_case("limit -l 8 on the torus is refused before refining" 4
  "Loop subdivision of [0-9]+ triangles to level 8 .*${budget_text}"
  limit ${PROJECT_SOURCE_DIR}/data/loop/torus.obj -l 8 --backend cpu --memory-budget 64M)

# /dev/zero behind each reader's extension: the input-size limit stops it (exit 4), or with the
# default limit the text readers' line-length limit refuses it first (exit 2), after a MiB.
# A JSON scene is refused at its first NUL byte (exit 2).
set(input_text "the input is larger than the input-size limit of 256 KiB .*--max-input-size SIZE")
foreach(ext bpt grid)
  tessera_limit_case("/dev/zero as x.${ext} stops at the input-size limit" 4
    "x.${ext}: ${input_text}" tessellate ${BIG_DIR}/x.${ext} --backend cpu --max-input-size 256K)
endforeach()
tessera_limit_case("/dev/zero as x.obj stops at the input-size limit" 4
  "x.obj: ${input_text}" loop ${BIG_DIR}/x.obj --backend cpu --max-input-size 256K)
# JSON holds no raw NUL: the reader stops at the first 64 KiB block that has one.
tessera_limit_case("/dev/zero as x.json stops at the first block" 2
  "x.json:1: invalid JSON at column 1" tessellate ${BIG_DIR}/x.json --backend cpu)
tessera_limit_case("/dev/zero as x.bpt: a line longer than 1 MiB is refused" 2
  "x.bpt:1: a line longer than 1 MiB" tessellate ${BIG_DIR}/x.bpt --backend cpu)
tessera_limit_case("/dev/zero as x.obj: a line longer than 1 MiB is refused" 2
  "x.obj:1: a line longer than 1 MiB" loop ${BIG_DIR}/x.obj --backend cpu)

# CAD files (Open CASCADE reads by path): a device is refused, a file over the limit too.
if(TESSERA_HAVE_CAD)
  tessera_limit_case("/dev/zero as x.step is refused: not a regular file" 2
    "x.step: not a regular file" info ${BIG_DIR}/x.step)
  tessera_limit_case("a STEP file over --max-input-size is refused before Open CASCADE reads it" 4
    "bspline_200.step: the input is larger than the input-size limit of 100 bytes"
    info ${BIG_DIR}/bspline_200.step --max-input-size 100)
  # A tolerance under 10⁻⁹ of the model's diagonal is refused at once (exit 2, naming the
  # smallest it takes); at that smallest, a small budget stops the edges' samples (exit 4).
  tessera_limit_case("a CAD tolerance under 1e-9 of the model's diagonal is refused" 2
    "SOT23.stp: the tolerance 1e-14 is below the smallest a CAD model takes, 1e-9 of its diagonal \\([0-9.e-]+ for [0-9.]+\\)"
    tessellate /usr/share/freecad/Mod/Idf/Idflibs/SOT23.stp --tolerance 1e-14 --backend cpu)
  tessera_limit_case("the edges of a CAD model at its smallest tolerance stop at the budget" 4
    "the discretisation of the B-rep edges at δ = [0-9.e-]+ needs about .*${budget_text}"
    tessellate /usr/share/freecad/Mod/Idf/Idflibs/CAP_50SGV_8_10.stp --tolerance 0.0000001%
    --backend cpu --memory-budget 64M)
endif()

# Bad sizes are a bad command line (exit 1), like any other bad option value.
foreach(bad 0 12Q -5 1.5.2 M 1e3 nan)
  tessera_limit_case("--memory-budget ${bad} is a usage error" 1
    "--memory-budget|is not a size" tessellate ${PROJECT_SOURCE_DIR}/data/teapot.bpt
    --memory-budget ${bad})
endforeach()
tessera_limit_case("--max-input-size 0 is a usage error" 1 "is not a size"
  loop ${PROJECT_SOURCE_DIR}/data/loop/torus.obj --max-input-size 0)
add_test(NAME "cli memory: the teapot under --memory-budget 512M runs"
  COMMAND tessera tessellate ${PROJECT_SOURCE_DIR}/data/teapot.bpt --backend cpu
          -m B --memory-budget 512M --max-input-size 1M)
set_tests_properties("cli memory: the teapot under --memory-budget 512M runs" PROPERTIES
  LABELS cpu PASS_REGULAR_EXPRESSION "triangles 12370")

# The same inputs under `ulimit -v` with the default budget (taken from that limit): exit 0 or
# 4, never 70 or a kill. AddressSanitizer reserves terabytes of address space, so not there.
if(NOT TESSERA_SANITIZE)
  add_test(NAME "cli memory: the big inputs under ulimit -v end 0 or 4"
    COMMAND sh ${CMAKE_CURRENT_SOURCE_DIR}/expect_limits_under_ulimit.sh $<TARGET_FILE:tessera>
            ${BIG_DIR} ${PROJECT_SOURCE_DIR}/data/loop/torus.obj)
  set_tests_properties("cli memory: the big inputs under ulimit -v end 0 or 4" PROPERTIES
    LABELS cpu FIXTURES_REQUIRED big_inputs TIMEOUT 120)
endif()

# Streaming (issue 18, docs/hardening.md): the teapot at rule T 0.01% needs about 21 MiB held
# (exit 4 before streaming existed); written in patch groups under 16 MiB it fits, and gives
# the held mesh's counts. Under 8 MiB not even one patch with its neighbours fits: exit 4
# naming the group and the budget. (Rule T, not D 0.02: as large a tree for a tenth of the
# time, which the sanitizer run multiplies.)
add_test(NAME "cli memory: the teapot over the budget is streamed in patch groups"
  COMMAND ${CMAKE_COMMAND} -DCMD=$<TARGET_FILE:tessera> -DINPUT=${PROJECT_SOURCE_DIR}/data/teapot.bpt
          "-DARGS=--tolerance;0.01%;--backend;cpu"
          "-DSTREAM_ARGS=--memory-budget;16M" -DDIR=${CMAKE_CURRENT_BINARY_DIR}/streamed_by_budget
          "-DEXPECT_TEXT=more than the memory budget of 16.0 MiB .*; streaming the mesh in patch groups instead"
          -P ${CMAKE_CURRENT_SOURCE_DIR}/expect_streamed_output.cmake)
set_tests_properties("cli memory: the teapot over the budget is streamed in patch groups"
  PROPERTIES LABELS cpu TIMEOUT 120)
add_test(NAME "cli memory: --stream-patches 3 gives the held counts"
  COMMAND ${CMAKE_COMMAND} -DCMD=$<TARGET_FILE:tessera> -DINPUT=${PROJECT_SOURCE_DIR}/data/teacup.bpt
          "-DARGS=-m;B;--backend;cpu" "-DSTREAM_ARGS=--stream-patches;3"
          -DDIR=${CMAKE_CURRENT_BINARY_DIR}/streamed_by_option
          -P ${CMAKE_CURRENT_SOURCE_DIR}/expect_streamed_output.cmake)
set_tests_properties("cli memory: --stream-patches 3 gives the held counts"
  PROPERTIES LABELS cpu TIMEOUT 120)
tessera_limit_case("a streamed group that does not fit still exits 4" 4
  "streamed patches [0-9]+–[0-9]+ with their neighbours: .*more than the memory budget of 8.00 MiB"
  tessellate ${PROJECT_SOURCE_DIR}/data/teapot.bpt --tolerance 0.01% --backend cpu
  --memory-budget 8M)
# A .glb streams too (its JSON chunk is made at the end from the counts and bounds): by the
# budget with the held counts, and by --stream-patches.
add_test(NAME "cli memory: a glb over the budget is streamed"
  COMMAND ${CMAKE_COMMAND} -DCMD=$<TARGET_FILE:tessera> -DINPUT=${PROJECT_SOURCE_DIR}/data/teapot.bpt
          "-DARGS=--tolerance;0.01%;--backend;cpu" -DFORMAT=glb
          "-DSTREAM_ARGS=--memory-budget;16M" -DDIR=${CMAKE_CURRENT_BINARY_DIR}/streamed_glb_by_budget
          "-DEXPECT_TEXT=more than the memory budget of 16.0 MiB .*; streaming the mesh in patch groups instead"
          -P ${CMAKE_CURRENT_SOURCE_DIR}/expect_streamed_output.cmake)
add_test(NAME "cli memory: --stream-patches 3 to .glb gives the held counts"
  COMMAND ${CMAKE_COMMAND} -DCMD=$<TARGET_FILE:tessera> -DINPUT=${PROJECT_SOURCE_DIR}/data/teacup.bpt
          "-DARGS=-m;B;--backend;cpu" "-DSTREAM_ARGS=--stream-patches;3" -DFORMAT=glb
          -DDIR=${CMAKE_CURRENT_BINARY_DIR}/streamed_glb_by_option
          -P ${CMAKE_CURRENT_SOURCE_DIR}/expect_streamed_output.cmake)
set_tests_properties("cli memory: a glb over the budget is streamed"
  "cli memory: --stream-patches 3 to .glb gives the held counts" PROPERTIES LABELS cpu TIMEOUT 120)
