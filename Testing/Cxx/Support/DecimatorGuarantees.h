// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_testing_DecimatorGuarantees_h
#define labelmesher_testing_DecimatorGuarantees_h

/**
 * @file DecimatorGuarantees.h
 * Every guarantee of the decimated mesh on one image: mesher then decimator
 * (Decimation/MeshDecimator.h), then the same measured guarantees as the
 * initial mesh (MeshGuarantees.h) with the decimator's angle bound. Shared by
 * the decimator's property tests and labelmesher_property_scan --decimate.
 */

#include "Decimation/MeshDecimator.h"
#include "LabelOctreeMesher.h"
#include "Streaming/StreamedPipeline.h"

#include <cstdint>
#include <string>
#include <vector>

namespace labelmesher
{
namespace testing
{

/// The decimation a property test uses for `seed`: the distances of
/// `mesher` (DrawDistanceBounds) and an angle drawn from {5, 10, 15, 19.47,
/// the proven bound (30 in 3D, 45 in 2D)}.
DecimationParameters DrawDecimationParameters(std::uint64_t seed, int dimension, const MesherParameters& mesher);

/// Meshes and decimates `image`; one line per violated guarantee (empty: all
/// hold). A thrown exception counts as a violation. `counts`, when given,
/// receives the decimator's counts.
std::vector<std::string> ViolatedDecimatorGuarantees(const LabelImage& image, const MesherParameters& mesher,
  const DecimationParameters& decimation, DecimationCounts* counts = nullptr);

/// The same through the block-streamed pipeline (StreamedPipeline.h) with
/// `streaming`'s blocks; `streamed`, when given, receives its counts.
std::vector<std::string> ViolatedStreamedGuarantees(const LabelImage& image, const MesherParameters& mesher,
  const DecimationParameters& decimation, const StreamingParameters& streaming, DecimationCounts* counts = nullptr,
  StreamingCounts* streamed = nullptr);

} // namespace testing
} // namespace labelmesher

#endif
