# Sanitizer and fuzzing builds (doc/sanitizers_and_fuzzing.md).
#
# RODNET_SANITIZE=address,undefined compiles every target of the project
# with those sanitizers; -fno-sanitize-recover makes every finding of
# UndefinedBehaviorSanitizer end the program, so that a test fails on it.
# RODNET_BUILD_FUZZERS=ON (clang only) adds libFuzzer's coverage
# instrumentation and builds the fuzz targets of fuzz/.
#
# The libraries of Debian (deal.II, Trilinos, Open MPI) are not
# instrumented; their leaks at exit are suppressed by the files in
# cmake/sanitizers/, which RODNET_SANITIZER_ENVIRONMENT hands to every test.
set(RODNET_SANITIZE "" CACHE STRING
  "Sanitizers of every target, e.g. address,undefined (empty: none)")
option(RODNET_BUILD_FUZZERS "Build the libFuzzer targets of fuzz/ (clang)" OFF)

set(RODNET_SANITIZER_ENVIRONMENT "")
if(RODNET_SANITIZE)
  add_compile_options(-fsanitize=${RODNET_SANITIZE} -fno-sanitize-recover=all
    -fno-omit-frame-pointer)
  add_link_options(-fsanitize=${RODNET_SANITIZE})
  set(_supp ${CMAKE_SOURCE_DIR}/cmake/sanitizers)
  # What Open MPI's unloaded plugins lose in MPI_Init and MPI_Finalize is
  # left out by rodnet::MPISession (base/mpi_session.cc), so the fast
  # unwinder serves: the full one doubled the time of every malloc.
  set(RODNET_SANITIZER_ENVIRONMENT
    "ASAN_OPTIONS=detect_leaks=1:strict_string_checks=1:detect_stack_use_after_return=1"
    "LSAN_OPTIONS=suppressions=${_supp}/lsan.supp:print_suppressions=0"
    "UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1:suppressions=${_supp}/ubsan.supp")
endif()

if(RODNET_BUILD_FUZZERS)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "RODNET_BUILD_FUZZERS needs clang (libFuzzer): "
      "configure with -DCMAKE_CXX_COMPILER=clang++")
  endif()
  if(NOT RODNET_SANITIZE)
    message(FATAL_ERROR "RODNET_BUILD_FUZZERS needs RODNET_SANITIZE, "
      "e.g. address,undefined: a fuzzer finds what the sanitizers report")
  endif()
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()
