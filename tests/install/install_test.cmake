# cmake -P: Penumbra used as an engine's build would use it. Installs this
# build into a prefix, moves the prefix (the package must be relocatable),
# then configures, builds and runs consumer/ against the moved package with
# Vulkan and OpenGL disabled (the compiler component must not need them), and
# probes the runtime and verify components with runtime_probe/.
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
# untouched project runs nothing. It is built from a copy, whose manifest
# the test edits.
set(embedded ${WORK_DIR}/embedded_consumer)
set(embedded_src ${WORK_DIR}/embedded_src)
file(COPY ${TEST_DIR}/embedded_consumer/ DESTINATION ${embedded_src})
run(${CMAKE_COMMAND} -S ${embedded_src} -B ${embedded} ${common_args}
    -DCMAKE_BUILD_TYPE=Release -DCMAKE_DISABLE_FIND_PACKAGE_glslang=ON
    -DCMAKE_DISABLE_FIND_PACKAGE_Vulkan=ON -DCMAKE_DISABLE_FIND_PACKAGE_OpenGL=ON)
run(${CMAKE_COMMAND} --build ${embedded})
run(${embedded}/embedded)
message(STATUS "${run_output}")
# index.json read back by a program linking Penumbra::library, built without glslang.
run(${prefix}/bin/penumbra build ${embedded_src}/manifest.json -o ${WORK_DIR}/embedded_library)
run(${embedded}/index_reader ${WORK_DIR}/embedded_library)
if(NOT run_output MATCHES "index_reader: pcss[^:]*: [a-z]")
  message(FATAL_ERROR "install test: index_reader listed no pcss variant:\n${run_output}")
