# SPDX-License-Identifier: GPL-2.0-or-later
# Slicer's CMake/SlicerExtensionGenerateConfig.cmake writes <Extension>Config.cmake for extensions
# that depend on this one; none does, so the stand-in only checks what it reads.
if("${EXTENSION_NAME}" STREQUAL "")
  message(FATAL_ERROR "error: EXTENSION_NAME is either NOT defined or empty.")
endif()
