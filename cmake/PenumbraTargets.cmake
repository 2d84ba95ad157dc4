# One place for warning flags, sanitizers and the shape of a library target:
# every project target calls penumbra_target_defaults().
function(penumbra_target_defaults target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
                                           -Wno-sign-conversion)
  # GCC 12 at -O3 (Release) reports -Wrestrict inside libstdc++ for
  # `"x" + std::string` (GCC bug 105329, fixed in 13); the warning is false.
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
    target_compile_options(${target} PRIVATE -Wno-restrict)
  endif()
  if(PENUMBRA_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
  if(PENUMBRA_SANITIZE OR PENUMBRA_FUZZ)
    # UBSan findings abort, so that a test or a fuzzer fails on them. Its
    # vptr check needs the typeinfo of every polymorphic class it sees, and
    # Debian's glslang is built without RTTI (glslang::TShader has none).
    target_compile_options(${target} PRIVATE -fsanitize=address,undefined -fno-sanitize=vptr
                                             -fno-sanitize-recover=undefined -fno-omit-frame-pointer)
    target_link_options(${target} PRIVATE -fsanitize=address,undefined)
    # GCC's -Wmaybe-uninitialized misfires on libstdc++ (std::regex's
    # std::function) under ASan's instrumentation, as GCC's manual warns.
    if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
      target_compile_options(${target} PRIVATE -Wno-maybe-uninitialized)
    endif()
  endif()
  if(PENUMBRA_FUZZ)
    target_compile_options(${target} PRIVATE -fsanitize=fuzzer-no-link)
  endif()
endfunction()

# penumbra_add_library(NAME ALIAS SOURCES...): a static library with its
# public headers in include/, private ones in src/, penumbra::ALIAS in the
# tree and Penumbra::ALIAS installed (cmake/PenumbraInstall.cmake). C++20 is a
# usage requirement: the public headers need it.
function(penumbra_add_library name alias)
  add_library(${name} STATIC ${ARGN})
  add_library(penumbra::${alias} ALIAS ${name})
  set_target_properties(${name} PROPERTIES EXPORT_NAME ${alias})
  target_compile_features(${name} PUBLIC cxx_std_20)
  target_include_directories(${name}
    PUBLIC $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
           $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>
    PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/src)
  penumbra_target_defaults(${name})
endfunction()
