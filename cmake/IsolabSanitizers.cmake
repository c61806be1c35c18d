# -DISOLAB_SANITIZE=ON: AddressSanitizer and UndefinedBehaviorSanitizer in every target, for
# scripts/sanitize.sh (a build of its own beside build/; docs/errors.md). Any finding stops
# the program (no recovery), so a test that trips one fails.
option(ISOLAB_SANITIZE "Build with AddressSanitizer and UBSan (scripts/sanitize.sh)" OFF)
set(ISOLAB_SANITIZER_COMPILE_OPTIONS)
set(ISOLAB_SANITIZER_LINK_OPTIONS)
set(ISOLAB_SANITIZER_DEFINITIONS)
if(ISOLAB_SANITIZE)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
    message(FATAL_ERROR "ISOLAB_SANITIZE needs g++ or clang++")
  endif()
  set(ISOLAB_SANITIZER_COMPILE_OPTIONS -fsanitize=address,undefined -fno-sanitize-recover=all
                                       -fno-omit-frame-pointer)
  set(ISOLAB_SANITIZER_LINK_OPTIONS -fsanitize=address,undefined)
  # Eigen uses its own aligned allocator under ASan unless told malloc is aligned already; Debian's
  # pagmo, built without it, then frees Eigen's memory with free(): a false heap error. glibc's
  # malloc aligns to 16 bytes, all Eigen asks for without AVX.
  set(ISOLAB_SANITIZER_DEFINITIONS EIGEN_MALLOC_ALREADY_ALIGNED=1)
  add_compile_options(${ISOLAB_SANITIZER_COMPILE_OPTIONS})
  add_link_options(${ISOLAB_SANITIZER_LINK_OPTIONS})
  add_compile_definitions(${ISOLAB_SANITIZER_DEFINITIONS})
endif()

# The installed static libraries of a sanitized build call the sanitizers' runtimes and share
# Eigen objects compiled under EIGEN_MALLOC_ALREADY_ALIGNED: a program linking them needs the same
# flags, so they are the exported targets' usage requirements (cmake/IsolabInstall.cmake). Inside
# this tree they repeat the global options above, which CMake drops as duplicates.
function(isolab_pass_sanitizers_on target)
  if(ISOLAB_SANITIZE)
    target_compile_options(${target} INTERFACE ${ISOLAB_SANITIZER_COMPILE_OPTIONS})
    target_link_options(${target} INTERFACE ${ISOLAB_SANITIZER_LINK_OPTIONS})
    target_compile_definitions(${target} INTERFACE ${ISOLAB_SANITIZER_DEFINITIONS})
  endif()
endfunction()
