# SPDX-License-Identifier: GPL-2.0-or-later
# What the core (Filters/Core) needs inside the extension: the target LabelMesher::p4est, as
# Resources/CMake/CoreDependencies.cmake makes it for the main build, and Eigen 3.4.
# - From the superbuild (SuperBuild/External_p4est.cmake): p4est's CMake package, P4EST_DIR, built
#   without MPI (libsc's stubs), so no MPI is linked and none is started inside Slicer.
# - Otherwise (the stand-in test, a developer's machine): a p4est without CMake package, such as
#   Debian's, with MPI linked only if its libsc was built with MPI (sc_config.h says so).
find_package(P4EST CONFIG QUIET)
add_library(LabelMesher::p4est INTERFACE IMPORTED)
if(P4EST_FOUND)
  target_link_libraries(LabelMesher::p4est INTERFACE P4EST::P4EST SC::SC)
  set(labelmesher_p4est_uses_mpi ${P4EST_ENABLE_MPI})
else()
  find_path(P4EST_INCLUDE_DIR p8est.h PATH_SUFFIXES p4est REQUIRED)
  find_library(P4EST_LIBRARY p4est REQUIRED)
  find_library(SC_LIBRARY sc REQUIRED)
  target_include_directories(LabelMesher::p4est INTERFACE ${P4EST_INCLUDE_DIR})
  target_link_libraries(LabelMesher::p4est INTERFACE ${P4EST_LIBRARY} ${SC_LIBRARY})
  file(STRINGS ${P4EST_INCLUDE_DIR}/sc_config.h labelmesher_p4est_uses_mpi REGEX "^#define SC_ENABLE_MPI 1")
endif()
if(labelmesher_p4est_uses_mpi)
  message(STATUS "LabelMesher: p4est was built with MPI; the filters start MPI themselves (fine outside Slicer, not for a Slicer package)")
  find_package(MPI REQUIRED COMPONENTS C)
  target_link_libraries(LabelMesher::p4est INTERFACE MPI::MPI_C)
endif()

find_package(Eigen3 3.4 REQUIRED CONFIG)
