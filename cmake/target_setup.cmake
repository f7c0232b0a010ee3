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
option(RODNET_NATIVE
  "Compile with -O3 -march=native: faster, but the binaries run only on CPUs like this one"
  OFF)

# deal.II's flags for the build type, and -O3 -march=native after them (the
# last -O wins) where RODNET_NATIVE is on.
function(rodnet_compile_like_deal_ii target)
  deal_ii_setup_target(${target})
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
