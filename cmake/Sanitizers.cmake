# URDFSNAP_SANITIZE: AddressSanitizer + UndefinedBehaviorSanitizer on every target (GCC or clang),
# stopping at the first undefined behaviour. URDFSNAP_BUILD_FUZZERS (clang only) adds libFuzzer's
# coverage instrumentation to every target, so the fuzz/ targets see into all of urdfsnap's code,
# and implies the sanitizers. Both are for the CI's sanitizer build and scripts/fuzz.sh; the normal
# build uses neither.
option(URDFSNAP_SANITIZE "Build with AddressSanitizer and UndefinedBehaviorSanitizer" OFF)
option(URDFSNAP_BUILD_FUZZERS "Build the libFuzzer targets in fuzz/ (clang; implies URDFSNAP_SANITIZE)" OFF)

if(URDFSNAP_BUILD_FUZZERS)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "URDFSNAP_BUILD_FUZZERS needs clang (libFuzzer): "
                        "configure with -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++")
  endif()
  set(URDFSNAP_SANITIZE ON)
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()

if(URDFSNAP_SANITIZE)
  set(sanitizers -fsanitize=address,undefined -fno-sanitize-recover=undefined)
  add_compile_options(${sanitizers} -fno-omit-frame-pointer)
  add_link_options(${sanitizers})
endif()
