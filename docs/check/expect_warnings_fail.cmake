# Runs Doxygen on the fixture configuration and passes only if it exits non-zero AND names each
# planted defect: warnings must be reported, and must fail the run.
#   cmake -DDOXYGEN=<doxygen> -DDOXYFILE=<check/Doxyfile> -P expect_warnings_fail.cmake
execute_process(COMMAND ${DOXYGEN} ${DOXYFILE} RESULT_VARIABLE status
                OUTPUT_VARIABLE out ERROR_VARIABLE err)
set(text "${out}${err}")
set(expected "undocumented_function.*is not documented"
             "parameters of member fixture::half_documented_function are not documented"
             "return type of member fixture::half_documented_function is not documented")
foreach(re IN LISTS expected)
  if(NOT text MATCHES "${re}")
    message(FATAL_ERROR "Doxygen did not report: ${re}\n${text}")
  endif()
endforeach()
if(status EQUAL 0)
  message(FATAL_ERROR "Doxygen reported the warnings but exited 0: warnings are not errors\n${text}")
endif()
message(STATUS "Doxygen reported every planted defect and failed (${status}), as it must")
