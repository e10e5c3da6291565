# Configures and builds tests/cmake/library_parent (add_subdirectory, shared, defaults), runs its
# consumer, then installs the shared library and checks the install (install_and_consume.cmake
# with CHECK_SHARED).
#   cmake -DSOURCE_DIR=<exactccd source> -DWORK=<scratch dir> [-DCXX=<compiler>] -P shared_parent.cmake
cmake_minimum_required(VERSION 3.25)
file(REMOVE_RECURSE ${WORK})
set(cxx_arg)
if(CXX)
  set(cxx_arg -DCMAKE_CXX_COMPILER=${CXX})
endif()
# No build type given: the parent's cache must keep its empty one.
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/cmake/library_parent
                        -B ${WORK}/build -DEXACTCCD_SOURCE_DIR=${SOURCE_DIR}
                        -DEXPECTED_BUILD_TYPE= ${cxx_arg}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "shared_parent: configure failed:\n${out}\n${err}")
endif()
include(ProcessorCount)
ProcessorCount(cores)
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK}/build -j ${cores}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "shared_parent: build failed:\n${out}\n${err}")
endif()
execute_process(COMMAND ${WORK}/build/parent_consumer RESULT_VARIABLE rc OUTPUT_VARIABLE out
                ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "shared_parent: the consumer failed:\n${out}\n${err}")
endif()
message(STATUS "shared_parent: ${out}")
set(BUILD_DIR ${WORK}/build)
set(WORK ${WORK}/install)
set(CHECK_SHARED ON)
include(${CMAKE_CURRENT_LIST_DIR}/install_and_consume.cmake)
