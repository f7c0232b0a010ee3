# One precompiled header for every target of the project
# (cmake/precompiled_headers.h: deal.II, Trilinos, Eigen, the standard
# library). A typical source file spent 15 of its 24 s of compilation parsing
# these headers; with the header precompiled it takes 6-9 s
# (doc/performance.md, "Build time"). The object library rodnet_pch owns the
# header, compiled with the same flags as every other target
# (deal_ii_setup_target), and the others reuse it.
option(RODNET_PRECOMPILED_HEADERS
  "Precompile the third-party headers once for all targets" ON)

if(RODNET_PRECOMPILED_HEADERS)
  add_library(rodnet_pch OBJECT ${CMAKE_SOURCE_DIR}/cmake/precompiled_headers.cc)
  target_precompile_headers(rodnet_pch PRIVATE
    ${CMAKE_SOURCE_DIR}/cmake/precompiled_headers.h)
  set_target_properties(rodnet_pch PROPERTIES POSITION_INDEPENDENT_CODE ON)
  target_link_libraries(rodnet_pch Eigen3::Eigen)
  deal_ii_setup_target(rodnet_pch)
endif()

# Lets @p target compile with the precompiled header (nothing when it is off).
function(rodnet_use_precompiled_headers target)
  if(RODNET_PRECOMPILED_HEADERS)
    target_precompile_headers(${target} REUSE_FROM rodnet_pch)
  endif()
endfunction()
