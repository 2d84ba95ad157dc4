# cmake -P: examples/engine-consumer as its README builds it. Installs this
# build into a prefix, configures and builds the example against it (its
# warnings are errors), runs it on the default Vulkan device (lavapipe) and
# reads its PNG back with CHECKER (shadow_png_check.cpp); with EXPECT_GL,
# also engine_consumer_gl (the function form in an OpenGL engine's shaders)
# and engine_consumer_gl_lights (two lights' maps in one atlas, then in one
# array), whose pictures must match engine_consumer's.
# Inputs: BUILD_DIR SOURCE_DIR WORK_DIR GENERATOR CXX_COMPILER CONFIG SANITIZE
# CHECKER EXPECT_GL.
include(${CMAKE_CURRENT_LIST_DIR}/run.cmake)

set(prefix ${WORK_DIR}/prefix)
set(example ${WORK_DIR}/build)
file(REMOVE_RECURSE ${WORK_DIR})

set(config_args "")
if(CONFIG)
  set(config_args --config ${CONFIG})
endif()
run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix} ${config_args})

set(configure_args -G ${GENERATOR} -DCMAKE_CXX_COMPILER=${CXX_COMPILER}
                   -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_BUILD_TYPE=Release
                   -DCMAKE_COMPILE_WARNING_AS_ERROR=ON)
if(SANITIZE)  # the installed libraries were built with ASan and UBSan
  list(APPEND configure_args "-DCMAKE_EXE_LINKER_FLAGS=-fsanitize=address,undefined")
endif()
# An engine that only draws needs no compiler library and no oneTBB: finding
# glslang, SPIRV-Tools or oneTBB fails the configure.
run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/examples/engine-consumer -B ${example} ${configure_args}
    -DCMAKE_DISABLE_FIND_PACKAGE_glslang=ON -DCMAKE_DISABLE_FIND_PACKAGE_SPIRV-Tools-opt=ON
    -DCMAKE_DISABLE_FIND_PACKAGE_TBB=ON)
run(${CMAKE_COMMAND} --build ${example})

run(${example}/engine_consumer ${WORK_DIR}/shadow.png)
message(STATUS "${run_output}")
if(NOT run_output MATCHES "pcss_b16_p16_whitepaper16 on .*: wrote .*shadow.png \\(512x512")
  message(FATAL_ERROR "install test: the example printed '${run_output}'")
endif()
run(${CHECKER} ${WORK_DIR}/shadow.png)
message(STATUS "${run_output}")
if(EXPECT_GL)
  run(${example}/engine_consumer_gl ${WORK_DIR}/shadow_gl.png)
  message(STATUS "${run_output}")
  if(NOT run_output MATCHES "pcss_b16_p16_whitepaper16_perspective on .*: wrote .*shadow_gl.png")
    message(FATAL_ERROR "install test: the OpenGL example printed '${run_output}'")
  endif()
  run(${CHECKER} ${WORK_DIR}/shadow_gl.png ${WORK_DIR}/shadow.png)
  message(STATUS "${run_output}")
  # Two lights' maps as an atlas's tiles or an array's layers, shaded in one
  # loop: light 0's picture is engine_consumer's.
  foreach(layout atlas array)
    run(${example}/engine_consumer_gl_lights ${layout} ${WORK_DIR}/shadow_gl_${layout}.png)
    message(STATUS "${run_output}")
    if(NOT run_output MATCHES
       "pcss_b16_p16_whitepaper16_perspective_${layout} on .*: wrote .*shadow_gl_${layout}.png")
      message(FATAL_ERROR "install test: the OpenGL ${layout} example printed '${run_output}'")
    endif()
    run(${CHECKER} ${WORK_DIR}/shadow_gl_${layout}.png ${WORK_DIR}/shadow.png)
    message(STATUS "${run_output}")
  endforeach()
endif()
message(STATUS "install test: the engine-consumer example passed")
