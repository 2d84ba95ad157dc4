# `cmake --install build --prefix P`: bin/penumbra, the headers, the static
# libraries, share/penumbra/shaderlib and a relocatable CMake package,
# find_package(Penumbra CONFIG [COMPONENTS shaders compiler runtime verify])
# from P/lib/cmake/Penumbra:
#   shaders   Penumbra::shaders (the lookup over embedded shaders, with
#             Penumbra::model and Penumbra::support), Penumbra::library
#             (load_library(): a built library's index.json),
#             Penumbra::device (the runtime's device interface and pass
#             driver, penumbra/runtime/), the executable
#             Penumbra::penumbra and penumbra_add_shader_library(); always
#             loaded; needs nlohmann_json only.
#   compiler  Penumbra::compiler and Penumbra::spirv; loaded when no
#             component is named, or compiler or verify is; needs glslang,
#             SPIRV-Tools and SPIRV-Cross.
#   runtime   Penumbra::runtime: Penumbra::vulkan, Penumbra::d3d (and its
#             host, libexec/penumbra/penumbra_d3d_host.exe, where built) and
#             Penumbra::gl where built, with Penumbra::spirv; needs Vulkan,
#             SPIRV-Cross's core (and OpenGL/EGL with gl), no compiler.
#   verify    Penumbra::verify and Penumbra::reference, the conformance
#             harness over the runtime and the compiler (both loaded with
#             it); needs oneTBB too.
# runtime and verify are built with PENUMBRA_BUILD_RUNTIME and looked up only
# when requested.
include(CMakePackageConfigHelpers)

set(PENUMBRA_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/Penumbra)
set(PENUMBRA_INSTALL_SHADERLIBDIR ${CMAKE_INSTALL_DATADIR}/penumbra/shaderlib)

set_target_properties(penumbra_cli PROPERTIES EXPORT_NAME penumbra)
install(TARGETS penumbra_support penumbra_model penumbra_library penumbra_device penumbra_shaders
        EXPORT PenumbraTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(TARGETS penumbra_cli EXPORT PenumbraTargets RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY support/include/ model/include/ library/include/ runtime/device/include/
                  shaders/include/
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(EXPORT PenumbraTargets NAMESPACE Penumbra:: DESTINATION ${PENUMBRA_INSTALL_CMAKEDIR})
install(FILES cmake/PenumbraShaderLibrary.cmake DESTINATION ${PENUMBRA_INSTALL_CMAKEDIR})

install(TARGETS penumbra_spirv EXPORT PenumbraSpirvTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(DIRECTORY spirv/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(EXPORT PenumbraSpirvTargets NAMESPACE Penumbra:: DESTINATION ${PENUMBRA_INSTALL_CMAKEDIR})

install(TARGETS penumbra_shaderlib_sources penumbra_compiler EXPORT PenumbraCompilerTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(DIRECTORY compiler/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(EXPORT PenumbraCompilerTargets NAMESPACE Penumbra::
        DESTINATION ${PENUMBRA_INSTALL_CMAKEDIR})

# The shipped manifests, where the benchmarks look first (bench/bench_files.hpp):
# share/penumbra/permutations, installed and in the build tree.
set(PENUMBRA_MANIFESTS permutations/default.json permutations/largest.json)
foreach(_manifest IN LISTS PENUMBRA_MANIFESTS)
  configure_file(${_manifest} ${PROJECT_BINARY_DIR}/share/penumbra/${_manifest} COPYONLY)
endforeach()
install(FILES ${PENUMBRA_MANIFESTS} DESTINATION ${CMAKE_INSTALL_DATADIR}/penumbra/permutations)

# The shader library's sources as `penumbra build` embeds them, for engines
# that read or ship them (Penumbra_SHADERLIB_DIR).
foreach(_file IN LISTS PENUMBRA_SHADERLIB_FILES)
  get_filename_component(_dir ${_file} DIRECTORY)
  install(FILES shaderlib/${_file} DESTINATION ${PENUMBRA_INSTALL_SHADERLIBDIR}/${_dir})
endforeach()

if(PENUMBRA_BUILD_RUNTIME)
  add_library(penumbra_runtime INTERFACE)
  add_library(penumbra::runtime ALIAS penumbra_runtime)
  set_target_properties(penumbra_runtime PROPERTIES EXPORT_NAME runtime)
  target_link_libraries(penumbra_runtime INTERFACE penumbra_device penumbra_vulkan penumbra_d3d)
  set(_runtime_targets penumbra_runtime penumbra_vulkan penumbra_d3d)
  set(_runtime_headers runtime/vulkan/include/ runtime/d3d/include/)
  if(PENUMBRA_BUILD_GL)
    target_link_libraries(penumbra_runtime INTERFACE penumbra_gl)
    list(APPEND _runtime_targets penumbra_gl)
    list(APPEND _runtime_headers runtime/gl/include/)
  endif()
  install(TARGETS ${_runtime_targets} EXPORT PenumbraRuntimeTargets
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
  install(DIRECTORY ${_runtime_headers} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  install(EXPORT PenumbraRuntimeTargets NAMESPACE Penumbra::
          DESTINATION ${PENUMBRA_INSTALL_CMAKEDIR})

  install(TARGETS penumbra_verify penumbra_reference EXPORT PenumbraVerifyTargets
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
  install(DIRECTORY verify/include/ reference/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  install(EXPORT PenumbraVerifyTargets NAMESPACE Penumbra::
          DESTINATION ${PENUMBRA_INSTALL_CMAKEDIR})
endif()

configure_package_config_file(cmake/PenumbraConfig.cmake.in
  ${PROJECT_BINARY_DIR}/PenumbraConfig.cmake
  INSTALL_DESTINATION ${PENUMBRA_INSTALL_CMAKEDIR}
  PATH_VARS PENUMBRA_INSTALL_SHADERLIBDIR)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/PenumbraConfigVersion.cmake
  COMPATIBILITY SameMajorVersion)
install(FILES ${PROJECT_BINARY_DIR}/PenumbraConfig.cmake
              ${PROJECT_BINARY_DIR}/PenumbraConfigVersion.cmake
        DESTINATION ${PENUMBRA_INSTALL_CMAKEDIR})
