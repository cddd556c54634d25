# SPDX-License-Identifier: GPL-2.0-or-later
# p4est with its libsc (a git submodule of p4est), built WITHOUT MPI: libsc then provides its MPI
# stubs (sc_mpi.h), so nothing starts MPI inside the Slicer process and no MPI library ships with
# the extension. Shared libraries, installed to Slicer_INSTALL_THIRDPARTY_LIB_DIR; the extension's
# package takes them from this project's install (CPACK_INSTALL_CMAKE_PROJECTS, CMakeLists.txt).
# Follows Slicer's Utilities/Templates/Extensions/SuperBuild/SuperBuild/External_Foo.cmake.

set(proj p4est)

# Set dependency list
set(${proj}_DEPENDS
  ""
  )

# Include dependent projects if any
ExternalProject_Include_Dependencies(${proj} PROJECT_VAR proj)

if(${SUPERBUILD_TOPLEVEL_PROJECT}_USE_SYSTEM_${proj})
  message(FATAL_ERROR "Enabling ${SUPERBUILD_TOPLEVEL_PROJECT}_USE_SYSTEM_${proj} is not supported !")
endif()

# Sanity checks
if(DEFINED p4est_DIR AND NOT EXISTS ${p4est_DIR})
  message(FATAL_ERROR "p4est_DIR [${p4est_DIR}] variable is defined but corresponds to nonexistent directory")
endif()

if(NOT DEFINED ${proj}_DIR AND NOT ${SUPERBUILD_TOPLEVEL_PROJECT}_USE_SYSTEM_${proj})

  ExternalProject_SetIfNotDefined(
    ${SUPERBUILD_TOPLEVEL_PROJECT}_${proj}_GIT_REPOSITORY
    "https://github.com/cburstedde/p4est.git"
    QUIET
    )

  # v2.8.7, the first release whose CMake build this follows (libsc option SC_ENABLE_MPI)
  ExternalProject_SetIfNotDefined(
    ${SUPERBUILD_TOPLEVEL_PROJECT}_${proj}_GIT_TAG
    "2296a990d8b6b54731a63be0ba5bc17b08cd1f3d"
    QUIET
    )

  set(EP_SOURCE_DIR ${CMAKE_BINARY_DIR}/${proj})
  set(EP_BINARY_DIR ${CMAKE_BINARY_DIR}/${proj}-build)
  set(EP_INSTALL_DIR ${CMAKE_BINARY_DIR}/${proj}-install)

  ExternalProject_Add(${proj}
    ${${proj}_EP_ARGS}
    GIT_REPOSITORY "${${SUPERBUILD_TOPLEVEL_PROJECT}_${proj}_GIT_REPOSITORY}"
    GIT_TAG "${${SUPERBUILD_TOPLEVEL_PROJECT}_${proj}_GIT_TAG}"
    GIT_SUBMODULES sc
    SOURCE_DIR ${EP_SOURCE_DIR}
    BINARY_DIR ${EP_BINARY_DIR}
    INSTALL_DIR ${EP_INSTALL_DIR}
    CMAKE_CACHE_ARGS
      # Compiler settings
      -DCMAKE_C_COMPILER:FILEPATH=${CMAKE_C_COMPILER}
      -DCMAKE_C_FLAGS:STRING=${ep_common_c_flags}
      -DCMAKE_CXX_COMPILER:FILEPATH=${CMAKE_CXX_COMPILER}
      -DCMAKE_CXX_FLAGS:STRING=${ep_common_cxx_flags}
      -DCMAKE_BUILD_TYPE:STRING=${CMAKE_BUILD_TYPE}
      # Install directories: libraries where an extension's third-party libraries go
      -DCMAKE_INSTALL_PREFIX:PATH=${EP_INSTALL_DIR}
      -DCMAKE_INSTALL_LIBDIR:STRING=${Slicer_INSTALL_THIRDPARTY_LIB_DIR}
      -DCMAKE_INSTALL_BINDIR:STRING=${Slicer_INSTALL_THIRDPARTY_BIN_DIR}
      # Options: no MPI (libsc's stubs), shared, no tests or examples
      -DSC_ENABLE_MPI:BOOL=OFF
      -Dmpi:BOOL=OFF
      -DBUILD_SHARED_LIBS:BOOL=ON
      -DSC_BUILD_SHARED_LIBS:BOOL=ON
      -DP4EST_BUILD_TESTING:BOOL=OFF
      -DP4EST_BUILD_EXAMPLES:BOOL=OFF
      -DSC_BUILD_TESTING:BOOL=OFF
      -DSC_BUILD_EXAMPLES:BOOL=OFF
      -DBUILD_TESTING:BOOL=OFF
    DEPENDS
      ${${proj}_DEPENDS}
    )
  set(${proj}_DIR ${EP_BINARY_DIR})
  # p4est and libsc install their CMake packages to <prefix>/cmake
  set(P4EST_DIR ${EP_INSTALL_DIR}/cmake)
  set(SC_DIR ${EP_INSTALL_DIR}/cmake)

else()
  ExternalProject_Add_Empty(${proj} DEPENDS ${${proj}_DEPENDS})
endif()

mark_as_superbuild(${proj}_DIR:PATH)
mark_as_superbuild(VARS P4EST_DIR:PATH SC_DIR:PATH)
