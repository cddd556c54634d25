// SPDX-License-Identifier: GPL-2.0-or-later
// libFuzzer target: the mesher (and, when asked, the decimator) on small images decoded from the
// bytes, every guarantee asserted on every mesh (MesherGuarantees.h, DecimatorGuarantees.h: the
// property tests' own checks):
//   byte 0: dimension (even: 2, odd: 3); bytes 1-3: sizes, clamped to [2, 10] in 3D, [2, 24] in
//   2D; byte 4: distance bounds in half voxels, h(I,M) = (high nibble % 7) / 2, h(M,I) = (low
//   nibble % 7) / 2; byte 5: bit 7 decimates, bits 0-2 pick the angle bound (5, 10, 15, 19.47 or
//   the proven one); then one byte per voxel, label = byte % 4 (missing bytes: 0).
// A violated guarantee is a finding (abort, so libFuzzer keeps the input).
#include "DecimatorGuarantees.h"
#include "MesherGuarantees.h"
#include "MPIStartup.h"
#include "Octree/OctreeRefinement.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

using namespace labelmesher;

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
  // MPI (p4est's) starts once, before the first input: what it keeps is not the input's leak.
  StartMPI(); // the application's start-up (Filters/MPIStartup.h); the core starts nothing
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  if (size < 6)
    return 0;
  const int dimension = data[0] % 2 == 0 ? 2 : 3;
  const int largest = dimension == 3 ? 10 : 24;
  const int nx = std::clamp<int>(data[1], 2, largest), ny = std::clamp<int>(data[2], 2, largest);
  const int nz = dimension == 3 ? std::clamp<int>(data[3], 2, largest) : 1;
  LabelImage image(nx, ny, nz);
  bool foreground = false;
  for (std::size_t v = 0; v < image.NumberOfVoxels(); ++v)
  {
    image.SetLabel(v, 6 + v < size ? data[6 + v] % 4 : 0);
    foreground = foreground || image.Label(v) != 0;
  }
  if (!foreground)
    return 0; // refused by design (the mesher's input checks), not a guarantee
  MesherParameters mesher;
  mesher.ImageToMeshDistance = ((data[4] >> 4) % 7) / 2.0;
  mesher.MeshToImageDistance = ((data[4] & 15) % 7) / 2.0;
  std::vector<std::string> problems;
  if (data[5] & 0x80)
  {
    const double angles[] = { 5.0, 10.0, 15.0, 19.47,
      dimension == 3 ? testing::kProvenDihedralBound : testing::kProvenPlanarBound };
    DecimationParameters decimation;
    decimation.ImageToMeshDistance = mesher.ImageToMeshDistance;
    decimation.MeshToImageDistance = mesher.MeshToImageDistance;
    decimation.MinimumAngle = angles[(data[5] & 7) % 5];
    problems = testing::ViolatedDecimatorGuarantees(image, mesher, decimation);
  }
  else
  {
    problems = testing::ViolatedMesherGuarantees(image, mesher);
  }
  if (!problems.empty())
  {
    std::fprintf(stderr, "fuzz finding: %zu violated guarantees (%dD %dx%dx%d, h(I,M) <= %g, h(M,I) <= %g)\n",
      problems.size(), dimension, nx, ny, nz, mesher.ImageToMeshDistance, mesher.MeshToImageDistance);
    for (const std::string& p : problems)
      std::fprintf(stderr, "  %s\n", p.c_str());
    std::abort();
  }
  return 0;
}
