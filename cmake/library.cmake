# The public API and the one library a consumer links, tessera::tessera (docs/api.md).
#
# One combined static library, libtessera.a: the objects of tessera_core, tessera_vulkan (with
# volk, which Debian ships as source and third_party/ compiles), tessera_io and the API
# (host/api/). One archive because a consumer should link one thing,
# and because the internal layers' usage requirements (glm and Vulkan defines, the host/
# include path, -ffp-contract=off) must stay inside Tessera's build: the combined target is
# built from objects only, so its interface is just include/, C++17, Threads and dl.
# Everything in it is position independent, so it can go into a shared library or a Python
# module.
include(GNUInstallDirs)
set(THREADS_PREFER_PTHREAD_FLAG ON)
find_package(Threads REQUIRED)  # imported targets are per directory: third_party's is not seen here

set_target_properties(tessera_core tessera_vulkan tessera_volk tessera_io PROPERTIES
  POSITION_INDEPENDENT_CODE ON)

# The API's own code, compiled against the internal layers. The tests link these objects
# beside the layers' static libraries (the combined archive would duplicate them).
file(GLOB TESSERA_API_SOURCES CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/host/api/*.cpp)
add_library(tessera_api OBJECT ${TESSERA_API_SOURCES})
target_link_libraries(tessera_api PUBLIC tessera_vulkan tessera_io tessera_core)
set_target_properties(tessera_api PROPERTIES POSITION_INDEPENDENT_CODE ON)

add_library(tessera_lib STATIC
  $<TARGET_OBJECTS:tessera_api> $<TARGET_OBJECTS:tessera_core>
  $<TARGET_OBJECTS:tessera_vulkan> $<TARGET_OBJECTS:tessera_volk> $<TARGET_OBJECTS:tessera_io>)
set_target_properties(tessera_lib PROPERTIES OUTPUT_NAME tessera EXPORT_NAME tessera
  LINKER_LANGUAGE CXX)
target_include_directories(tessera_lib INTERFACE
  $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
  $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
target_compile_features(tessera_lib INTERFACE cxx_std_17)
# What the objects need at link time: threads (the parallel CPU backend) and dlopen (volk
# opens the Vulkan loader at run time, nothing links libvulkan). volk itself is inside, so
# the package config needs no find_dependency for it.
target_link_libraries(tessera_lib INTERFACE Threads::Threads ${CMAKE_DL_LIBS})
add_library(tessera::tessera ALIAS tessera_lib)

# The CAD API (include/tessera/cad.h), tessera::cad: libtessera_cad.a, the CAD reader
# (host/cad/) and its entry point (host/api/cad/), apart from libtessera.a so that only its
# users link Open CASCADE. Its interface: tessera::tessera and OCCT's libraries by file, as
# third_party/ found them (no OCCT header is public).
if(TESSERA_HAVE_CAD)
  # The layer's own archive keeps another name: libtessera_cad.a is the installed one.
  set_target_properties(tessera_cad PROPERTIES POSITION_INDEPENDENT_CODE ON
    OUTPUT_NAME tessera_cad_layer)
  file(GLOB TESSERA_CAD_API_SOURCES CONFIGURE_DEPENDS
    ${CMAKE_CURRENT_SOURCE_DIR}/host/api/cad/*.cpp)
  add_library(tessera_cad_api OBJECT ${TESSERA_CAD_API_SOURCES})
  target_link_libraries(tessera_cad_api PUBLIC tessera_cad tessera_vulkan tessera_io tessera_core)
  set_target_properties(tessera_cad_api PROPERTIES POSITION_INDEPENDENT_CODE ON)

  add_library(tessera_cad_lib STATIC
    $<TARGET_OBJECTS:tessera_cad_api> $<TARGET_OBJECTS:tessera_cad>)
  set_target_properties(tessera_cad_lib PROPERTIES OUTPUT_NAME tessera_cad EXPORT_NAME cad
    LINKER_LANGUAGE CXX)
  get_target_property(TESSERA_CAD_OCCT_FILES tessera_occt_exchange INTERFACE_LINK_LIBRARIES)
  target_link_libraries(tessera_cad_lib INTERFACE tessera_lib ${TESSERA_CAD_OCCT_FILES})
  add_library(tessera::cad ALIAS tessera_cad_lib)
endif()
