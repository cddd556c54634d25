// SPDX-License-Identifier: GPL-2.0-or-later
// Fills one octree leaf with tetrahedra (triangles in 2D) from its face stencils (Algorithm 3).
#include "Fill/LeafFill.h"

#include "Fill/FaceTriangulation.h"
#include "Octree/LatticeLabels.h"

#include <stdexcept>

namespace labelmesher
{
namespace
{

/// Doubled-lattice point of the leaf at `half` steps (halves of the leaf side).
LatticePoint LeafLattice(const LeafBox& leaf, int hx, int hy, int hz)
{
  const std::int64_t s = leaf.Size;
  return { leaf.Low(0) + hx * s, leaf.Low(1) + hy * s, leaf.Low(2) + hz * s };
}

/// The label of a labelled (non-0) corner of a proper leaf.
std::int32_t LabelOf(const OctreeLeaf& leaf, const CornerSigns& signs, int corner)
{
  if (signs[corner] == 0)
    throw std::logic_error("a cell takes its material from a 0-corner");
  return signs[corner] > 0 ? leaf.First : leaf.Second;
}

void FillSquare(const OctreeLeaf& leaf, const CornerSigns& signs, MeshAssembler& mesh)
{
  const LeafBox& box = leaf.Box;
  auto corner = [&](int c) { return LeafLattice(box, 2 * (c & 1), 2 * ((c >> 1) & 1), 0); };
  const bool proper = leaf.IsProper();
  auto hasMidpoint = [&](int face) {
    const int axis = face / 2, side = face % 2, other = 1 - axis;
    const int c0 = side << axis, c1 = c0 | (1 << other);
    const bool hanging = (leaf.EdgeMidpoints >> face) & 1u;
    if (proper && hanging && signs[c0] * signs[c1] <= 0)
      throw std::logic_error("a finer leaf meets a rigid side; the octree rules exclude this");
    return hanging || (proper && signs[c0] * signs[c1] < 0);
  };
  bool any = false;
  for (int f = 0; f < 4; ++f)
    any = any || hasMidpoint(f);
  if (!any && !proper)
  {
    mesh.AddCell({ corner(0), corner(1), corner(3), {} }, leaf.First);
    mesh.AddCell({ corner(0), corner(3), corner(2), {} }, leaf.First);
    return;
  }
  // Counter-clockwise ring: corners and the midpoints of sides y=0, x=1, y=1, x=0.
  struct RingPoint
  {
    LatticePoint Point;
    int Corner;
  };
  std::vector<RingPoint> ring;
  const int ringCorners[4] = { 0, 1, 3, 2 }, ringFaces[4] = { 2, 1, 3, 0 };
  const int midpointHalves[4][2] = { { 1, 0 }, { 2, 1 }, { 1, 2 }, { 0, 1 } };
  for (int i = 0; i < 4; ++i)
  {
    ring.push_back({ corner(ringCorners[i]), ringCorners[i] });
    if (hasMidpoint(ringFaces[i]))
      ring.push_back({ LeafLattice(box, midpointHalves[i][0], midpointHalves[i][1], 0), -1 });
  }
  const LatticePoint centre = LeafLattice(box, 1, 1, 0);
  for (std::size_t i = 0; i < ring.size(); ++i)
  {
    const RingPoint& p = ring[i];
    const RingPoint& q = ring[(i + 1) % ring.size()];
    // Its material: a labelled corner among its two ring points (a midpoint
    // sits between corners of both labels; 0-corners are never adjacent).
    const int c = (p.Corner >= 0 && (!proper || signs[p.Corner] != 0)) ? p.Corner : q.Corner;
    mesh.AddCell({ centre, p.Point, q.Point, {} }, proper ? LabelOf(leaf, signs, c) : leaf.First);
  }
}

void FillCube(const OctreeLeaf& leaf, const CornerSigns& signs, MeshAssembler& mesh)
{
  const LeafBox& box = leaf.Box;
  const bool proper = leaf.IsProper();
  if (!proper && leaf.EdgeMidpoints == 0 && leaf.SplitFaces == 0)
  {
    // Six tetrahedra around the diagonal from corner 0 to corner 7 (Kuhn).
    auto corner = [&](int c) { return LeafLattice(box, 2 * (c & 1), 2 * ((c >> 1) & 1), 2 * ((c >> 2) & 1)); };
    const int permutations[6][3] = { { 0, 1, 2 }, { 0, 2, 1 }, { 1, 0, 2 }, { 1, 2, 0 }, { 2, 0, 1 }, { 2, 1, 0 } };
    for (const auto& p : permutations)
    {
      const int a = 1 << p[0], ab = a | (1 << p[1]);
      mesh.AddCell({ corner(0), corner(a), corner(ab), corner(7) }, leaf.First);
    }
    return;
  }
  const LatticePoint centre = LeafLattice(box, 1, 1, 1);
  for (int face = 0; face < 6; ++face)
  {
    const int axis = face / 2, side = face % 2;
    const auto others = OtherAxes(axis);
    unsigned midpointMask = 0;
    for (int e = 0; e < 4; ++e)
      if ((leaf.EdgeMidpoints >> FaceEdgeToCube(face, e)) & 1u)
        midpointMask |= 1u << e;
    const bool split = (leaf.SplitFaces >> face) & 1u;
    unsigned negative = 0, zero = 0;
    int labelledCorner = -1;
    for (int q = 0; q < 4; ++q)
    {
      const int sign = signs[FaceCornerToCube(face, q)];
      negative |= (sign < 0 ? 1u : 0u) << q;
      zero |= (sign == 0 ? 1u : 0u) << q;
      if (sign != 0 && labelledCorner < 0)
        labelledCorner = q;
    }

    FaceKind kind = split ? FaceKind::Split : (midpointMask ? FaceKind::Fan : FaceKind::Plain);
    if (proper && IsCrossedFace(negative, zero))
      kind = FaceKind::Crossed;
    if (kind == FaceKind::Crossed && (split || midpointMask))
      throw std::logic_error("a finer leaf meets a crossed face; the octree rules exclude this");
    if (proper && labelledCorner < 0)
      throw std::logic_error("a proper boundary leaf with a face of 0-corners only");
    const std::int64_t extent = box.Extent();
    for (const FaceTriangle& t : TriangulateFace(kind, midpointMask, negative, zero))
    {
      std::array<LatticePoint, 4> cell;
      for (int i = 0; i < 3; ++i)
      {
        LatticePoint p;
        p[axis] = box.Low(axis) + side * extent;
        p[others[0]] = box.Low(others[0]) + t.Points[i].A * extent / 4;
        p[others[1]] = box.Low(others[1]) + t.Points[i].B * extent / 4;
        cell[i] = p;
      }
      cell[3] = centre;
      // Crossed faces name the labelled corner of each triangle's side; the
      // other faces lie on one side, that of any labelled corner.
      const int q = kind == FaceKind::Crossed ? t.SideCorner : labelledCorner;
      mesh.AddCell(cell, proper ? LabelOf(leaf, signs, FaceCornerToCube(face, q)) : leaf.First);
    }
  }
}

} // namespace

void FillLeaf(const LabelImage& image, const OctreeLeaf& leaf, MeshAssembler& mesh)
{
  const CornerSigns signs =
    leaf.IsProper() ? LeafCornerSigns(image, leaf.Box, leaf.First, leaf.Second) : CornerSigns{};
  if (leaf.Box.Dimension == 2)
    FillSquare(leaf, signs, mesh);
  else
    FillCube(leaf, signs, mesh);
}

} // namespace labelmesher
