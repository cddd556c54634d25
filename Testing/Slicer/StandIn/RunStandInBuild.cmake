# SPDX-License-Identifier: GPL-2.0-or-later
# ctest slicer.extension_standin_build: configures the stand-in Slicer (this folder), configures
# and builds SlicerModule/'s inner build against it as a Slicer extension build would, installs
# it, then imports `labelmesher` and meshes an image through LabelMesherLib/meshing.py from the
# build tree's and the install tree's qt-scripted-modules folders with Debian's Python.
#   cmake -DSOURCE=<repository> -DWORK=<scratch folder> -DPYTHON=/usr/bin/python3
#         [-DLAUNCHER=ccache] [-DJOBS=1] -P RunStandInBuild.cmake
foreach(var SOURCE WORK PYTHON)
  if(NOT ${var})
    message(FATAL_ERROR "RunStandInBuild.cmake needs -D${var}=...")
  endif()
endforeach()
if(NOT JOBS)
  set(JOBS 1)
endif()
set(launcher)
if(LAUNCHER)
  # ccache: the core's objects are the main build's (same sources, flags and include folders)
  set(launcher -DCMAKE_C_COMPILER_LAUNCHER=${LAUNCHER} -DCMAKE_CXX_COMPILER_LAUNCHER=${LAUNCHER})
endif()

function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "Slicer stand-in: ${what} failed (${result})")
  endif()
endfunction()

set(standin ${WORK}/standin)
set(extension ${WORK}/extension)
set(installed ${WORK}/install)
# A fresh install, and nothing left from an earlier run outside the two build folders.
file(GLOB leftovers LIST_DIRECTORIES true ${WORK}/*)
list(REMOVE_ITEM leftovers ${standin} ${extension})
if(leftovers)
  file(REMOVE_RECURSE ${leftovers})
endif()
run("configuring the stand-in Slicer" ${CMAKE_COMMAND} -S ${SOURCE}/Testing/Slicer/StandIn -B ${standin}
  -G Ninja -DPython3_EXECUTABLE=${PYTHON})
# What the test imports is made anew each run (a file kept from an earlier build must not hide a
# rule that no longer makes it); the libraries are only relinked.
file(REMOVE_RECURSE ${extension}/lib/Slicer-5.8/qt-scripted-modules)
# The inner build, as the superbuild would configure it once p4est and Eigen exist; here they are
# Debian's (no network for the superbuild's downloads).
run("configuring the extension" ${CMAKE_COMMAND} -S ${SOURCE}/SlicerModule -B ${extension} -G Ninja
  -DSlicer_DIR=${standin} -DLabelMesher_SUPERBUILD=OFF ${launcher})
run("building the extension" ${CMAKE_COMMAND} --build ${extension} -j ${JOBS})
# Everything the build makes stays in its build folder (a module folder outside the source folder
# must not put its build folder next to it).
file(GLOB strays LIST_DIRECTORIES true RELATIVE ${WORK} ${WORK}/*)
list(REMOVE_ITEM strays standin extension install)
if(strays)
  message(FATAL_ERROR "Slicer stand-in: the build wrote outside its build folder: ${WORK}/${strays}")
endif()
run("installing the extension" ${CMAKE_COMMAND} --install ${extension} --prefix ${installed})

foreach(tree ${extension} ${installed})
  message(STATUS "Slicer stand-in: meshing with ${tree}/lib/Slicer-5.8/qt-scripted-modules")
  run("meshing from ${tree}" ${CMAKE_COMMAND} -E env
    PYTHONPATH=${tree}/lib/Slicer-5.8/qt-scripted-modules PYTHONDONTWRITEBYTECODE=1
    ${PYTHON} ${SOURCE}/Testing/Slicer/StandIn/mesh_from_extension.py ${tree}/lib/Slicer-5.8/qt-scripted-modules)
endforeach()
