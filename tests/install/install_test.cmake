# cmake -P: Penumbra used as an engine's build would use it. Installs this
# build into a prefix, moves the prefix (the package must be relocatable),
# then configures, builds and runs consumer/ against the moved package with
# Vulkan and OpenGL disabled (the compiler component must not need them), and
# probes the runtime component with runtime_probe/.
# Inputs: BUILD_DIR SOURCE_DIR TEST_DIR WORK_DIR GENERATOR CXX_COMPILER CONFIG
# EXPECT_RUNTIME SANITIZE.

include(${CMAKE_CURRENT_LIST_DIR}/run.cmake)

set(staged ${WORK_DIR}/staged)
set(prefix ${WORK_DIR}/moved)
file(REMOVE_RECURSE ${WORK_DIR})

set(config_args "")
if(CONFIG)
  set(config_args --config ${CONFIG})
endif()
run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${staged} ${config_args})
file(RENAME ${staged} ${prefix})

# Relocatable: no path of this build in the package's CMake files.
file(GLOB_RECURSE package_files ${prefix}/*.cmake)
list(FILTER package_files INCLUDE REGEX "/cmake/Penumbra/[^/]*$")
if(NOT package_files MATCHES "PenumbraConfig.cmake")
  message(FATAL_ERROR "install test: no lib/cmake/Penumbra/PenumbraConfig.cmake in ${prefix}")
endif()
foreach(file IN LISTS package_files)
  file(READ ${file} text)
  foreach(path IN ITEMS ${SOURCE_DIR} ${BUILD_DIR} ${WORK_DIR})
    string(FIND "${text}" "${path}" at)
    if(NOT at EQUAL -1)
      message(FATAL_ERROR "install test: ${file} names ${path}: the package is not relocatable")
    endif()
  endforeach()
endforeach()

set(common_args -G ${GENERATOR} -DCMAKE_CXX_COMPILER=${CXX_COMPILER}
                -DCMAKE_PREFIX_PATH=${prefix})
if(SANITIZE)  # the installed libraries were built with ASan and UBSan
  list(APPEND common_args "-DCMAKE_EXE_LINKER_FLAGS=-fsanitize=address,undefined")
endif()

set(consumer ${WORK_DIR}/consumer)
run(${CMAKE_COMMAND} -S ${TEST_DIR}/consumer -B ${consumer} ${common_args}
    -DCMAKE_BUILD_TYPE=Release -DCMAKE_DISABLE_FIND_PACKAGE_Vulkan=ON
    -DCMAKE_DISABLE_FIND_PACKAGE_OpenGL=ON)
run(${CMAKE_COMMAND} --build ${consumer})

run(${consumer}/consumer ${WORK_DIR}/library)
message(STATUS "${run_output}")
file(STRINGS ${consumer}/variants.txt variants)
if(NOT variants MATCHES "(^|;)hard(;|$)" OR NOT variants MATCHES "(^|;)pcf_grid")
  message(FATAL_ERROR "install test: `penumbra list` in the consumer's build wrote '${variants}'")
endif()

# The shaders component alone: penumbra_add_shader_library() generates at
# build time with the installed executable, without glslang, Vulkan or GL
# (finding any of them disabled fails the configure); a second build of the
# untouched project runs nothing.
set(embedded ${WORK_DIR}/embedded_consumer)
run(${CMAKE_COMMAND} -S ${TEST_DIR}/embedded_consumer -B ${embedded} ${common_args}
    -DCMAKE_BUILD_TYPE=Release -DCMAKE_DISABLE_FIND_PACKAGE_glslang=ON
    -DCMAKE_DISABLE_FIND_PACKAGE_Vulkan=ON -DCMAKE_DISABLE_FIND_PACKAGE_OpenGL=ON)
run(${CMAKE_COMMAND} --build ${embedded})
run(${embedded}/embedded)
message(STATUS "${run_output}")
run(${CMAKE_COMMAND} --build ${embedded} --verbose)
if(GENERATOR STREQUAL "Ninja" AND NOT run_output MATCHES "no work to do")
  message(FATAL_ERROR "install test: rebuilding the untouched embedded consumer ran:\n${run_output}")
endif()

# Its shaders come from the installed shaderlib folder, and the build step's
# depfile lists the files its variant (pcss) includes: touching one of them
# regenerates the library, touching a technique it does not use runs nothing.
set(installed_shaderlib ${prefix}/share/penumbra/shaderlib)
if(GENERATOR STREQUAL "Ninja")
  file(TOUCH ${installed_shaderlib}/techniques/hard.glsl)
  run(${CMAKE_COMMAND} --build ${embedded} --verbose)
  if(NOT run_output MATCHES "no work to do")
    message(FATAL_ERROR "install test: touching techniques/hard.glsl, which the embedded "
                        "consumer does not use, ran:\n${run_output}")
  endif()
  file(TOUCH ${installed_shaderlib}/techniques/pcss.glsl)
  run(${CMAKE_COMMAND} --build ${embedded} --verbose)
  if(NOT run_output MATCHES "--shaderlib")
    message(FATAL_ERROR "install test: touching techniques/pcss.glsl, which the embedded "
                        "consumer's variant includes, did not regenerate its shaders:\n"
                        "${run_output}")
  endif()
  run(${embedded}/embedded)
endif()

# The runtime component: missing without Vulkan, found with it when built.
run(${CMAKE_COMMAND} -S ${TEST_DIR}/runtime_probe -B ${WORK_DIR}/probe_without_vulkan
    ${common_args} -DCMAKE_DISABLE_FIND_PACKAGE_Vulkan=ON -DEXPECT_RUNTIME=OFF)
run(${CMAKE_COMMAND} -S ${TEST_DIR}/runtime_probe -B ${WORK_DIR}/probe ${common_args}
    -DEXPECT_RUNTIME=${EXPECT_RUNTIME})
message(STATUS "install test: passed")
