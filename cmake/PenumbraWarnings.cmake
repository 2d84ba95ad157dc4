# One place for warning flags and sanitizers; every project target calls
# penumbra_target_defaults().
function(penumbra_target_defaults target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
                                           -Wno-sign-conversion)
  if(PENUMBRA_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
  if(PENUMBRA_SANITIZE)
    target_compile_options(${target} PRIVATE -fsanitize=address,undefined -fno-omit-frame-pointer)
    target_link_options(${target} PRIVATE -fsanitize=address,undefined)
  endif()
endfunction()
