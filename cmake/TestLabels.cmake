# ctest labels and timeouts. Every test is `fast` or `slow`: slow are the programs that run for
# more than about 20 s in a Release build on 2 cores. The developer loop skips them:
#   ctest --test-dir build -L fast -j2
# The timeouts are generous for a Release build, so that the same values serve the sanitizer
# build at its reduced EXACTCCD_TEST_SCALE (.ci/sanitizers.sh) on a busy machine.

set(EXACTCCD_FAST_TEST_TIMEOUT 300)   # seconds
set(EXACTCCD_SLOW_TEST_TIMEOUT 1500)

# Labels `fast`, with the fast timeout, every test of the calling directory that has no label
# yet (add_test tests; GoogleTest programs get theirs through gtest_discover_tests). Call it
# deferred, so that it sees the tests added after the call:
#   cmake_language(DEFER CALL exactccd_label_unlabelled_tests)
function(exactccd_label_unlabelled_tests)
  get_directory_property(tests TESTS)
  foreach(test IN LISTS tests)
    get_test_property(${test} LABELS labels)
    if(NOT labels)
      set_tests_properties(${test} PROPERTIES LABELS fast)
    endif()
    get_test_property(${test} TIMEOUT timeout)
    if(NOT timeout)
      set_tests_properties(${test} PROPERTIES TIMEOUT ${EXACTCCD_FAST_TEST_TIMEOUT})
    endif()
  endforeach()
endfunction()
