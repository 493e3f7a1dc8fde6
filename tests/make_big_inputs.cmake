# Writes the memory-budget tests' inputs into DIR (cmake -P; run once per build by ctest's
# fixture): valid inputs whose headers or counts ask for far more memory than a small
# --memory-budget, scaled down from issue 18's cases so that each test stops in well under a
# second. Nothing big is kept in git: the largest file written here is ~1 MB.
#   grid_4096.grid     a 4096×4096 grid's header and first point (refused at the header)
#   bspline_200.json   one degree-7 B-spline of 200×200 control points (37,249 pieces)
#   patches_30k.bpt    30,000 bilinear patches
#   teapots_100.bpt    100 teapots
#   bspline_200.step   722 bytes of text named .step (for the input-size limit)
#   x.bpt x.grid x.obj x.json x.step   symbolic links to /dev/zero
file(MAKE_DIRECTORY ${DIR})
file(WRITE ${DIR}/grid_4096.grid "4096 4096\n0 0 0\n")

set(n 200)
set(degree 7)
math(EXPR knotCount "${n} + ${degree} + 1")
math(EXPR interior "${n} - ${degree} - 1")
set(knots "0,0,0,0,0,0,0,0")
foreach(k RANGE 1 ${interior})
  string(APPEND knots ",${k}")
endforeach()
math(EXPR last "${interior} + 1")
string(REPEAT ",${last}" 8 tail)
string(APPEND knots "${tail}")
math(EXPR points "${n} * ${n} - 1")
string(REPEAT "[0,0,0]," ${points} net)
file(WRITE ${DIR}/bspline_200.json
  "{\"tessera_scene\": 1, \"surfaces\": [{\"type\": \"bspline\", \"degree\": [7, 7], "
  "\"count\": [${n}, ${n}], \"knots_u\": [${knots}], \"knots_v\": [${knots}], "
  "\"points\": [${net}[0,0,0]]}]}\n")

string(REPEAT "1 1\n0 0 0\n0 1 0\n1 0 0\n1 1 0\n" 30000 bilinear)
file(WRITE ${DIR}/patches_30k.bpt "30000\n${bilinear}")

# Not a STEP model: only its size matters (refused before Open CASCADE opens it).
file(WRITE ${DIR}/bspline_200.step "ISO-10303-21;\n${knots}\n")

file(READ ${TEAPOT} teapot)
string(REGEX REPLACE "^[ \t]*[0-9]+[ \t\r]*\n" "" teapotPatches "${teapot}")
string(REGEX MATCH "^[ \t]*[0-9]+" teapotCount "${teapot}")
string(STRIP "${teapotCount}" teapotCount)
math(EXPR total "${teapotCount} * 100")
string(REPEAT "${teapotPatches}" 100 teapots)
file(WRITE ${DIR}/teapots_100.bpt "${total}\n${teapots}")

foreach(ext bpt grid obj json step)
  file(REMOVE ${DIR}/x.${ext})
  file(CREATE_LINK /dev/zero ${DIR}/x.${ext} SYMBOLIC)
endforeach()
