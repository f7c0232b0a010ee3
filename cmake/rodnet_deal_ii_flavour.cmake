# The flavour of deal.II's library (DEBUG or RELEASE) that
# deal_ii_setup_target links for the build type @p build_type, stored in
# @p result: the Debug library only for Debug and where deal.II has one.
# Used where librodnet is built (CMakeLists.txt) and, installed beside
# rodnetConfig.cmake, where a program is built against it.
function(rodnet_deal_ii_flavour build_type result)
  if(build_type STREQUAL "Debug" AND DEAL_II_BUILD_TYPE MATCHES "Debug")
    set(${result} DEBUG PARENT_SCOPE)
  else()
    set(${result} RELEASE PARENT_SCOPE)
  endif()
endfunction()
