# SPDX-License-Identifier: GPL-2.0-or-later
# Follows Slicer's CMake/SlicerMacroBuildScriptedModule.cmake, which hands the files to CTK's
# ctkMacroCompilePythonScript (commontk/CTK, CMake/ctkMacroCompilePythonScript.cmake): every script
# and resource is copied, keeping its path below the module folder, into
# <build>/${Slicer_QTSCRIPTEDMODULES_LIB_DIR} (no WITH_SUBDIR) and installed to
# ${Slicer_INSTALL_QTSCRIPTEDMODULES_LIB_DIR}. Left out: CTK's byte-compilation (.pyc) and the
# generic in-application tests (WITH_GENERIC_TESTS), which need Slicer.
macro(slicerMacroBuildScriptedModule)
  cmake_parse_arguments(MY_SLICER "WITH_GENERIC_TESTS;WITH_SUBDIR;VERBOSE" "NAME" "SCRIPTS;RESOURCES" ${ARGN})
  if(MY_SLICER_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "Unknown keywords given to slicerMacroBuildScriptedModule(): \"${MY_SLICER_UNPARSED_ARGUMENTS}\"")
  endif()
  if(NOT Slicer_USE_PYTHONQT)
    message(FATAL_ERROR "Attempting to build the Python scripted module '${MY_SLICER_NAME}' when Slicer_USE_PYTHONQT is OFF")
  endif()
  set(_subdir "")
  if(MY_SLICER_WITH_SUBDIR)
    get_filename_component(_subdir ${CMAKE_CURRENT_SOURCE_DIR} NAME)
    set(_subdir "/${_subdir}")
  endif()
  set(_copied)
  foreach(_file IN LISTS MY_SLICER_SCRIPTS MY_SLICER_RESOURCES)
    if(NOT EXISTS ${CMAKE_CURRENT_SOURCE_DIR}/${_file} AND EXISTS ${CMAKE_CURRENT_SOURCE_DIR}/${_file}.py)
      set(_file ${_file}.py)  # ctkMacroCompilePythonScript accepts scripts without .py
    endif()
    if(NOT EXISTS ${CMAKE_CURRENT_SOURCE_DIR}/${_file})
      message(FATAL_ERROR "slicerMacroBuildScriptedModule given nonexistent file or directory '${_file}'")
    endif()
    set(_to ${CMAKE_BINARY_DIR}/${Slicer_QTSCRIPTEDMODULES_LIB_DIR}${_subdir}/${_file})
    add_custom_command(OUTPUT ${_to}
      COMMAND ${CMAKE_COMMAND} -E copy ${CMAKE_CURRENT_SOURCE_DIR}/${_file} ${_to}
      DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/${_file})
    list(APPEND _copied ${_to})
    get_filename_component(_folder ${_file} DIRECTORY)
    install(FILES ${CMAKE_CURRENT_SOURCE_DIR}/${_file}
      DESTINATION ${Slicer_INSTALL_QTSCRIPTEDMODULES_LIB_DIR}${_subdir}/${_folder} COMPONENT RuntimeLibraries)
  endforeach()
  add_custom_target(Copy${MY_SLICER_NAME}PythonScripts ALL DEPENDS ${_copied})
endmacro()
