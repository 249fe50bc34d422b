# Script for the install_package test (cmake -P): install, then build and run the example
# against the installed package only. Variables: see tests/install/CMakeLists.txt.

function(run_step what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "install test: ${what} failed (${result})")
  endif()
endfunction()

# Start clean so that a stale prefix or example build cannot hide a packaging error.
file(REMOVE_RECURSE ${PREFIX} ${EXAMPLE_BUILD_DIR})

run_step("cmake --install"
  ${CMAKE_COMMAND} --install ${GENMOD_BUILD_DIR} --prefix ${PREFIX} --config ${CONFIG})

run_step("configuring the example"
  ${CMAKE_COMMAND} -S ${EXAMPLE_SOURCE_DIR} -B ${EXAMPLE_BUILD_DIR} -G ${GENERATOR}
    -DCMAKE_MAKE_PROGRAM=${MAKE_PROGRAM} -DCMAKE_CXX_COMPILER=${CXX_COMPILER}
    -DCMAKE_BUILD_TYPE=${CONFIG} -DCMAKE_PREFIX_PATH=${PREFIX})

# The package must come from the prefix, not from a copy installed elsewhere on the machine.
file(STRINGS ${EXAMPLE_BUILD_DIR}/CMakeCache.txt found_dir REGEX "^genmod_DIR:")
string(REGEX REPLACE "^genmod_DIR:[A-Z]+=" "" found_dir "${found_dir}")
cmake_path(IS_PREFIX PREFIX "${found_dir}" NORMALIZE from_prefix)
if(NOT from_prefix)
  message(FATAL_ERROR "install test: find_package(genmod) used ${found_dir}, not the package in ${PREFIX}")
endif()

run_step("building the example" ${CMAKE_COMMAND} --build ${EXAMPLE_BUILD_DIR} --config ${CONFIG})

find_program(example genmod_install_example PATHS ${EXAMPLE_BUILD_DIR} ${EXAMPLE_BUILD_DIR}/${CONFIG}
  NO_DEFAULT_PATH REQUIRED)
run_step("running the example" ${example})
