# Install the CLI and export the libraries for consumers (find_package(penumbra)).
include(CMakePackageConfigHelpers)
set(_targets penumbra_support penumbra_model penumbra_shaderlib_sources penumbra_compiler penumbra_reference)
if(PENUMBRA_BUILD_GL)
  list(APPEND _targets penumbra_gl)
endif()
if(PENUMBRA_BUILD_RUNTIME)
  list(APPEND _targets penumbra_vulkan penumbra_verify)
endif()
install(TARGETS ${_targets} EXPORT penumbraTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(TARGETS penumbra_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY support/include/ model/include/ compiler/include/ reference/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
if(PENUMBRA_BUILD_RUNTIME)
  install(DIRECTORY engines/vulkan/include/ verify/include/
          DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endif()
if(PENUMBRA_BUILD_GL)
  install(DIRECTORY engines/gl/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endif()
install(EXPORT penumbraTargets NAMESPACE penumbra::
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/penumbra)
configure_package_config_file(cmake/penumbraConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/penumbraConfig.cmake
  INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/penumbra)
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/penumbraConfigVersion.cmake
  COMPATIBILITY SameMajorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/penumbraConfig.cmake
              ${CMAKE_CURRENT_BINARY_DIR}/penumbraConfigVersion.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/penumbra)
