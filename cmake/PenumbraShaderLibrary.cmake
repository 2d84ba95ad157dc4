# penumbra_add_shader_library(<name> MANIFEST <file> [TARGETS <target>...]
#                             [FORMS <form>...] [OUTPUT_DIR <dir>] [HLSL_COMPILER <path>]
#                             [SHADERLIB_DIR <dir>] [GROUPS <n>])
#
# A static library <name> whose header <name>/shaders.hpp holds every variant
# of MANIFEST for TARGETS and FORMS (query, deferred, function; default: the
# manifest's own; `penumbra build --target/--form`), with the reflection
# and a lookup by technique and keys (docs/embedding.md). Generated at build
# time, never at configure time, in GROUPS (default 16) hermetic steps:
# `penumbra build --group I/N` writes each group's part under
# OUTPUT_DIR/parts (default OUTPUT_DIR: <current binary dir>/<name>), then
# `penumbra merge` joins them into OUTPUT_DIR/library, byte for byte what one
# `penumbra build` writes. Each step also embeds its part (`penumbra embed
# --part`) as a source of its own, so a large library compiles as GROUPS
# objects, in parallel, and an edit recompiles the parts it changed. A variant
# belongs to a group by its name's hash, so an edited manifest set reruns the
# steps of the groups whose variants changed; the others find their build
# stamp current and leave their part untouched, and a step whose part comes
# out the same leaves it untouched too, so Ninja reruns nothing after it.
# Compiled shaders come from the shader cache when they were built before
# (docs/cache.md). The Direct3D bytecode needs vkd3d-compiler: HLSL_COMPILER,
# or what `penumbra build` finds (PENUMBRA_HLSL_COMPILER, sid-tools.sh's cache).
#
# The shaders are compiled from SHADERLIB_DIR's files (`penumbra build
# --shaderlib`), by default the installed package's Penumbra_SHADERLIB_DIR
# when it exists. Each step's depfile lists the files of it that its variants
# include, so editing one of them reruns the steps that read it and editing
# any other reruns nothing. Without a folder (in Penumbra's own tree, where
# Penumbra_SHADERLIB_DIR is unset) the copy built into `penumbra` is used:
# the steps already depend on that executable, which is rebuilt when
# shaderlib/ changes.
function(penumbra_add_shader_library name)
  cmake_parse_arguments(PARSE_ARGV 1 ARG "" "MANIFEST;OUTPUT_DIR;HLSL_COMPILER;SHADERLIB_DIR;GROUPS"
                        "TARGETS;FORMS")
  if(ARG_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "penumbra_add_shader_library(${name}): unknown arguments "
                        "'${ARG_UNPARSED_ARGUMENTS}' (allowed: MANIFEST, TARGETS, FORMS, OUTPUT_DIR, "
                        "HLSL_COMPILER, SHADERLIB_DIR, GROUPS)")
  endif()
  if(NOT name MATCHES "^[A-Za-z_][A-Za-z0-9_]*$")
    message(FATAL_ERROR "penumbra_add_shader_library(${name}): the name becomes a C++ "
                        "namespace and must be an identifier (letters, digits, '_')")
  endif()
  if(NOT ARG_MANIFEST)
    message(FATAL_ERROR "penumbra_add_shader_library(${name}): MANIFEST <file> is required")
  endif()
  if(NOT DEFINED ARG_GROUPS)
    set(ARG_GROUPS 16)
  endif()
  if(NOT ARG_GROUPS MATCHES "^[1-9][0-9]*$" OR ARG_GROUPS GREATER 4096)
    message(FATAL_ERROR "penumbra_add_shader_library(${name}): GROUPS ${ARG_GROUPS} is not "
                        "allowed; allowed: an integer 1..4096")
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
  foreach(form IN LISTS ARG_FORMS)
    list(APPEND build_args --form ${form})
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

  # One step per group: its part's index.json is the depfile's target, and
  # its part of the embedded shaders is one object of its own.
  set(parts)
  set(part_indexes)
  set(sources ${ARG_OUTPUT_DIR}/${name}_shaders.cpp)
  foreach(group RANGE 1 ${ARG_GROUPS})
    set(part ${ARG_OUTPUT_DIR}/parts/${group})
    set(part_source ${ARG_OUTPUT_DIR}/${name}_shaders_${group}.cpp)
    add_custom_command(
      OUTPUT ${part}/index.json
      BYPRODUCTS ${part_source}
      COMMAND Penumbra::penumbra build ${ARG_MANIFEST} -o ${part} -q --group ${group}/${ARG_GROUPS}
              --depfile ${ARG_OUTPUT_DIR}/parts/${group}.d ${build_args}
      COMMAND Penumbra::penumbra embed ${part} --name ${name} --part ${group} -o ${ARG_OUTPUT_DIR}
              -q
      DEPENDS ${ARG_MANIFEST} $<TARGET_FILE:Penumbra::penumbra>
      DEPFILE ${ARG_OUTPUT_DIR}/parts/${group}.d
      COMMENT "penumbra: ${name}, group ${group}/${ARG_GROUPS}"
      VERBATIM)
    list(APPEND parts ${part})
    list(APPEND part_indexes ${part}/index.json)
    list(APPEND sources ${part_source})
  endforeach()

  # The header and the index of the parts depend on the name and GROUPS
  # alone; `penumbra embed` rewrites them only when they change, so Ninja
  # rebuilds nothing that includes the header when the shaders change.
  add_custom_command(
    OUTPUT ${ARG_OUTPUT_DIR}/library/index.json ${ARG_OUTPUT_DIR}/${name}_shaders.cpp
    BYPRODUCTS ${ARG_OUTPUT_DIR}/include/${name}/shaders.hpp
    COMMAND Penumbra::penumbra merge ${parts} -o ${ARG_OUTPUT_DIR}/library -q
    COMMAND Penumbra::penumbra embed --name ${name} --parts ${ARG_GROUPS} -o ${ARG_OUTPUT_DIR} -q
    DEPENDS ${part_indexes} $<TARGET_FILE:Penumbra::penumbra>
    COMMENT "penumbra: shader library ${name} (${ARG_GROUPS} groups)"
    VERBATIM)
  add_library(${name} STATIC ${sources})
  target_include_directories(${name} PUBLIC $<BUILD_INTERFACE:${ARG_OUTPUT_DIR}/include>)
  target_link_libraries(${name} PUBLIC Penumbra::shaders)
endfunction()
