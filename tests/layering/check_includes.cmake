# The layering rules of docs/architecture.md, checked on the sources (cmake -P, SOURCE_DIR set):
# 1. core code (host/<stage>/ files without the _vulkan suffix; a _vulkan.h header is the
#    backend's, like a _vulkan.cpp) includes no Vulkan: not host/vk/,
#    not <vulkan/...>, not <volk.h>, not the generated SPIR-V headers (*_comp.h);
# 2. no file sits directly in host/ except README.md;
# 3. a core stage never includes the CLI, the experiments or the render layer.
set(stages common geometry eval bspline quadtree mesh division reduction loop realtime)
set(violations "")
foreach(stage ${stages})
  file(GLOB_RECURSE sources "${SOURCE_DIR}/host/${stage}/*.h" "${SOURCE_DIR}/host/${stage}/*.cpp")
  foreach(src ${sources})
    if(src MATCHES "_vulkan\\.(cpp|h)$")
      continue()
    endif()
    file(STRINGS "${src}" includes REGEX "^[ \t]*#[ \t]*include")
    foreach(line ${includes})
      if(line MATCHES "\"vk/|<vulkan/|<volk\\.h>|_comp\\.h\"|\"cli/|\"experiments/|\"render/")
        file(RELATIVE_PATH rel "${SOURCE_DIR}" "${src}")
        string(APPEND violations "  ${rel}: ${line}\n")
      endif()
    endforeach()
  endforeach()
endforeach()
file(GLOB loose LIST_DIRECTORIES false "${SOURCE_DIR}/host/*")
foreach(f ${loose})
  get_filename_component(name "${f}" NAME)
  if(NOT name STREQUAL "README.md")
    string(APPEND violations "  host/${name}: a file outside a stage folder\n")
  endif()
endforeach()
if(violations)
  message(FATAL_ERROR "layering violations (docs/architecture.md):\n${violations}")
endif()
message(STATUS "layering: core stages include no Vulkan, CLI, experiments or render code; host/ holds only folders")
