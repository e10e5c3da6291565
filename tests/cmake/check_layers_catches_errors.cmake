# layering_catches_violations: builds a small tree with includes from a layer not below (exact ->
# oracle, exact -> filters, filters -> exact, corpus -> tests, tests -> bench, examples -> exact;
# one after a comment holding an unbalanced "[0, 1)") and requires check_layers.cmake to fail
# naming each of them, and none of the allowed includes.
#   cmake -DCHECKER=<check_layers.cmake> -DWORK=<scratch folder> -P check_layers_catches_errors.cmake
file(REMOVE_RECURSE "${WORK}")
file(WRITE "${WORK}/core/include/exactccd/types.hpp" "#pragma once\n")
file(WRITE "${WORK}/core/predicates/motion.hpp" "#pragma once\n#include \"exactccd/types.hpp\"\n")
file(WRITE "${WORK}/exact/arithmetic/rational.hpp"
  "#pragma once\n#include \"core/predicates/motion.hpp\"\n#include \"exactccd/types.hpp\"\n")
file(WRITE "${WORK}/exact/arithmetic/rational.cpp"
  "#include \"exact/arithmetic/rational.hpp\"\n#include \"oracle/check.hpp\"\n")
file(WRITE "${WORK}/exact/stages/stage.cpp"
  "#include \"exact/arithmetic/rational.hpp\"\n#include \"filters/interval.hpp\"\n")
file(WRITE "${WORK}/filters/interval.hpp" "#pragma once\n#include \"core/predicates/motion.hpp\"\n")
file(WRITE "${WORK}/filters/cubic_filter.cpp"
  "#include \"interval.hpp\"\n#include \"exact/arithmetic/rational.hpp\"\n")
file(WRITE "${WORK}/pipeline/ccd.hpp"
  "#pragma once\n#include \"filters/interval.hpp\"\n#include \"exact/arithmetic/rational.hpp\"\n")
file(WRITE "${WORK}/oracle/check.hpp" "#pragma once\n#include \"pipeline/ccd.hpp\"\n")
file(WRITE "${WORK}/corpus/families.cpp" "// a generator\n#include \"tests/test_scale.hpp\"\n")
file(WRITE "${WORK}/corpus/walk.cpp"
  "// times in [0, 1)\n// (the bracket above is not closed)\n#include \"tests/test_scale.hpp\"\n")
file(WRITE "${WORK}/study/manifest.hpp" "#pragma once\n#include \"oracle/check.hpp\"\n")
file(WRITE "${WORK}/bench/bench_util.hpp" "#pragma once\n#include \"study/manifest.hpp\"\n")
file(WRITE "${WORK}/tests/test_scale.hpp" "#pragma once\n#include \"oracle/check.hpp\"\n")
file(WRITE "${WORK}/tests/fuzz/manifest_fuzz.cpp"
  "#include \"study/manifest.hpp\"\n#include \"bench/bench_util.hpp\"\n")
file(WRITE "${WORK}/examples/consumer/main.cpp"
  "#include \"exactccd/types.hpp\"\n#include \"../../exact/arithmetic/rational.hpp\"\n")
execute_process(COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${WORK} -P ${CHECKER}
                RESULT_VARIABLE failed OUTPUT_VARIABLE out ERROR_VARIABLE err)
set(all "${out}${err}")
if(NOT failed)
  message(FATAL_ERROR "check_layers passed a broken tree:\n${all}")
endif()
# (CMake may wrap the message: compare without line breaks.)
string(REGEX REPLACE "[ \n]+" " " all "${all}")
set(missed "")
foreach(expected "exact/arithmetic/rational.cpp:2: includes \"oracle/check.hpp\""
                 "exact/stages/stage.cpp:2: includes \"filters/interval.hpp\""
                 "filters/cubic_filter.cpp:2: includes \"exact/arithmetic/rational.hpp\""
                 "corpus/families.cpp:2: includes \"tests/test_scale.hpp\""
                 "corpus/walk.cpp:3: includes \"tests/test_scale.hpp\""
                 "tests/fuzz/manifest_fuzz.cpp:2: includes \"bench/bench_util.hpp\""
                 "examples/consumer/main.cpp:2: includes \"../../exact/arithmetic/rational.hpp\"")
  string(FIND "${all}" "${expected}" at)
  if(at EQUAL -1)
    string(APPEND missed "  ${expected}\n")
  endif()
endforeach()
if(missed)
  message(FATAL_ERROR "check_layers did not report:\n${missed}${all}")
endif()
foreach(unexpected "rational.hpp:" "interval.hpp:" "pipeline/ccd.hpp:" "oracle/check.hpp:"
                   "study/manifest.hpp:" "bench/bench_util.hpp:" "tests/test_scale.hpp:"
                   "core/predicates/motion.hpp:" ".cpp:1:")
  string(FIND "${all}" "${unexpected}" at)
  if(NOT at EQUAL -1)
    message(FATAL_ERROR "check_layers reported an allowed include: ${unexpected}\n${all}")
  endif()
endforeach()
message(STATUS "check_layers catches includes from a layer not below: exact -> oracle, "
               "exact -> filters, filters -> exact, corpus -> tests (also after an unbalanced "
               "'['), tests -> bench, examples -> exact")
