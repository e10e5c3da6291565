# Installs a built exactccd into a fresh temporary prefix and proves the install works on its own:
# the consumer project examples/consumer configured with find_package(exactccd) against that
# prefix, built and run; the same program built from the pkg-config file alone and run; the
# installed headers free of internal and CGAL includes; the installed command runs.
#   cmake -DBUILD_DIR=<exactccd build> -DSOURCE_DIR=<exactccd source> -DWORK=<scratch dir>
#         [-DCXX=<compiler>] [-DCHECK_SHARED=ON] -P install_and_consume.cmake
# With CHECK_SHARED the installed library must be a shared object with an SONAME that exports
# the public API only.
cmake_minimum_required(VERSION 3.25)

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    string(JOIN " " command ${ARGN})
    message(FATAL_ERROR "install_and_consume: `${command}` failed (${rc}):\n${out}\n${err}")
  endif()
  set(last_output "${out}" PARENT_SCOPE)
endfunction()

file(REMOVE_RECURSE ${WORK})
set(prefix ${WORK}/prefix)
run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})

# Only the public headers, and nothing in them that reaches into the build tree or CGAL.
file(GLOB_RECURSE headers ${prefix}/include/*)
foreach(h IN LISTS headers)
  if(NOT h MATCHES "/include/exactccd/[a-z_0-9]+\\.hpp$")
    message(FATAL_ERROR "install_and_consume: unexpected installed header ${h}")
  endif()
  file(STRINGS ${h} bad REGEX "#include [<\"](exact|filters|core|corpus|oracle|CGAL)/")
  if(bad)
    message(FATAL_ERROR "install_and_consume: ${h} includes an internal header: ${bad}")
  endif()
endforeach()
if(NOT EXISTS ${prefix}/include/exactccd/version.hpp)
  message(FATAL_ERROR "install_and_consume: exactccd/version.hpp was not installed")
endif()

# find_package(exactccd) from a separate project.
set(cxx_arg)
if(CXX)
  set(cxx_arg -DCMAKE_CXX_COMPILER=${CXX})
endif()
run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/examples/consumer -B ${WORK}/consumer
    -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_BUILD_TYPE=Release ${cxx_arg})
run(${CMAKE_COMMAND} --build ${WORK}/consumer)
run(${WORK}/consumer/consumer)
message(STATUS "find_package consumer: ${last_output}")

# The same program from the pkg-config file only.
find_program(PKG_CONFIG pkg-config REQUIRED)
file(GLOB_RECURSE pc_files ${prefix}/*/exactccd.pc)
list(LENGTH pc_files n)
if(NOT n EQUAL 1)
  message(FATAL_ERROR "install_and_consume: expected one exactccd.pc under ${prefix}, found ${n}")
endif()
get_filename_component(pc_dir ${pc_files} DIRECTORY)
set(ENV{PKG_CONFIG_PATH} ${pc_dir})
run(${PKG_CONFIG} --cflags --libs --static exactccd)
string(STRIP "${last_output}" flags)
separate_arguments(flags UNIX_COMMAND "${flags}")
if(NOT CXX)
  set(CXX c++)
endif()
run(${CXX} -std=c++17 ${SOURCE_DIR}/examples/consumer/main.cpp ${flags} -o ${WORK}/pc_consumer)
set(ENV{LD_LIBRARY_PATH} "${prefix}/lib:$ENV{LD_LIBRARY_PATH}")
run(${WORK}/pc_consumer)
message(STATUS "pkg-config consumer: ${last_output}")

# The installed command.
if(EXISTS ${prefix}/bin/exactccd)
  run(${prefix}/bin/exactccd --version)
  message(STATUS "installed command: ${last_output}")
endif()

if(CHECK_SHARED)
  file(GLOB libs ${prefix}/lib*/libexactccd.so.*.*)
  list(LENGTH libs n)
  if(NOT n EQUAL 1)
    message(FATAL_ERROR "install_and_consume: expected libexactccd.so.<version>, found '${libs}'")
  endif()
  find_program(READELF readelf REQUIRED)
  run(${READELF} -d ${libs})
  if(NOT last_output MATCHES "SONAME\\)[^\n]*libexactccd\\.so\\.[0-9]+\\]")
    message(FATAL_ERROR "install_and_consume: no SONAME libexactccd.so.<major>:\n${last_output}")
  endif()
  find_program(NM nm REQUIRED)
  run(${NM} -D -C --defined-only ${libs})
  string(REGEX MATCHALL "[^\n]*exactccd::(exact|filters|predicates|detail|float_only)::[^\n]*"
         leaked "${last_output}")
  if(leaked)
    list(LENGTH leaked count)
    list(GET leaked 0 first)
    message(FATAL_ERROR "install_and_consume: ${count} internal symbols exported, e.g. ${first}")
  endif()
  if(NOT last_output MATCHES "exactccd::vertex_face_ccd")
    message(FATAL_ERROR "install_and_consume: exactccd::vertex_face_ccd is not exported")
  endif()
endif()
message(STATUS "install_and_consume: the installed package works")
