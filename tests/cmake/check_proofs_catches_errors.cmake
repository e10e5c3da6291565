# proofs_test_catches_errors: builds a small tree with a dangling PROOF: reference, anchors that
# name no test (one after a line holding an unbalanced "[0, 1)"), tests that do not exist, a
# cited identifier and path that do not exist, and a proof the index does not link; requires
# check_proofs.cmake to fail on each, and on nothing that is right (math is not read as code).
#   cmake -DCHECKER=<check_proofs.cmake> -DWORK=<scratch folder> -P check_proofs_catches_errors.cmake
# The references are built from a variable, so that this file itself cites no proof.
set(p "proofs/p.md")
file(REMOVE_RECURSE "${WORK}")
file(WRITE "${WORK}/proofs/README.md" "- [`p.md`](p.md): the widget.\n")
file(WRITE "${WORK}/proofs/p.md"
  "<a id=\"covered\"></a>\n## A\nChecked by `widget_test`, for $t$ in [0, 1).\n\n"
  "<a id=\"after-bracket\"></a>\n## B\nNo test here; `Widget::widget_value` exists and\n"
  "`NoSuchType::no_such_function` does not, nor does `core/no_such_file.hpp`;\n"
  "`core/widget.cpp` and $`not_code_but_math`$ are fine.\n\n"
  "<a id=\"ghost\"></a>\n## C\nChecked by `Widget.Works`, `Ghost.DoesNotExist` and\n"
  "`test_widget.py::test_missing`.\n\n"
  "<a id=\"alias\"></a>\n<a id=\"python\"></a>\n## D\nChecked by `test_widget.py::test_value`.\n")
file(WRITE "${WORK}/proofs/q.md" "<a id=\"unlisted\"></a>\nChecked by `Widget.*`.\n")
file(WRITE "${WORK}/tests/widget_test.cpp" "TEST(Widget, Works) {}\n")
file(WRITE "${WORK}/python/tests/test_widget.py" "def test_value():\n    pass\n")
file(WRITE "${WORK}/core/widget.cpp"
  "// PROOF: ${p}#covered\n// PROOF: ${p}#missing\nstruct Widget { int widget_value; };\n")
execute_process(COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${WORK} -P ${CHECKER}
                RESULT_VARIABLE failed OUTPUT_VARIABLE out ERROR_VARIABLE err)
set(all "${out}${err}")
if(NOT failed)
  message(FATAL_ERROR "check_proofs passed a broken tree:\n${all}")
endif()
# (CMake may wrap the message: compare without line breaks.)
string(REGEX REPLACE "[ \n]+" " " all "${all}")
set(missed "")
foreach(expected "core/widget.cpp: ${p}#missing does not resolve"
                 "${p}#after-bracket: names no test"
                 "${p}#ghost: names `Ghost.DoesNotExist`, which is no test"
                 "${p}#ghost: names `test_widget.py::test_missing`, which is no test"
                 "${p}:8: cites `NoSuchType::no_such_function`: `NoSuchType` occurs in no"
                 "${p}:8: cites `NoSuchType::no_such_function`: `no_such_function` occurs in no"
                 "${p}:8: cites `core/no_such_file.hpp`, which is no file"
                 "proofs/README.md: does not link proofs/q.md")
  string(FIND "${all}" "${expected}" at)
  if(at EQUAL -1)
    string(APPEND missed "  ${expected}\n")
  endif()
endforeach()
if(missed)
  message(FATAL_ERROR "check_proofs did not report:\n${missed}${all}")
endif()
foreach(unexpected "#covered does not resolve" "#covered: names" "#alias: names" "#python: names"
                   "widget_value"
                   "widget.cpp`" "not_code_but_math" "link proofs/p.md")
  string(FIND "${all}" "${unexpected}" at)
  if(NOT at EQUAL -1)
    message(FATAL_ERROR "check_proofs reported something right: ${unexpected}\n${all}")
  endif()
endforeach()
message(STATUS "check_proofs catches a dangling reference, uncovered anchors (also after an "
               "unbalanced '['), ghost tests, a cited name and path that do not exist, and an "
               "unlisted proof")
