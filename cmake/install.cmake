# cmake --install: headers, libtessera.a, the CMake package (find_package(tessera), target
# tessera::tessera) and tessera.pc; the commands too when they are built (tessera, and
# tessera-cad with Open CASCADE). scripts/check-install.sh builds examples/consumer against an
# installed copy both ways.
include(CMakePackageConfigHelpers)

set(TESSERA_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/tessera)
install(TARGETS tessera_lib EXPORT tesseraTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
if(TARGET tessera_cad_lib)  # the component cad: libtessera_cad.a (cmake/library.cmake)
  install(TARGETS tessera_cad_lib EXPORT tesseraTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
endif()
# cad.h only with its library: a header whose symbols no installed archive defines would
# compile and then fail at link time.
if(TARGET tessera_cad_lib)
  set(TESSERA_HEADERS_LEFT_OUT "")
else()
  set(TESSERA_HEADERS_LEFT_OUT PATTERN "cad.h" EXCLUDE)
endif()
install(DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/include/tessera
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} FILES_MATCHING PATTERN "*.h" ${TESSERA_HEADERS_LEFT_OUT})
if(TESSERA_BUILD_CLI)
  install(TARGETS tessera RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  # In the same directory: tessera execs the tessera-cad beside it for a CAD model (cli/cad_job.h).
  if(TARGET tessera-cad)
    install(TARGETS tessera-cad RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  endif()
endif()

install(EXPORT tesseraTargets NAMESPACE tessera:: DESTINATION ${TESSERA_CMAKE_DIR})
configure_package_config_file(${CMAKE_CURRENT_SOURCE_DIR}/cmake/tesseraConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/tesseraConfig.cmake INSTALL_DESTINATION ${TESSERA_CMAKE_DIR})
# 0.x: a new minor version may change the API.
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/tesseraConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/tesseraConfig.cmake
  ${CMAKE_CURRENT_BINARY_DIR}/tesseraConfigVersion.cmake DESTINATION ${TESSERA_CMAKE_DIR})

# pkg-config: the same library and its link-time needs (-pthread, -ldl). C++17 or later.
set(TESSERA_PC_LINK_NEEDS "-pthread")
foreach(lib ${CMAKE_DL_LIBS})
  string(APPEND TESSERA_PC_LINK_NEEDS " -l${lib}")
endforeach()
file(RELATIVE_PATH TESSERA_PC_TO_PREFIX "/p/${CMAKE_INSTALL_LIBDIR}/pkgconfig" "/p")
string(REGEX REPLACE "/$" "" TESSERA_PC_TO_PREFIX "${TESSERA_PC_TO_PREFIX}")
configure_file(${CMAKE_CURRENT_SOURCE_DIR}/cmake/tessera.pc.in
  ${CMAKE_CURRENT_BINARY_DIR}/tessera.pc @ONLY)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/tessera.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
if(TARGET tessera_cad_lib)
  # tessera-cad.pc: libtessera_cad.a and OCCT's libraries by file, then tessera's.
  string(JOIN " " TESSERA_PC_OCCT_FILES ${TESSERA_CAD_OCCT_FILES})
  configure_file(${CMAKE_CURRENT_SOURCE_DIR}/cmake/tessera-cad.pc.in
    ${CMAKE_CURRENT_BINARY_DIR}/tessera-cad.pc @ONLY)
  install(FILES ${CMAKE_CURRENT_BINARY_DIR}/tessera-cad.pc
    DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
endif()
