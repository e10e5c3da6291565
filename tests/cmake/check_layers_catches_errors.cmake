# layering_catches_violations: builds a small tree in which the exact layer includes the oracle,
# the corpus includes a test header, and an example includes a private header, and requires
# check_layers.cmake to fail naming each of the three (and none of the allowed includes).
#   cmake -DCHECKER=<check_layers.cmake> -DWORK=<scratch folder> -P check_layers_catches_errors.cmake
file(REMOVE_RECURSE "${WORK}")
file(WRITE "${WORK}/core/include/exactccd/types.hpp" "#pragma once\n")
file(WRITE "${WORK}/core/predicates/motion.hpp" "#pragma once\n")
file(WRITE "${WORK}/exact/rational.hpp"
  "#pragma once\n#include \"core/predicates/motion.hpp\"\n#include \"exactccd/types.hpp\"\n")
file(WRITE "${WORK}/exact/rational.cpp"
  "#include \"exact/rational.hpp\"\n#include \"oracle/check.hpp\"\n")
file(WRITE "${WORK}/oracle/check.hpp" "#pragma once\n#include \"exact/rational.hpp\"\n")
file(WRITE "${WORK}/corpus/families.cpp" "// a generator\n#include \"tests/test_scale.hpp\"\n")
file(WRITE "${WORK}/tests/test_scale.hpp" "#pragma once\n#include \"oracle/check.hpp\"\n")
file(WRITE "${WORK}/examples/consumer/main.cpp"
  "#include \"exactccd/types.hpp\"\n#include \"../../exact/rational.hpp\"\n")
execute_process(COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${WORK} -P ${CHECKER}
                RESULT_VARIABLE failed OUTPUT_VARIABLE out ERROR_VARIABLE err)
set(all "${out}${err}")
if(NOT failed)
  message(FATAL_ERROR "check_layers passed a broken tree:\n${all}")
endif()
# (CMake may wrap the message: compare without line breaks.)
string(REGEX REPLACE "[ \n]+" " " all "${all}")
foreach(expected "exact/rational.cpp:2: includes \"oracle/check.hpp\""
                 "corpus/families.cpp:2: includes \"tests/test_scale.hpp\""
                 "examples/consumer/main.cpp:2: includes \"../../exact/rational.hpp\"")
  string(FIND "${all}" "${expected}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "check_layers did not report: ${expected}\n${all}")
  endif()
endforeach()
foreach(unexpected "exact/rational.hpp:" "oracle/check.hpp:" "tests/test_scale.hpp:"
                   "exact/rational.cpp:1:" "examples/consumer/main.cpp:1:")
  string(FIND "${all}" "${unexpected}" at)
  if(NOT at EQUAL -1)
    message(FATAL_ERROR "check_layers reported an allowed include: ${unexpected}\n${all}")
  endif()
endforeach()
message(STATUS "check_layers catches includes from above: exact -> oracle, corpus -> tests, "
               "examples -> exact")
