# Compile settings shared by every genmod target.
#
# -frounding-math: interval code changes the FPU rounding mode; without it GCC may fold or
#   reorder operations across those changes. It is part of the kernel's usage requirements, so
#   code inlined from genmod headers into a user's program is compiled with it too.
# -ffp-contract=off: no fused multiply-add contraction, so the scalar and batch evaluators
#   produce bitwise identical results whatever the vector width.
# -Werror=switch: a switch over an enum without a default names every value, so an opcode
#   added to the table (opcode.hpp) fails to compile until every evaluator has its rule.
add_library(genmod_build_flags INTERFACE)
target_compile_options(genmod_build_flags INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor -Wold-style-cast -Wcast-align
  -Wnull-dereference -Wdouble-promotion -Wformat=2 -Wimplicit-fallthrough -Werror=switch)

if(GENMOD_SANITIZE)
  target_compile_options(genmod_build_flags INTERFACE -fsanitize=${GENMOD_SANITIZE} -fno-omit-frame-pointer
    -fno-sanitize-recover=all)
  target_link_options(genmod_build_flags INTERFACE -fsanitize=${GENMOD_SANITIZE})
endif()

# Applies the project's settings to a target of ours (never exported to users).
function(genmod_target_defaults target)
  target_link_libraries(${target} PRIVATE $<BUILD_INTERFACE:genmod_build_flags>)
endfunction()
