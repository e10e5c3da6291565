# Sanitizer and fuzzing instrumentation for every target defined after this file is included.
#
#   EXACTCCD_SANITIZE  "" (off), "address,undefined" or "thread": passed to -fsanitize= for
#                      compiling and linking. Undefined behaviour aborts at the first report
#                      (-fno-sanitize-recover), so a test cannot pass over it.
#   EXACTCCD_FUZZ      also builds the libFuzzer harnesses (tests/fuzz/; clang only) and
#                      compiles everything with -fsanitize=fuzzer-no-link, so that libFuzzer sees
#                      the coverage of the library's code, not only the harnesses'.
#
# Both keep the project's floating-point flags (EXACTCCD_FP_FLAGS); CGAL's assertions stay on
# unless the build type defines NDEBUG (use Debug). .ci/sanitizers.sh is the CI entry point.

set(EXACTCCD_SANITIZE "" CACHE STRING
    "Sanitizers for every target: empty (none), address,undefined, or thread")

if(EXACTCCD_SANITIZE)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang|GNU")
    message(FATAL_ERROR "EXACTCCD_SANITIZE needs clang or gcc, not ${CMAKE_CXX_COMPILER_ID}")
  endif()
  if(EXACTCCD_SANITIZE MATCHES "thread" AND EXACTCCD_SANITIZE MATCHES "address")
    message(FATAL_ERROR "EXACTCCD_SANITIZE: thread and address cannot be combined")
  endif()
  add_compile_options(-fsanitize=${EXACTCCD_SANITIZE} -fno-omit-frame-pointer)
  add_link_options(-fsanitize=${EXACTCCD_SANITIZE})
  if(EXACTCCD_SANITIZE MATCHES "undefined")
    add_compile_options(-fno-sanitize-recover=undefined)
  endif()
  if(EXACTCCD_SANITIZE MATCHES "thread")
    # TBB's headers then announce their task hand-offs through ITT (libtbb's call_itt_notify),
    # which tests/tsan/tbb_tsan_bridge.cpp turns into ThreadSanitizer synchronisation.
    add_compile_definitions(TBB_USE_PROFILING_TOOLS=2)
  endif()
endif()

if(EXACTCCD_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "EXACTCCD_FUZZ needs clang (libFuzzer): configure with "
                        "-DCMAKE_CXX_COMPILER=clang++")
  endif()
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()
