# cmake --install: headers, the library and a CMake package so that downstream projects can
#   find_package(tripose REQUIRED)
#   target_link_libraries(app PRIVATE tripose::tripose)
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(TRIPOSE_CMAKE_DIR "${CMAKE_INSTALL_LIBDIR}/cmake/tripose")

install(TARGETS opencv_tripose EXPORT triposeTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY modules/tripose/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(EXPORT triposeTargets NAMESPACE tripose:: DESTINATION ${TRIPOSE_CMAKE_DIR})

configure_package_config_file(cmake/triposeConfig.cmake.in
  "${CMAKE_CURRENT_BINARY_DIR}/triposeConfig.cmake"
  INSTALL_DESTINATION ${TRIPOSE_CMAKE_DIR})
write_basic_package_version_file("${CMAKE_CURRENT_BINARY_DIR}/triposeConfigVersion.cmake"
  COMPATIBILITY SameMinorVersion)
install(FILES "${CMAKE_CURRENT_BINARY_DIR}/triposeConfig.cmake"
              "${CMAKE_CURRENT_BINARY_DIR}/triposeConfigVersion.cmake"
        DESTINATION ${TRIPOSE_CMAKE_DIR})
