# penumbra_add_shader_library(<name> MANIFEST <file> [TARGETS <target>...]
#                             [OUTPUT_DIR <dir>] [HLSL_COMPILER <path>]
#                             [SHADERLIB_DIR <dir>])
#
# A static library <name> whose header <name>/shaders.hpp holds every variant
# of MANIFEST for TARGETS (default: the manifest's own), with the reflection
# and a lookup by technique and keys (docs/embedding.md). Generated at build
# time, never at configure time: `penumbra build` into OUTPUT_DIR/library
# (default: <current binary dir>/<name>), then `penumbra embed`. The Direct3D
# bytecode needs vkd3d-compiler: HLSL_COMPILER, or what `penumbra build` finds
# (PENUMBRA_HLSL_COMPILER, fetch-vkd3d's cache).
#
# The shaders are compiled from SHADERLIB_DIR's files (`penumbra build
# --shaderlib`), by default the installed package's Penumbra_SHADERLIB_DIR
# when it exists. `penumbra build --depfile` lists the files of it that the
# variants include, so editing one of them regenerates the library and
# editing any other does not. Without a folder (in Penumbra's own tree, where
# Penumbra_SHADERLIB_DIR is unset) the copy built into `penumbra` is used:
# the command already depends on that executable, which is rebuilt when
# shaderlib/ changes.
function(penumbra_add_shader_library name)
  cmake_parse_arguments(PARSE_ARGV 1 ARG "" "MANIFEST;OUTPUT_DIR;HLSL_COMPILER;SHADERLIB_DIR"
                        "TARGETS")
  if(ARG_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "penumbra_add_shader_library(${name}): unknown arguments "
                        "'${ARG_UNPARSED_ARGUMENTS}' (allowed: MANIFEST, TARGETS, OUTPUT_DIR, "
                        "HLSL_COMPILER, SHADERLIB_DIR)")
  endif()
  if(NOT name MATCHES "^[A-Za-z_][A-Za-z0-9_]*$")
    message(FATAL_ERROR "penumbra_add_shader_library(${name}): the name becomes a C++ "
                        "namespace and must be an identifier (letters, digits, '_')")
  endif()
  if(NOT ARG_MANIFEST)
    message(FATAL_ERROR "penumbra_add_shader_library(${name}): MANIFEST <file> is required")
  endif()
  cmake_path(ABSOLUTE_PATH ARG_MANIFEST BASE_DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR})
  if(NOT ARG_OUTPUT_DIR)
    set(ARG_OUTPUT_DIR ${CMAKE_CURRENT_BINARY_DIR}/${name})
  endif()
  cmake_path(ABSOLUTE_PATH ARG_OUTPUT_DIR BASE_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
  set(build_args)
  foreach(target IN LISTS ARG_TARGETS)
    list(APPEND build_args --target ${target})
  endforeach()
  if(ARG_HLSL_COMPILER)
    list(APPEND build_args --hlsl-compiler ${ARG_HLSL_COMPILER})
  endif()
  if(NOT DEFINED ARG_SHADERLIB_DIR AND DEFINED Penumbra_SHADERLIB_DIR
     AND IS_DIRECTORY "${Penumbra_SHADERLIB_DIR}")
    set(ARG_SHADERLIB_DIR ${Penumbra_SHADERLIB_DIR})
  endif()
  if(ARG_SHADERLIB_DIR)
    cmake_path(ABSOLUTE_PATH ARG_SHADERLIB_DIR BASE_DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR})
    list(APPEND build_args --shaderlib ${ARG_SHADERLIB_DIR})
  endif()
  set(source ${ARG_OUTPUT_DIR}/${name}_shaders.cpp)
  set(index ${ARG_OUTPUT_DIR}/library/index.json)
  set(depfile ${ARG_OUTPUT_DIR}/${name}.d)
  # index.json comes first: it is the depfile's target. The header is a
  # byproduct: `penumbra embed` rewrites it only when it changes, and Ninja
  # then rebuilds nothing that includes it.
  add_custom_command(
    OUTPUT ${index} ${source}
    BYPRODUCTS ${ARG_OUTPUT_DIR}/include/${name}/shaders.hpp
    COMMAND Penumbra::penumbra build ${ARG_MANIFEST} -o ${ARG_OUTPUT_DIR}/library -q
            --depfile ${depfile} ${build_args}
    COMMAND Penumbra::penumbra embed ${ARG_OUTPUT_DIR}/library --name ${name}
            -o ${ARG_OUTPUT_DIR}
    DEPENDS ${ARG_MANIFEST} $<TARGET_FILE:Penumbra::penumbra>
    DEPFILE ${depfile}
    COMMENT "penumbra: shader library ${name} from ${ARG_MANIFEST}"
    VERBATIM)
  add_library(${name} STATIC ${source})
  target_include_directories(${name} PUBLIC $<BUILD_INTERFACE:${ARG_OUTPUT_DIR}/include>)
  target_link_libraries(${name} PUBLIC Penumbra::shaders)
endfunction()
