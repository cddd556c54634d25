// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_MesherParameters_h
#define labelmesher_MesherParameters_h

/**
 * @file MesherParameters.h
 * What the user asks of the initial mesh (Algorithm 1's inputs h1, h2). The
 * angle is not a parameter here: the initial mesh's bound (30 degrees in 3D,
 * 45 in 2D) follows from the octree rules and the face tables and is proved
 * by enumeration (Testing/Cxx/Fill/TestAngleBoundEnumeration.cxx); the decimator
 * takes the user's angle (Decimation/DecimationParameters.h).
 *
 * Distances are in voxels of the image as meshed (index space: the smallest
 * spacing after resampling an anisotropic image, LabelImage.h).
 */

namespace labelmesher
{

struct MesherParameters
{
  /// h(I, M), section 2.2: every point of the image boundary lies within this
  /// distance of the mesh boundary, overall and per material. Voxels, >= 0
  /// (0: the mesh boundary covers the image boundary exactly); default 2.
  double ImageToMeshDistance = 2.0;
  /// h(M, I): every point of the mesh boundary between materials a and b lies
  /// within this distance of the image boundary between a and b. Voxels, >= 0;
  /// default 2.
  double MeshToImageDistance = 2.0;
};

} // namespace labelmesher

#endif
