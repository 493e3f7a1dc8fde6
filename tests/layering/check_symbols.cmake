# The names libtessera.a gives a program that links it (docs/api.md, "Building against it"): every
# strong global symbol it defines must be Tessera's (namespace tessera, or a tessera_ prefix as
# volk's renamed globals have). A Vulkan command's name (volk's globals before they were renamed)
# made an engine's own Vulkan calls crash; any other plain name could clash with the program's.
#   cmake -DNM=<nm> -DARCHIVE=<libtessera.a> [-DMIN_SYMBOLS=100] -P check_symbols.cmake
# (MIN_SYMBOLS: fewer strong symbols than that means nm's listing was not understood).
execute_process(COMMAND ${NM} --defined-only --extern-only --demangle ${ARCHIVE}
  OUTPUT_VARIABLE listing RESULT_VARIABLE status ERROR_QUIET)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${NM} could not list ${ARCHIVE}")
endif()
string(REPLACE "\n" ";" lines "${listing}")
set(strong 0)
set(foreign "")
foreach(line IN LISTS lines)
  # "<address> <kind> <name>": T text, D data, B bss, R read-only data, G/S small data.
  if(line MATCHES "^[0-9a-f]+ [TDBRGS] (.+)$")
    math(EXPR strong "${strong} + 1")
    set(name "${CMAKE_MATCH_1}")
    # A class's typeinfo, vtable and thunks are named by it (strong in clang's builds).
    if(NOT name MATCHES "^((typeinfo( name)?|vtable|VTT|construction vtable|guard variable) for |(non-)?virtual thunk to )?(tessera::|tessera_)")
      string(APPEND foreign "\n  ${name}")
    endif()
  endif()
endforeach()
if(NOT DEFINED MIN_SYMBOLS)
  set(MIN_SYMBOLS 100)
endif()
if(strong LESS MIN_SYMBOLS)
  message(FATAL_ERROR "${ARCHIVE}: only ${strong} strong global symbols listed; nm's format?")
endif()
if(foreign)
  message(FATAL_ERROR "${ARCHIVE} defines global names outside tessera:: and tessera_*:${foreign}")
endif()
message(STATUS "${ARCHIVE}: ${strong} strong global symbols, all Tessera's")
