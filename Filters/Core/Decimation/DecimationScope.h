// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_DecimationScope_h
#define labelmesher_DecimationScope_h

/**
 * @file DecimationScope.h
 * The decimation of section 3.1.3 on an EditableMesh in place, limited to a
 * scope: the unit the block-streamed pipeline (Streaming/StreamedPipeline.h)
 * runs on each block and then on the assembled mesh. DecimateMesh is this
 * with the whole mesh in scope.
 */

#include "Decimation/DecimationParameters.h"
#include "Decimation/EditableMesh.h"
#include "Decimation/ImageBoundary.h"
#include "Decimation/MeshDecimator.h"
#include "Support/ProgressObserver.h"
#include "Support/StageClock.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace labelmesher
{

struct DecimationScope
{
  /// Per image boundary face (ImageBoundary::Faces' order): the faces whose
  /// h(I,M) this run certifies and keeps; null: all. The caller keeps every
  /// mesh face near the others as it is (frozen).
  const std::vector<std::uint8_t>* ImageFaces = nullptr;
  /// Per mesh vertex: may not move or vanish (a piece's border vertices are
  /// frozen besides); empty: none. On return: every vertex the run froze
  /// (these, the border's, the certificates' and FreezeNear's).
  std::vector<std::uint8_t> Frozen;
  /// With ImageFaces: called once the certificates are made, before any
  /// merge, with the image faces (per ImageBoundary face) of which some side
  /// found no certificate in this mesh; it must freeze (set in `frozen`) at least the vertices of every
  /// interface face of their sides within h(I,M) of them. Null: such a face is an error, the
  /// input breaks h(I,M).
  std::function<void(const EditableMesh& mesh, const std::vector<std::uint8_t>& uncertified,
    std::vector<std::uint8_t>& frozen)>
    FreezeNear;
  /// The mesh is what earlier passes of this run left, each of which kept
  /// every bound: the setup skips re-checking that it covers the image, its
  /// angles and h(M,I) (not the certificates of h(I,M), which it makes). Only
  /// for a pass that a later pass over the same faces follows, whose setup
  /// re-checks them (the streamed pipeline's border passes and joins, before
  /// its last pass).
  bool InputKept = false;
  /// Per mesh vertex: offered in the first pass (relocation then tries every
  /// vertex, and re-offers what it moves); empty: every vertex.
  std::vector<std::uint8_t> Offered;
};

/// Decimates `mesh` (of `image`, whose boundary is `boundary`) in place within
/// `scope`: checks that it covers the image with no angle below the bound and
/// that its interface faces hold h(M,I) (neither with scope.InputKept),
/// certifies h(I,M) (throwing std::invalid_argument when the input breaks a
/// bound), merges in RegionScheduler's runs, then the rounds of
/// relocation. Counts are added to `counts`, stage times to `clock`, progress
/// spans [start, start + share]; throws AbortRequested when `observer` says stop.
void DecimateInScope(const LabelImage& image, const ImageBoundary& boundary, EditableMesh& mesh, const DecimationParameters& parameters,
  DecimationScope& scope, const ProgressObserver& observer, double start, double share,
  DecimationCounts& counts, StageClock& clock);

/// `result`'s mesh, interfaces and final counts, from the decimated `mesh`.
void FinishDecimation(const EditableMesh& mesh, DecimationResult& result);

} // namespace labelmesher

#endif
