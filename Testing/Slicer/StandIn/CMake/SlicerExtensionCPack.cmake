# SPDX-License-Identifier: GPL-2.0-or-later
# Follows the sanity checks of Slicer's CMake/SlicerExtensionCPack.cmake; the packaging itself
# (CPack, fixup of the bundle) is not emulated.
foreach(var EXTENSION_NAME Slicer_REVISION Slicer_OS Slicer_ARCHITECTURE)
  if("${${var}}" STREQUAL "")
    message(FATAL_ERROR "error: ${var} is either NOT defined or empty.")
  endif()
endforeach()
foreach(var EXTENSION_README_FILE EXTENSION_LICENSE_FILE)
  if(NOT EXISTS ${${var}})
    message(FATAL_ERROR "error: ${var} points to an inexistent file: ${${var}}")
  endif()
endforeach()
# A SuperBuild extension (one that defines <Extension>_SUPERBUILD) must say what to package.
if(DEFINED ${EXTENSION_NAME}_SUPERBUILD AND "${CPACK_INSTALL_CMAKE_PROJECTS}" STREQUAL "")
  message(FATAL_ERROR "${EXTENSION_NAME}: Variable CPACK_INSTALL_CMAKE_PROJECTS is expected to be set.")
endif()
