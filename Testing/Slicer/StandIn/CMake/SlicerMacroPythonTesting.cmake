# SPDX-License-Identifier: GPL-2.0-or-later
# Slicer's CMake/SlicerMacroPythonTesting.cmake: slicer_add_python_unittest runs a module's
# unittest inside the Slicer application (its launcher). There is no Slicer here: the test is
# not added, and the configure says so.
function(slicer_add_python_unittest)
  cmake_parse_arguments(MY "" "SCRIPT;TESTNAME_PREFIX" "SLICER_ARGS" ${ARGN})
  message(STATUS "Slicer stand-in: not adding Slicer's in-application test of ${MY_SCRIPT}")
endfunction()
