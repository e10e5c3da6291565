# ctest python_install_test: `cmake --install` of the python component into a fresh prefix, then
# the installed package (and only it: PYTHONPATH is the prefix's site directory) decides a query.
#   cmake -DBUILD_DIR=... -DPREFIX=... -DINSTALL_DIR=... -DPYTHON=... -P install_test.cmake
file(REMOVE_RECURSE "${PREFIX}")
execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --component python
                        --prefix "${PREFIX}"
                RESULT_VARIABLE status OUTPUT_QUIET)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "cmake --install failed (${status})")
endif()
if(IS_ABSOLUTE "${INSTALL_DIR}")
  set(site "${INSTALL_DIR}")
else()
  set(site "${PREFIX}/${INSTALL_DIR}")
endif()
set(check [=[
import pathlib, sys
import numpy as np
import exactccd, exactccd.dask
site = pathlib.Path(sys.argv[1]).resolve()
assert site in pathlib.Path(exactccd.__file__).resolve().parents, exactccd.__file__
tri = [[0, 0, 0], [1, 0, 0], [0, 1, 0]]
r = exactccd.vertex_face_ccd([0.25, 0.25, 1], *tri, [0.25, 0.25, -3], *tri)
assert r.collides and r.toi_lo == r.toi_hi == 0.25, r
b = exactccd.vertex_face_ccd_batch(np.array([[[0.25, 0.25, 1], *tri, [0.25, 0.25, -3], *tri]] * 100), threads=2)
assert b.collides.all() and (b.toi_lo == 0.25).all()
print("installed exactccd", exactccd.__version__, "at", exactccd.__file__)
]=])
execute_process(COMMAND "${CMAKE_COMMAND}" -E env "PYTHONPATH=${site}" PYTHONDONTWRITEBYTECODE=1
                        "${PYTHON}" -c "${check}" "${site}"
                WORKING_DIRECTORY "${PREFIX}"
                RESULT_VARIABLE status)
file(REMOVE_RECURSE "${PREFIX}")
if(NOT status EQUAL 0)
  message(FATAL_ERROR "the installed package failed (${status})")
endif()
