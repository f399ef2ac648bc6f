# SPDX-License-Identifier: BSD-3-Clause
# Warnings used for every target of the project.
function(projcurve_warnings target)
  if(CMAKE_C_COMPILER_ID MATCHES "GNU|Clang")
    target_compile_options(${target} PRIVATE
      -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion
      -Wstrict-prototypes -Wmissing-prototypes -Wvla)
  endif()
endfunction()
