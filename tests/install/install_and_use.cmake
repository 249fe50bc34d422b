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

# Install into a staging prefix and move it: the example then uses a package that was not
# written for the place it is in, so any absolute path into the install tree would break it.
set(staging ${PREFIX}-staging)
file(REMOVE_RECURSE ${staging})
run_step("cmake --install"
  ${CMAKE_COMMAND} --install ${GENMOD_BUILD_DIR} --prefix ${staging} --config ${CONFIG})
file(RENAME ${staging} ${PREFIX})

# Relocatable: the exported targets name their dependencies by imported target
# (OpenMeshCore, TBB::tbb, ...), never by a library file's absolute path.
file(GLOB target_files ${PREFIX}/lib*/cmake/genmod/genmodTargets*.cmake)
if(NOT target_files)
  message(FATAL_ERROR "install test: no genmodTargets*.cmake under ${PREFIX}")
endif()
foreach(target_file IN LISTS target_files)
  file(STRINGS ${target_file} link_lines REGEX "INTERFACE_LINK_LIBRARIES")
  foreach(line IN LISTS link_lines)
    if(line MATCHES "\"/|;/|\\.so|\\.a[;\"]")
      message(FATAL_ERROR "install test: ${target_file} links a library by its path, not by a target: ${line}")
    endif()
  endforeach()
  file(STRINGS ${target_file} staged REGEX "${staging}")
  if(staged)
    message(FATAL_ERROR "install test: ${target_file} names the staging prefix ${staging}: ${staged}")
  endif()
endforeach()

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
