# How every target of the project is compiled: deal.II's flags for the build
# type (deal_ii_setup_target), the optional build for this machine's CPU,
# and one precompiled header for all targets.
#
# The precompiled header (cmake/precompiled_headers.h: deal.II, Trilinos,
# Eigen, the standard library) is compiled once per build tree by the object
# library rodnet_pch, with the same flags as every other target, and reused by
# them. A typical source file spent 15 of its 24 s of compilation parsing these
# headers; with the header precompiled it takes 6-9 s (doc/performance.md,
# "Build time").
option(RODNET_PRECOMPILED_HEADERS
  "Precompile the third-party headers once for all targets" ON)
option(RODNET_UNITY_BUILD
  "Compile the library's sources in batches of 8, one compiler run per batch"
  ON)
option(RODNET_NATIVE
  "Compile with -march=native: faster, but the binaries run only on CPUs like this one"
  OFF)

# Debian's deal.II puts full debugging information (-g) into its Release
# flags too, and compressed sections into its Debug flags; both cost build
# time (doc/performance.md, "Build time").
set(RODNET_DEBUG_INFO "" CACHE STRING
  "Debugging information: full (deal.II's flags), lines (-g1: functions and line tables, enough for stack traces), none (-g0); empty: none in Release, full in Debug")
set_property(CACHE RODNET_DEBUG_INFO PROPERTY STRINGS "" full lines none)
set(_debug_info "${RODNET_DEBUG_INFO}")
if("${_debug_info}" STREQUAL "")
  if(CMAKE_BUILD_TYPE STREQUAL "Debug")
    set(_debug_info full)
  else()
    set(_debug_info none)
  endif()
endif()
if(NOT _debug_info MATCHES "^(full|lines|none)$")
  message(FATAL_ERROR "RODNET_DEBUG_INFO is \"${RODNET_DEBUG_INFO}\": "
    "choose full, lines or none (or leave it empty)")
endif()
set(RODNET_DEBUG_INFO_FLAGS "")
if(_debug_info STREQUAL "lines")
  set(RODNET_DEBUG_INFO_FLAGS -g1 -Wa,--nocompress-debug-sections)
elseif(_debug_info STREQUAL "none")
  set(RODNET_DEBUG_INFO_FLAGS -g0)
endif()

# deal.II's flags for the build type, then the ones that override them (the
# last -O and -g win): the debugging information asked for, -O3 instead of
# deal.II's -O2 outside Debug, and -march=native where RODNET_NATIVE is on.
# -O3 changes no instruction set, so the binaries stay portable; it inlines
# the small fixed-size Eigen products of the kernels that -O2 leaves as
# calls (1.3x on the assembled kernel rates, doc/performance.md).
function(rodnet_compile_like_deal_ii target)
  deal_ii_setup_target(${target})
  target_compile_options(${target} PRIVATE ${RODNET_DEBUG_INFO_FLAGS}
    $<$<NOT:$<CONFIG:Debug>>:-O3>)
  if(RODNET_NATIVE)
    target_compile_options(${target} PRIVATE -O3 -march=native)
  endif()
endfunction()

if(RODNET_PRECOMPILED_HEADERS)
  add_library(rodnet_pch OBJECT ${CMAKE_SOURCE_DIR}/cmake/precompiled_headers.cc)
  target_precompile_headers(rodnet_pch PRIVATE
    ${CMAKE_SOURCE_DIR}/cmake/precompiled_headers.h)
  set_target_properties(rodnet_pch PROPERTIES POSITION_INDEPENDENT_CODE ON)
  target_link_libraries(rodnet_pch Eigen3::Eigen)
  rodnet_compile_like_deal_ii(rodnet_pch)
endif()

# Sets up @p target as every target of rodnet: deal.II's flags, the native
# options, the precompiled header.
function(rodnet_setup_target target)
  rodnet_compile_like_deal_ii(${target})
  if(RODNET_PRECOMPILED_HEADERS)
    target_precompile_headers(${target} REUSE_FROM rodnet_pch)
  endif()
endfunction()

# The library's sources compiled in batches (CMake's unity build): loading
# the precompiled header takes 3.5 s per compiler run, and the batch's
# sources share their template instantiations; the library compiled in
# 260 s of CPU instead of 840 s (doc/performance.md, "Build time"). Names in
# the anonymous namespaces of the library's files must therefore differ
# from file to file.
function(rodnet_compile_in_batches target)
  if(RODNET_UNITY_BUILD)
    set_target_properties(${target} PROPERTIES
      UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE 8)
  endif()
endfunction()
