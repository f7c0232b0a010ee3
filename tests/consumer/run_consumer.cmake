# Installs the build tree into WORK_DIR/prefix, builds the consumer against
# it and runs it, and runs the installed rodnet-run; any failing step fails
# the test.
file(REMOVE_RECURSE ${WORK_DIR})
foreach(_step
    "${CMAKE_COMMAND};--install;${BINARY_DIR};--prefix;${WORK_DIR}/prefix"
    "${CMAKE_COMMAND};-S;${SOURCE_DIR};-B;${WORK_DIR}/build;-DCMAKE_BUILD_TYPE=${BUILD_TYPE};-DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix"
    "${CMAKE_COMMAND};--build;${WORK_DIR}/build"
    "${CMAKE_COMMAND};-E;env;LD_LIBRARY_PATH=${WORK_DIR}/prefix/lib:${WORK_DIR}/prefix/lib/x86_64-linux-gnu;${WORK_DIR}/build/consumer"
    # The installed launcher finds its driver module without help.
    "${WORK_DIR}/prefix/bin/rodnet-run;--version"
    "${WORK_DIR}/prefix/bin/rodnet-run;--help")
  execute_process(COMMAND ${_step} RESULT_VARIABLE _result)
  if(NOT _result EQUAL 0)
    message(FATAL_ERROR "consumer step failed (${_result}): ${_step}")
  endif()
endforeach()
