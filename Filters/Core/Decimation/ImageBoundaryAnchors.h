// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_ImageBoundaryAnchors_h
#define labelmesher_ImageBoundaryAnchors_h

/**
 * @file ImageBoundaryAnchors.h
 * The h(I, M) half of requirement 2 of section 3.1.3, kept local as the
 * dissertation suggests ("for each boundary face we maintain a cumulative
 * list of the image boundary vertices ... reassigned after each merge"), but
 * for whole image faces instead of their vertices, so that nothing is
 * sampled: every side m (m != 0) of every image face F carries a certificate
 * (an anchor) that F lies within h of the mesh boundary of m:
 *
 *  - a mesh face that separates m and lies within h of every corner of F
 *    (distance to a convex face is convex, so then all of F is within h);
 *  - or a vertex v: F is within h of the union of the faces around v that
 *    separate m (DistanceBound's exact test), needed where h is below a
 *    voxel's half diagonal;
 *  - or, for the few faces that no single star certifies, the faces found at
 *    the start, whose vertices are then frozen so that they never change.
 *
 * A merge of a into b changes exactly the faces that contain a, and the stars
 * of b and of a's neighbours; the certificates that lean on them are re-made
 * from the faces around b after the merge, or the merge is refused.
 * Certificates stay valid otherwise: faces that do not contain a keep their
 * place and, by the topology check's commutation, their labels.
 */

#include "Decimation/EdgeCollapse.h"
#include "Decimation/ImageBoundary.h"

#include <array>
#include <cstdint>
#include <vector>

namespace labelmesher
{

class ImageBoundaryAnchors
{
public:
  ImageBoundaryAnchors(const ImageBoundary& boundary, double imageToMesh);

  /// Certifies every image face side on `mesh`, whose interface faces are
  /// `faces` (EditableMesh::InterfaceFaces), in parallel. Vertices that must
  /// never move are set in `frozen`. Throws std::invalid_argument when some
  /// image face is farther than the bound from the mesh boundary.
  /// `imageFaces` (per ImageBoundary face), when given, limits this to the
  /// flagged faces: the others are neither certified nor guarded, and the
  /// caller must keep every mesh face near them as it is (a block of the
  /// streamed pipeline freezes them, Streaming/StreamedPipeline.h).
  /// `uncertified` (per ImageBoundary face), when given, receives the faces
  /// with a side that no face of `mesh` certifies, instead of the exception:
  /// the caller must then keep every mesh face near them as it is.
  void Initialize(const EditableMesh& mesh, const std::vector<InterfaceFace>& faces, std::vector<std::uint8_t>& frozen,
    const std::vector<std::uint8_t>* imageFaces = nullptr, std::vector<std::uint8_t>* uncertified = nullptr);

  struct Update
  {
    std::int32_t Item;
    std::array<VertexId, 3> Anchor;
  };
  /// Re-certifies, against the faces around b after the merge, every side
  /// whose certificate the merge invalidates; false if one cannot be.
  /// Thread-safe for merges in disjoint regions (reads only what the merge's
  /// vertices own).
  bool Recertify(const EditableMesh& mesh, const EdgeCollapse& merge, std::vector<Update>& updates) const;
  /// Records the new certificates of an applied merge.
  void Commit(const EdgeCollapse& merge, const std::vector<Update>& updates);

  std::size_t NumberOfSides() const { return ItemFace.size(); }
  /// While regions run at once, registrations are not pruned: pruning reads
  /// certificates that another region may be rewriting.
  void SetShared(bool shared) { Shared = shared; }

private:
  static constexpr VertexId kStar = -2;   ///< Anchor {v, kStar, kStar}: the star of v
  static constexpr VertexId kPinned = -3; ///< Anchor {kPinned, ...}: frozen faces
  bool IsStar(const std::array<VertexId, 3>& anchor) const { return anchor[1] == kStar; }
  bool Mentions(std::int32_t item, VertexId v) const;
  void Register(std::int32_t item, VertexId v);
  /// A certificate for `item` among `faces` (those separating its side), or
  /// an anchor with Anchor[0] == -1 if there is none.
  std::array<VertexId, 3> Certify(const EditableMesh& mesh, std::int32_t item,
    const std::vector<InterfaceFace>& faces, VertexId starVertex, std::vector<ConvexPiece>& scratch) const;

  const ImageBoundary& Boundary;
  double H;
  int Dimension = 3;
  std::vector<std::int32_t> ItemFace, ItemSide;
  std::vector<std::array<VertexId, 3>> Anchor;
  std::vector<std::vector<std::int32_t>> ItemsAt; ///< per vertex; entries may be stale (Mentions decides)
  std::vector<std::uint32_t> PrunedSize;
  std::vector<std::uint32_t> StarAnchors; ///< per vertex: star certificates that rest on it
  bool Shared = false;
};

/// The mesh face `face` in index space.
ConvexPiece MeshFacePiece(const EditableMesh& mesh, const std::array<VertexId, 3>& face);

} // namespace labelmesher

#endif
