# SPDX-License-Identifier: GPL-2.0-or-later
# What the VTK-free core (Filters/Core) needs, found the same way by the main
# build and by the ParaView plugin's own configure: p4est with the MPI it is
# built against (Debian ships no CMake or pkg-config file for p4est, so the
# imported target LabelMesher::p4est is made here) and Eigen 3.4 (CONFIG mode:
# VTK and ParaView ship their own FindEigen3).
find_package(MPI REQUIRED COMPONENTS C)
find_path(P4EST_INCLUDE_DIR p8est.h PATH_SUFFIXES p4est REQUIRED)
find_library(P4EST_LIBRARY p4est REQUIRED)
find_library(SC_LIBRARY sc REQUIRED)
add_library(LabelMesher::p4est INTERFACE IMPORTED)
target_include_directories(LabelMesher::p4est INTERFACE ${P4EST_INCLUDE_DIR})
target_link_libraries(LabelMesher::p4est INTERFACE ${P4EST_LIBRARY} ${SC_LIBRARY} MPI::MPI_C)

find_package(Eigen3 3.4 REQUIRED CONFIG)
