# proofs_test_catches_errors: builds a small tree with a dangling PROOF: reference, an anchor that
# names no test and one that names a test that does not exist, and requires check_proofs.cmake
# to fail on each of the three.
#   cmake -DCHECKER=<check_proofs.cmake> -DWORK=<scratch folder> -P check_proofs_catches_errors.cmake
# The references are built from a variable, so that this file itself cites no proof.
set(p "proofs/p.md")
file(REMOVE_RECURSE "${WORK}")
file(WRITE "${WORK}/proofs/p.md"
  "<a id=\"covered\"></a>\n## A\nChecked by `widget_test`.\n\n"
  "<a id=\"uncovered\"></a>\n## B\nNo test here.\n\n"
  "<a id=\"ghost\"></a>\n## C\nChecked by `Widget.Works` and `Ghost.DoesNotExist`.\n")
file(WRITE "${WORK}/tests/widget_test.cpp" "TEST(Widget, Works) {}\n")
file(WRITE "${WORK}/core/a.cpp" "// PROOF: ${p}#covered\n// PROOF: ${p}#missing\n")
execute_process(COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${WORK} -P ${CHECKER}
                RESULT_VARIABLE failed OUTPUT_VARIABLE out ERROR_VARIABLE err)
set(all "${out}${err}")
if(NOT failed)
  message(FATAL_ERROR "check_proofs passed a broken tree:\n${all}")
endif()
foreach(expected "core/a.cpp: ${p}#missing does not resolve"
                 "${p}#uncovered: names no test"
                 "${p}#ghost: names `Ghost.DoesNotExist`, which is no test")
  string(FIND "${all}" "${expected}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "check_proofs did not report: ${expected}\n${all}")
  endif()
endforeach()
foreach(unexpected "${p}#covered does not resolve" "${p}#covered: names no test")
  string(FIND "${all}" "${unexpected}" at)
  if(NOT at EQUAL -1)
    message(FATAL_ERROR "check_proofs reported a correct reference: ${unexpected}\n${all}")
  endif()
endforeach()
message(STATUS "check_proofs catches a dangling reference, an uncovered anchor and a ghost test")
