# SPDX-License-Identifier: GPL-2.0-or-later
# The stand-in's Slicer_USE_FILE. Follows Slicer's CMake/UseSlicer.cmake.in (v5.8.1; v5.6.2 is the
# same for these parts), keeping what an extension like SlicerModule/ relies on.

# EXTENSION_NAME defaults to the project's name; Slicer refuses an empty one.
if(NOT DEFINED EXTENSION_NAME)
  set(EXTENSION_NAME ${PROJECT_NAME})
endif()
if("${EXTENSION_NAME}" MATCHES "^$|^Slicer$|^Project$")
  message(FATAL_ERROR "error: Make sure to call 'project(<extension_name>)' or set EXTENSION_NAME prior to call 'include(\${Slicer_USE_FILE})' !")
endif()

# Shared libraries like Slicer's; nothing sets CMAKE_POSITION_INDEPENDENT_CODE (a static library
# linked into a shared one must ask for it itself).
if(NOT DEFINED BUILD_SHARED_LIBS)
  set(BUILD_SHARED_LIBS ${Slicer_BUILD_SHARED})
endif()

# SlicerInitializeBuildType.cmake
if(NOT CMAKE_BUILD_TYPE AND NOT CMAKE_CONFIGURATION_TYPES)
  set(CMAKE_BUILD_TYPE ${Slicer_DEFAULT_BUILD_TYPE} CACHE STRING "Choose the type of build." FORCE)
endif()

include(CMakeParseArguments)
include(ExternalProject)
include(ExternalProjectDependency)      # mark_as_superbuild (stand-in: records nothing)
include(SlicerMacroBuildScriptedModule)
include(SlicerMacroPythonTesting)

# Install folders of an extension package (Slicer_BUNDLE_EXTENSIONS_LOCATION is empty off macOS).
set(Slicer_BUNDLE_EXTENSIONS_LOCATION "")
set(Slicer_INSTALL_QTSCRIPTEDMODULES_BIN_DIR "${Slicer_INSTALL_ROOT}${Slicer_BUNDLE_EXTENSIONS_LOCATION}${Slicer_QTSCRIPTEDMODULES_BIN_DIR}")
set(Slicer_INSTALL_QTSCRIPTEDMODULES_LIB_DIR "${Slicer_INSTALL_ROOT}${Slicer_BUNDLE_EXTENSIONS_LOCATION}${Slicer_QTSCRIPTEDMODULES_LIB_DIR}")
set(Slicer_INSTALL_QTSCRIPTEDMODULES_SHARE_DIR "${Slicer_INSTALL_ROOT}${Slicer_BUNDLE_EXTENSIONS_LOCATION}${Slicer_QTSCRIPTEDMODULES_SHARE_DIR}")
set(Slicer_INSTALL_THIRDPARTY_BIN_DIR "${Slicer_INSTALL_ROOT}${Slicer_BUNDLE_EXTENSIONS_LOCATION}${Slicer_THIRDPARTY_BIN_DIR}")
set(Slicer_INSTALL_THIRDPARTY_LIB_DIR "${Slicer_INSTALL_ROOT}${Slicer_BUNDLE_EXTENSIONS_LOCATION}${Slicer_THIRDPARTY_LIB_DIR}")
set(Slicer_INSTALL_THIRDPARTY_SHARE_DIR "${Slicer_INSTALL_ROOT}${Slicer_BUNDLE_EXTENSIONS_LOCATION}${Slicer_THIRDPARTY_SHARE_DIR}")

# Extension defaults
if(NOT DEFINED EXTENSION_DEPENDS)
  set(EXTENSION_DEPENDS NA)
endif()
if(NOT DEFINED EXTENSION_LICENSE_FILE)
  set(EXTENSION_LICENSE_FILE ${Slicer_LICENSE_FILE})
endif()
if(NOT DEFINED EXTENSION_README_FILE)
  set(EXTENSION_README_FILE ${Slicer_README_FILE})
endif()
if(NOT DEFINED EXTENSION_SOURCE_DIR)
  set(EXTENSION_SOURCE_DIR ${CMAKE_SOURCE_DIR})
endif()
if(NOT DEFINED EXTENSION_SUPERBUILD_BINARY_DIR)
  set(EXTENSION_SUPERBUILD_BINARY_DIR ${CMAKE_BINARY_DIR})
endif()
if(NOT DEFINED EXTENSION_BUILD_SUBDIRECTORY)
  set(EXTENSION_BUILD_SUBDIRECTORY ".")
endif()

# SlicerEnableExtensionTesting: an extension gets CTest (BUILD_TESTING).
include(CTest)
