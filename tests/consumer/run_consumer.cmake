# The README's library recipe, followed as a user would: install the build
# tree into WORK_DIR/prefix, write the recipe's lines of README.md (section
# "Using the library from your deal.II program") as the CMakeLists.txt of a
# program beside consumer.cc (as my_program.cc), configure it with
# CMAKE_PREFIX_PATH only, build it and run it without LD_LIBRARY_PATH.
#
# MODE find_package: the configuration prints no CMake warning and takes the
# build type of librodnet (BUILD_TYPE), the program ends with exit code 0 and
# prints the tip deflection P L^3 / (3 EI) = 1e-4 / 3 = 3.333e-5 to three
# digits, and the installed rodnet-run finds its driver module.
# MODE refusals: the mistakes that linked deal.II's two libraries into one
# program (a crash at exit) stop the configuration with rodnet's message: a
# build type of the other deal.II library, find_package(rodnet) before
# project(), and deal_ii_setup_target with the other library.
#
# Any failing step fails the test with what it printed.
cmake_minimum_required(VERSION 3.13)

# Runs @p ARGN in a clean environment (no LD_LIBRARY_PATH, no
# CMAKE_BUILD_TYPE default); its exit code and its merged output go to
# @p result and @p output.
function(run result output)
  execute_process(COMMAND ${CMAKE_COMMAND} -E env --unset=LD_LIBRARY_PATH
    --unset=CMAKE_BUILD_TYPE ${ARGN}
    RESULT_VARIABLE _result OUTPUT_VARIABLE _output ERROR_VARIABLE _output)
  set(${result} "${_result}" PARENT_SCOPE)
  set(${output} "${_output}" PARENT_SCOPE)
endfunction()

# Runs @p ARGN and fails the test unless it ends with exit code 0; its output
# goes to @p output.
function(run_ok output)
  run(_result _output ${ARGN})
  if(NOT _result EQUAL 0)
    message(FATAL_ERROR "step failed (${_result}): ${ARGN}\n${_output}")
  endif()
  set(${output} "${_output}" PARENT_SCOPE)
endfunction()

# The indented lines under the README's heading, without their indent.
function(readme_recipe result)
  file(READ ${README} _readme)
  string(REGEX MATCH "## Using the library from your deal.II program\n\
(([^ \n][^\n]*)?\n)*((    [^\n]*\n)+)" _section "${_readme}")
  if(NOT CMAKE_MATCH_3)
    message(FATAL_ERROR "no indented recipe under \"## Using the library "
      "from your deal.II program\" in ${README}")
  endif()
  string(REGEX REPLACE "(^|\n)    " "\\1" _recipe "${CMAKE_MATCH_3}")
  set(${result} "${_recipe}" PARENT_SCOPE)
endfunction()

# Writes a program with the CMakeLists.txt @p lists into WORK_DIR/@p name
# and configures it with CMAKE_PREFIX_PATH and the options @p ARGN; its exit
# code and output go to @p result and @p output.
function(configure_program name lists result output)
  file(WRITE ${WORK_DIR}/${name}/CMakeLists.txt "${lists}")
  configure_file(${SOURCE_DIR}/consumer.cc ${WORK_DIR}/${name}/my_program.cc
    COPYONLY)
  run(_result _output ${CMAKE_COMMAND} -S ${WORK_DIR}/${name}
    -B ${WORK_DIR}/${name}/build -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix ${ARGN})
  set(${result} "${_result}" PARENT_SCOPE)
  set(${output} "${_output}" PARENT_SCOPE)
endfunction()

# Fails the test unless configuring the program @p name with @p lists and
# the options @p ARGN stops with an error whose text matches @p expected.
function(expect_refusal name lists expected)
  configure_program(${name} "${lists}" _result _output ${ARGN})
  if(_result EQUAL 0 OR NOT _output MATCHES "${expected}")
    message(FATAL_ERROR "${name}: expected a configuration error matching "
      "\"${expected}\", got exit code ${_result}:\n${_output}")
  endif()
  message(STATUS "${name}: refused as expected")
endfunction()

file(REMOVE_RECURSE ${WORK_DIR})
run_ok(_ignored ${CMAKE_COMMAND} --install ${BINARY_DIR}
  --prefix ${WORK_DIR}/prefix)
readme_recipe(recipe)

if(MODE STREQUAL "find_package")
  configure_program(readme "${recipe}" _result _configured)
  if(NOT _result EQUAL 0
     OR _configured MATCHES "CMake (Warning|Deprecation|Error)")
    message(FATAL_ERROR "the README's recipe: configuration exit code "
      "${_result}, or a CMake warning in its output:\n${_configured}")
  endif()
  file(STRINGS ${WORK_DIR}/readme/build/CMakeCache.txt _build_type
    REGEX "^CMAKE_BUILD_TYPE:")
  if(NOT _build_type STREQUAL "CMAKE_BUILD_TYPE:STRING=${BUILD_TYPE}")
    message(FATAL_ERROR "the program's build type is \"${_build_type}\", "
      "librodnet's ${BUILD_TYPE}")
  endif()
  run_ok(_ignored ${CMAKE_COMMAND} --build ${WORK_DIR}/readme/build)
  run_ok(_printed ${WORK_DIR}/readme/build/my_program)
  if(NOT _printed MATCHES "tip deflection 3\\.33[0-9]*e-05,")
    message(FATAL_ERROR "the program's tip deflection is not "
      "P L^3/(3 EI) = 3.333e-5:\n${_printed}")
  endif()
  message(STATUS "README recipe: ${_printed}")
  # The installed launcher finds its driver module without help.
  run_ok(_ignored ${WORK_DIR}/prefix/bin/rodnet-run --version)
  run_ok(_ignored ${WORK_DIR}/prefix/bin/rodnet-run --help)
elseif(MODE STREQUAL "refusals")
  if(BUILD_TYPE STREQUAL "Debug")
    set(_other_type Release)
    set(_other_flavour RELEASE)
  else()
    set(_other_type Debug)
    set(_other_flavour DEBUG)
  endif()
  expect_refusal(other_build_type "${recipe}"
    "CMAKE_BUILD_TYPE is ${_other_type}, but librodnet"
    -DCMAKE_BUILD_TYPE=${_other_type})
  # The recipe of 3641289: deal.II's order, find_package before project.
  string(REGEX REPLACE "(project\\([^\n]*\n)(find_package\\([^\n]*\n)"
    "\\2\\1" _package_first "${recipe}")
  expect_refusal(package_before_project "${_package_first}"
    "find_package\\(rodnet\\) comes before")
  expect_refusal(other_deal_ii_library
    "${recipe}deal_ii_setup_target(my_program ${_other_flavour})\n"
    "Target my_program links rodnet::rodnet")
else()
  message(FATAL_ERROR "MODE is \"${MODE}\": find_package or refusals")
endif()
