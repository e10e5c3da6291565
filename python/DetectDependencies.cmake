# Finds what the Python module needs (an interpreter with numpy, Python 3's development files,
# pybind11) and sets EXACTCCD_PYTHON_DEFAULT, the default of the option EXACTCCD_BUILD_PYTHON:
# ON when exactccd is the top-level project, not a sanitizer or fuzzing build (an extension module
# loaded by an uninstrumented interpreter cannot carry their runtimes) and everything is found.
# Included from the top-level CMakeLists.txt before the option is declared.

set(EXACTCCD_PYTHON_DEFAULT OFF)
set(EXACTCCD_PYTHON_SKIPPED "")

if(DEFINED EXACTCCD_BUILD_PYTHON AND NOT EXACTCCD_BUILD_PYTHON)
  message(STATUS "exactccd: the Python module is not built (EXACTCCD_BUILD_PYTHON is OFF)")
  return()  # search nothing
endif()
if(NOT PROJECT_IS_TOP_LEVEL AND NOT EXACTCCD_BUILD_PYTHON)
  # Pulled in by a parent project: search nothing (the parent's own Python stays its own).
  message(STATUS "exactccd: the Python module is not built: exactccd is not the top-level project (-DEXACTCCD_BUILD_PYTHON=ON builds it)")
  return()
endif()

# The interpreter: the user's Python3_EXECUTABLE when given; otherwise the first `python3` that
# imports numpy, on PATH and then the distribution's /usr/bin/python3. A version manager's shim
# (pyenv, a virtualenv) earlier on PATH often lacks the distribution's numpy and pytest.
if(NOT DEFINED Python3_EXECUTABLE)
  find_program(EXACTCCD_PATH_PYTHON NAMES python3)
  mark_as_advanced(EXACTCCD_PATH_PYTHON)
  foreach(candidate IN ITEMS "${EXACTCCD_PATH_PYTHON}" /usr/bin/python3)
    if(candidate AND EXISTS "${candidate}")
      execute_process(COMMAND "${candidate}" -c "import numpy"
                      RESULT_VARIABLE numpy_missing OUTPUT_QUIET ERROR_QUIET)
      if(numpy_missing EQUAL 0)
        set(Python3_EXECUTABLE "${candidate}" CACHE FILEPATH "The Python interpreter")
        break()
      endif()
    endif()
  endforeach()
endif()

find_package(Python3 3.7 COMPONENTS Interpreter Development.Module)
if(Python3_FOUND)
  find_package(pybind11 2.6 CONFIG QUIET)
endif()

if(NOT Python3_FOUND)
  set(EXACTCCD_PYTHON_SKIPPED "Python 3 with its development files was not found (Debian: python3-dev)")
elseif(NOT pybind11_FOUND)
  set(EXACTCCD_PYTHON_SKIPPED "pybind11 was not found (Debian: pybind11-dev)")
else()
  execute_process(COMMAND "${Python3_EXECUTABLE}" -c "import numpy"
                  RESULT_VARIABLE numpy_missing OUTPUT_QUIET ERROR_QUIET)
  if(NOT numpy_missing EQUAL 0)
    set(EXACTCCD_PYTHON_SKIPPED "${Python3_EXECUTABLE} cannot import numpy (Debian: python3-numpy)")
  endif()
endif()

set(EXACTCCD_PYTHON_MISSING "${EXACTCCD_PYTHON_SKIPPED}")  # what python/ fails on when asked for
if(EXACTCCD_PYTHON_SKIPPED)
  set(EXACTCCD_PYTHON_SKIPPED "the Python module is not built: ${EXACTCCD_PYTHON_SKIPPED}")
elseif(EXACTCCD_SANITIZE OR EXACTCCD_FUZZ)
  set(EXACTCCD_PYTHON_SKIPPED "the Python module is not built in a sanitizer or fuzzing build (-DEXACTCCD_BUILD_PYTHON=ON builds it)")
else()
  set(EXACTCCD_PYTHON_DEFAULT ON)
endif()

if(EXACTCCD_PYTHON_SKIPPED AND NOT DEFINED EXACTCCD_BUILD_PYTHON)
  message(STATUS "exactccd: ${EXACTCCD_PYTHON_SKIPPED}")
endif()
