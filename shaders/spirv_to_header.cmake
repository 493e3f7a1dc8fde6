# cmake -DSPV=<module.spv> -DHEADER=<out.h> -DNAME=<array name> -P spirv_to_header.cmake
# Writes the SPIR-V module as `const uint32_t NAME[] = {…};` (SPIR-V words are little-endian
# in the file, as on every host we build for), what glslangValidator --vn writes for GLSL.
file(READ "${SPV}" hex HEX)
string(LENGTH "${hex}" digits)
math(EXPR remainder "${digits} % 8")
if(digits EQUAL 0 OR NOT remainder EQUAL 0)
  message(FATAL_ERROR "${SPV}: not a whole number of 32-bit words")
endif()
# Each word's 4 bytes in file order b0 b1 b2 b3 → 0xb3b2b1b0.
string(REGEX REPLACE "(..)(..)(..)(..)" "0x\\4\\3\\2\\1," words "${hex}")
file(WRITE "${HEADER}.tmp"
     "// Generated from ${SPV} by shaders/spirv_to_header.cmake.\n#pragma once\n"
     "const uint32_t ${NAME}[] = {${words}};\n")
file(RENAME "${HEADER}.tmp" "${HEADER}")