endif()
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
  # Touched, not changed: the group step found its stamp current, so nothing
  # after it ran.
  if(run_output MATCHES "penumbra merge")
    message(FATAL_ERROR "install test: touching techniques/pcss.glsl without changing it "
                        "merged the library again:\n${run_output}")
  endif()
  # Edited without changing a shader (dead code the optimizer removes): the
  # step recompiles, its part comes out the same, and nothing after it runs.
  # A second apart from the step that just ran: on a loaded machine the edit
  # once landed inside that step's recorded time and Ninja saw nothing new.
  execute_process(COMMAND ${CMAKE_COMMAND} -E sleep 1.1)
  file(APPEND ${installed_shaderlib}/techniques/pcss.glsl
       "\nfloat penumbra_install_test_unused(float x) { return x + 1.0; }\n")
  run(${CMAKE_COMMAND} --build ${embedded} --verbose)
  if(NOT run_output MATCHES "--shaderlib" OR run_output MATCHES "penumbra merge")
    message(FATAL_ERROR "install test: a dead-code edit of techniques/pcss.glsl should rerun "
                        "its group step and nothing after it:\n${run_output}")
  endif()
  # Changed: the library, the part's object and the program are rebuilt,
  # and no other part's object.
  file(READ ${installed_shaderlib}/techniques/pcss.glsl pcss)
  string(REPLACE "return 1.0;  // no occluder" "return 0.999;  // no occluder" pcss "${pcss}")
  execute_process(COMMAND ${CMAKE_COMMAND} -E sleep 1.1)
  file(WRITE ${installed_shaderlib}/techniques/pcss.glsl "${pcss}")
  run(${CMAKE_COMMAND} --build ${embedded} --verbose)
  string(REGEX MATCHALL "-c [^ \n]*engine_shadows_shaders_[0-9]+\\.cpp" recompiled "${run_output}")
  list(REMOVE_DUPLICATES recompiled)
  list(LENGTH recompiled recompiled)
  if(NOT run_output MATCHES "penumbra merge" OR NOT recompiled EQUAL 1)
    message(FATAL_ERROR "install test: editing techniques/pcss.glsl should rebuild the library "
                        "and recompile exactly one part of the embedded consumer's shaders "
                        "(${recompiled} were):\n${run_output}")
  endif()
  run(${embedded}/embedded)

  # Editing one manifest set (a second variant) reruns every group step, but
  # only the new variant's group writes its part: the others stay untouched.
  file(GLOB parts ${embedded}/engine_shadows/parts/*/index.json)
  set(before "")
  foreach(part IN LISTS parts)
    file(TIMESTAMP ${part} stamp "%s")
    list(APPEND before "${part}=${stamp}")
  endforeach()
  execute_process(COMMAND ${CMAKE_COMMAND} -E sleep 1.1)  # timestamps are in seconds
  file(READ ${embedded_src}/manifest.json manifest)
  string(REPLACE "\"sets\": [" "\"sets\": [\n    { \"technique\": \"pcf_grid\", \"kernel\": 5 },"
                 manifest "${manifest}")
  file(WRITE ${embedded_src}/manifest.json "${manifest}")
  run(${CMAKE_COMMAND} --build ${embedded} --verbose)
  string(REGEX MATCHALL "-c [^ \n]*engine_shadows_shaders_[0-9]+\\.cpp" recompiled "${run_output}")
  list(REMOVE_DUPLICATES recompiled)
  list(LENGTH recompiled recompiled)
  if(NOT recompiled EQUAL 1)
    message(FATAL_ERROR "install test: adding one variant recompiled ${recompiled} parts of the "
                        "embedded consumer's shaders; expected only its own group's")
  endif()
  set(rewritten 0)
  foreach(entry IN LISTS before)
    string(REGEX MATCH "^(.*)=([0-9]+)$" _ "${entry}")
    file(TIMESTAMP ${CMAKE_MATCH_1} stamp "%s")
    if(NOT stamp STREQUAL CMAKE_MATCH_2)
      math(EXPR rewritten "${rewritten} + 1")
    endif()
  endforeach()
  if(NOT rewritten EQUAL 1)
    message(FATAL_ERROR "install test: adding one variant rewrote ${rewritten} of the "
                        "embedded consumer's group parts; expected only its own group's")
  endif()
  run(${embedded}/embedded)
  # Two variants, two targets, the depth and query passes of FORMS query
  # function (no deferred pass).
  if(NOT run_output MATCHES "embedded: .*, 8 programs")
    message(FATAL_ERROR "install test: after adding pcf_grid_k5 the embedded consumer printed "
                        "'${run_output}'; expected 8 programs")
  endif()
endif()

# The runtime and verify components: both missing without Vulkan; with it,
# found when built. The runtime needs no compiler library and no oneTBB
# (finding glslang, SPIRV-Tools or oneTBB disabled), which verify needs.
run(${CMAKE_COMMAND} -S ${TEST_DIR}/runtime_probe -B ${WORK_DIR}/probe_without_vulkan
    ${common_args} -DCMAKE_DISABLE_FIND_PACKAGE_Vulkan=ON -DEXPECT_RUNTIME=OFF
    -DEXPECT_VERIFY=OFF)
run(${CMAKE_COMMAND} -S ${TEST_DIR}/runtime_probe -B ${WORK_DIR}/probe_without_compiler
    ${common_args} -DCMAKE_DISABLE_FIND_PACKAGE_glslang=ON
    -DCMAKE_DISABLE_FIND_PACKAGE_SPIRV-Tools-opt=ON -DCMAKE_DISABLE_FIND_PACKAGE_TBB=ON
    -DEXPECT_RUNTIME=${EXPECT_RUNTIME} -DEXPECT_VERIFY=OFF)
run(${CMAKE_COMMAND} -S ${TEST_DIR}/runtime_probe -B ${WORK_DIR}/probe ${common_args}
    -DEXPECT_RUNTIME=${EXPECT_RUNTIME} -DEXPECT_VERIFY=${EXPECT_RUNTIME})
message(STATUS "install test: passed")
