// SPDX-License-Identifier: GPL-2.0-or-later
// The octree (p8est) instance of the forest code; see OctreeRefinementForest.h.
#include <p4est_to_p8est.h>
#include <p8est_bits.h>
#include <p8est_extended.h>
#include <p8est_iterate.h>

#include <memory>
#include <string>

#include "Octree/OctreeRefinementForest.h"

namespace labelmesher
{
namespace detail
{
std::vector<OctreeLeaf> BuildForest3(
  int depth, const LeafEvaluator& evaluate, const ProgressObserver& observer, double start, double end)
{
  return BuildForest(depth, evaluate, observer, start, end);
}
} // namespace detail
} // namespace labelmesher
