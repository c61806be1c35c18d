# -DISOLAB_SANITIZE=ON: AddressSanitizer and UndefinedBehaviorSanitizer in every target, for
# scripts/sanitize.sh (a build of its own beside build/; docs/errors.md). Any finding stops
# the program (no recovery), so a test that trips one fails.
option(ISOLAB_SANITIZE "Build with AddressSanitizer and UBSan (scripts/sanitize.sh)" OFF)
if(ISOLAB_SANITIZE)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
    message(FATAL_ERROR "ISOLAB_SANITIZE needs g++ or clang++")
  endif()
  add_compile_options(-fsanitize=address,undefined -fno-sanitize-recover=all
                      -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined)
  # Eigen uses its own aligned allocator under ASan unless told malloc is aligned already; Debian's
  # pagmo, built without it, then frees Eigen's memory with free(): a false heap error. glibc's
  # malloc aligns to 16 bytes, all Eigen asks for without AVX.
  add_compile_definitions(EIGEN_MALLOC_ALREADY_ALIGNED=1)
endif()
