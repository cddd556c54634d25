// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_BoundarySamples_h
#define labelmesher_BoundarySamples_h

/**
 * @file BoundarySamples.h
 * Where the image says each interface chain's segments should run: the
 * midpoints of the pixel edges between the chain's two materials, each given
 * to the nearest segment of a chain with the same pair of materials. They are
 * the data the fitted curves of BoundaryFit.h approximate. Pixel edges on the
 * image's outer side are left out: the border stays straight.
 */

#include "Curving/ImageOnMesh.h"
#include "Curving/InterfaceChains.h"

#include <cstddef>
#include <vector>

namespace labelmesher
{

struct BoundarySample
{
  std::size_t Segment = 0; ///< segment s of the chain: Vertices[s] → Vertices[s + 1] (cyclic when closed)
  Point2 Point{ 0.0, 0.0 }; ///< in mesh coordinates
  double Parameter = 0.5;  ///< first guess of its curve parameter: projection on the chord, in (0, 1)
};

/// Per chain (same order as `chains`): its samples. A pixel edge is used when
/// a segment with the same materials lies within `reach` voxels of its
/// midpoint and the midpoint projects inside that segment.
std::vector<std::vector<BoundarySample>> CollectBoundarySamples(const SimplexMesh& linear,
  const std::vector<InterfaceChain>& chains, const ImageOnMesh& image, double reach);

} // namespace labelmesher

#endif
