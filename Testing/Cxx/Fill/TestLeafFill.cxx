// SPDX-License-Identifier: GPL-2.0-or-later
//
// FillLeaf (Filters/Core/Fill/LeafFill.h) into a MeshAssembler
// (Filters/Core/Fill/MeshAssembler.h), one leaf (or a few neighbours) at a
// time: the number and shape of the cells for each kind of leaf (Kuhn split,
// cone from the centre over fanned, split and crossed faces), the material of
// every cell of a proper leaf against the side of the surface it lies on, and
// in every case positive orientation, an exact tiling of the leaf (volumes
// summing to its volume, sample points in exactly one cell) and the proven
// angle bound (30 degrees dihedral in 3D, 45 degrees planar in 2D), measured
// with Checks/MeshChecks.h.

#include "Checks/MeshChecks.h"
#include "Fill/LeafFill.h"
#include "HandMadeImages.h"
#include "Fill/MeshAssembler.h"
#include "MesherGuarantees.h"
#include "Octree/LeafBox.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <vector>

namespace labelmesher
{
namespace
{

SimplexMesh Fill(const LabelImage& image, const std::vector<OctreeLeaf>& leaves)
{
  MeshAssembler assembler(leaves.front().Box.Dimension);
  for (const OctreeLeaf& leaf : leaves)
    FillLeaf(image, leaf, assembler);
  return assembler.Release();
}

OctreeLeaf Uniform(LeafBox box, std::int32_t label, std::uint16_t midpoints = 0, std::uint8_t split = 0)
{
  OctreeLeaf leaf;
  leaf.Box = box;
  leaf.First = leaf.Second = label;
  leaf.EdgeMidpoints = midpoints;
  leaf.SplitFaces = split;
  return leaf;
}

OctreeLeaf Proper(LeafBox box, std::int32_t first, std::int32_t second)
{
  OctreeLeaf leaf;
  leaf.Box = box;
  leaf.First = first;
  leaf.Second = second;
  return leaf;
}

/// Six times the signed volume of a tetrahedron, twice the signed area of a
/// triangle (exact: the points are on the half-integer lattice).
double Measure(const SimplexMesh& mesh, std::size_t c)
{
  const std::int64_t* v = mesh.Cell(c);
  const Point3 &a = mesh.Points[v[0]], &b = mesh.Points[v[1]], &p = mesh.Points[v[2]];
  const double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] }, w[3] = { p[0] - a[0], p[1] - a[1], p[2] - a[2] };
  if (mesh.Dimension == 2)
    return u[0] * w[1] - u[1] * w[0];
  const Point3& d = mesh.Points[v[3]];
  const double t[3] = { d[0] - a[0], d[1] - a[1], d[2] - a[2] };
  return u[0] * (w[1] * t[2] - w[2] * t[1]) - u[1] * (w[0] * t[2] - w[2] * t[0]) + u[2] * (w[0] * t[1] - w[1] * t[0]);
}

Point3 Centroid(const SimplexMesh& mesh, std::size_t c)
{
  Point3 sum{ 0, 0, 0 };
  for (int i = 0; i < mesh.VerticesPerCell(); ++i)
    for (int a = 0; a < 3; ++a)
      sum[a] += mesh.Points[mesh.Cell(c)[i]][a] / mesh.VerticesPerCell();
  return sum;
}

bool HasVertex(const SimplexMesh& mesh, std::size_t c, const Point3& p)
{
  for (int i = 0; i < mesh.VerticesPerCell(); ++i)
    if (mesh.Points[mesh.Cell(c)[i]] == p)
      return true;
  return false;
}

/// Barycentric containment: +1 strictly inside, 0 outside, -1 too close to
/// the cell's boundary to say.
int Contains(const SimplexMesh& mesh, std::size_t c, const Point3& q)
{
  const int n = mesh.VerticesPerCell();
  SimplexMesh one;
  one.Dimension = mesh.Dimension;
  one.Points.resize(n);
  one.Connectivity.resize(n);
  for (int i = 0; i < n; ++i)
  {
    one.Points[i] = mesh.Points[mesh.Cell(c)[i]];
    one.Connectivity[i] = i;
  }
  one.Materials = { 0 };
  const double whole = Measure(one, 0);
  bool inside = true;
  for (int i = 0; i < n; ++i)
  {
    const Point3 kept = one.Points[i];
    one.Points[i] = q;
    const double part = Measure(one, 0) / whole; // barycentric coordinate i of q
    one.Points[i] = kept;
    if (std::abs(part) < 1e-9)
      return -1;
    inside = inside && part > 0;
  }
  return inside ? 1 : 0;
}

/// The cells tile the box [lo, lo + side]^d: every cell positively oriented
/// and inside the box, measures summing to the box's exactly, and sample
/// points inside the box in exactly one cell each.
void ExpectTiling(const SimplexMesh& mesh, const Point3& lo, double side)
{
  const int d = mesh.Dimension;
  double total = 0.0;
  for (std::size_t c = 0; c < mesh.NumberOfCells(); ++c)
  {
    EXPECT_GT(Measure(mesh, c), 0.0) << "cell " << c;
    total += Measure(mesh, c);
  }
  EXPECT_EQ(total, (d == 2 ? 2.0 : 6.0) * std::pow(side, d)); // d! times the box's measure
  for (const Point3& p : mesh.Points)
    for (int a = 0; a < d; ++a)
    {
      EXPECT_GE(p[a], lo[a]);
      EXPECT_LE(p[a], lo[a] + side);
    }
  const int n = 7;
  int decided = 0, samples = 0;
  for (int k = 0; k < (d == 2 ? 1 : n); ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
      {
        ++samples;
        const Point3 q{ lo[0] + side * (i + 0.37) / n, lo[1] + side * (j + 0.61) / n,
          d == 2 ? 0.0 : lo[2] + side * (k + 0.29) / n };
        int containing = 0;
        bool ambiguous = false;
        for (std::size_t c = 0; c < mesh.NumberOfCells(); ++c)
        {
          const int in = Contains(mesh, c, q);
          ambiguous = ambiguous || in < 0;
          containing += in > 0;
        }
        if (ambiguous)
          continue;
        ++decided;
        EXPECT_EQ(containing, 1) << "sample (" << q[0] << ", " << q[1] << ", " << q[2] << ")";
      }
  EXPECT_GE(decided, samples * 9 / 10);
}

void ExpectAngleBound(const SimplexMesh& mesh)
{
  const QualityReport quality = MeasureQuality(mesh);
  EXPECT_EQ(quality.InvertedCells, 0u);
  const double bound = mesh.Dimension == 3 ? testing::kProvenDihedralBound : testing::kProvenPlanarBound;
  EXPECT_GE(quality.MinimumAngle, bound - 1e-9);
}

LeafBox Cube(int x, int y, int z, int size) { return LeafBox{ { x, y, z }, size, 3 }; }
LeafBox Square(int x, int y, int size) { return LeafBox{ { x, y, 0 }, size, 2 }; }

/// Index-space corner of a leaf (voxel centres at integers: the leaf's low
/// corner is at Origin - 1/2).
Point3 Low(const LeafBox& box)
{
  return { box.Origin[0] - 0.5, box.Origin[1] - 0.5, box.Dimension == 2 ? 0.0 : box.Origin[2] - 0.5 };
}

using testing::Plane;
using testing::Volume;

const LabelImage kEmpty3D(16, 16, 16), kEmpty2D(16, 16, 1);

// ---- uniform leaves ------------------------------------------------------------

TEST(LeafFill, UniformCubeWithoutExtraPointsIsTheSixTetrahedraKuhnSplit)
{
  const LeafBox box = Cube(2, 4, 6, 4);
  const SimplexMesh mesh = Fill(kEmpty3D, { Uniform(box, 7) });
  ASSERT_EQ(mesh.NumberOfCells(), 6u);
  EXPECT_EQ(mesh.Points.size(), 8u); // the cube's corners only
  const Point3 lo = Low(box), hi{ lo[0] + 4, lo[1] + 4, lo[2] + 4 };
  for (std::size_t c = 0; c < 6; ++c)
  {
    EXPECT_EQ(mesh.Materials[c], 7);
    EXPECT_EQ(Measure(mesh, c), 64.0); // six times a sixth of 4^3
    EXPECT_TRUE(HasVertex(mesh, c, lo) && HasVertex(mesh, c, hi)) << "cell " << c << " is not around the diagonal";
  }
  ExpectTiling(mesh, lo, 4);
  EXPECT_NEAR(MeasureQuality(mesh).MinimumAngle, 45.0, 1e-9); // the Kuhn tetrahedron's smallest angle
  ExpectAngleBound(mesh);
}

TEST(LeafFill, UniformSquareWithoutExtraPointsIsTwoTriangles)
{
  const LeafBox box = Square(3, 5, 8);
  const SimplexMesh mesh = Fill(kEmpty2D, { Uniform(box, 2) });
  ASSERT_EQ(mesh.NumberOfCells(), 2u);
  EXPECT_EQ(mesh.Points.size(), 4u);
  const Point3 lo = Low(box), hi{ lo[0] + 8, lo[1] + 8, 0 };
  for (std::size_t c = 0; c < 2; ++c)
  {
    EXPECT_EQ(mesh.Materials[c], 2);
    EXPECT_EQ(Measure(mesh, c), 64.0); // twice half of 8^2
    EXPECT_TRUE(HasVertex(mesh, c, lo) && HasVertex(mesh, c, hi)); // split along the diagonal from the low corner
  }
  ExpectTiling(mesh, lo, 8);
  EXPECT_NEAR(MeasureQuality(mesh).MinimumAngle, 45.0, 1e-9);
}

TEST(LeafFill, UniformCubeWithAnEdgeMidpointIsConedFromItsCentre)
{
  // A midpoint on cube edge 0 (along x, at y = z = low): the two faces
  // through that edge are fanned from their centres over five ring points
  // (five triangles each), the other four keep their Kuhn diagonal (two
  // each): 18 tetrahedra, every one with the leaf's centre as apex.
  const LeafBox box = Cube(0, 0, 0, 2);
  const SimplexMesh mesh = Fill(kEmpty3D, { Uniform(box, 3, 1u << 0) });
  EXPECT_EQ(mesh.NumberOfCells(), 18u);
  const Point3 lo = Low(box), centre{ lo[0] + 1, lo[1] + 1, lo[2] + 1 }, midpoint{ lo[0] + 1, lo[1], lo[2] };
  std::size_t usingMidpoint = 0;
  for (std::size_t c = 0; c < mesh.NumberOfCells(); ++c)
  {
    EXPECT_TRUE(HasVertex(mesh, c, centre)) << "cell " << c;
    EXPECT_EQ(mesh.Materials[c], 3);
    usingMidpoint += HasVertex(mesh, c, midpoint);
  }
  EXPECT_EQ(usingMidpoint, 4u); // two fan triangles on each side of it, on each of its two faces
  ExpectTiling(mesh, lo, 2);
  ExpectAngleBound(mesh);
}

TEST(LeafFill, UniformCubeWithEveryEdgeMidpointHasEightTrianglesPerFace)
{
  const LeafBox box = Cube(4, 0, 8, 4);
  const SimplexMesh mesh = Fill(kEmpty3D, { Uniform(box, 1, 0x0fff) });
  EXPECT_EQ(mesh.NumberOfCells(), 6u * 8u);
  EXPECT_EQ(mesh.Points.size(), 8u + 12u + 6u + 1u); // corners, edge midpoints, face centres, centre
  ExpectTiling(mesh, Low(box), 4);
  ExpectAngleBound(mesh);
}

TEST(LeafFill, SquareWithASideMidpointIsConedFromItsCentre)
{
  // Bit f of EdgeMidpoints in 2D: side f (2 axis + high). A midpoint on side
  // 1 (x high): a ring of five points, five triangles around the centre.
  const LeafBox box = Square(0, 0, 4);
  const SimplexMesh mesh = Fill(kEmpty2D, { Uniform(box, 1, 1u << 1) });
  ASSERT_EQ(mesh.NumberOfCells(), 5u);
  const Point3 lo = Low(box), centre{ lo[0] + 2, lo[1] + 2, 0 }, midpoint{ lo[0] + 4, lo[1] + 2, 0 };
  std::size_t usingMidpoint = 0;
  for (std::size_t c = 0; c < mesh.NumberOfCells(); ++c)
  {
    EXPECT_TRUE(HasVertex(mesh, c, centre));
    usingMidpoint += HasVertex(mesh, c, midpoint);
  }
  EXPECT_EQ(usingMidpoint, 2u);
  ExpectTiling(mesh, lo, 4);
  ExpectAngleBound(mesh);
  // All four sides: eight triangles.
  const SimplexMesh full = Fill(kEmpty2D, { Uniform(box, 1, 0xf) });
  EXPECT_EQ(full.NumberOfCells(), 8u);
  ExpectTiling(full, lo, 4);
  ExpectAngleBound(full);
}

// ---- neighbours of different sizes --------------------------------------------

TEST(LeafFill, LeafWithASplitFaceConformsToItsFourFinerNeighbours)
{
  // A 4^3 leaf whose face x = high (face 1) is covered by four 2^3 leaves:
  // that face is four plain sub-faces (eight triangles), the four faces
  // around it carry the midpoint of their edge on it (five triangles each),
  // the opposite face is plain (two): 30 tetrahedra. With the four finer
  // leaves' Kuhn splits the whole is conforming: no hanging vertex, no face
  // shared by more than two cells.
  const LeafBox big = Cube(0, 0, 0, 4);
  std::uint16_t edgesOfFace1 = 0;
  for (int e = 0; e < 4; ++e)
    edgesOfFace1 |= static_cast<std::uint16_t>(1u << FaceEdgeToCube(1, e));
  const SimplexMesh alone = Fill(kEmpty3D, { Uniform(big, 1, edgesOfFace1, 1u << 1) });
  EXPECT_EQ(alone.NumberOfCells(), 30u);
  ExpectTiling(alone, Low(big), 4);
  ExpectAngleBound(alone);

  std::vector<OctreeLeaf> leaves{ Uniform(big, 1, edgesOfFace1, 1u << 1) };
  for (int j : { 0, 2 })
    for (int k : { 0, 2 })
      leaves.push_back(Uniform(Cube(4, j, k, 2), 1));
  const SimplexMesh together = Fill(kEmpty3D, leaves);
  EXPECT_EQ(together.NumberOfCells(), 30u + 4u * 6u);
  const ConformityReport conformity = MeasureConformity(together);
  EXPECT_EQ(conformity.HangingVertices, 0u);
  EXPECT_EQ(conformity.OverSharedFaces, 0u);
  EXPECT_EQ(conformity.NonManifoldBoundaryEdges, 0u);
  ExpectAngleBound(together);
  // Without the split face the finer leaves' corners hang on the big face.
  std::vector<OctreeLeaf> unsplit = leaves;
  unsplit[0] = Uniform(big, 1);
  EXPECT_GT(MeasureConformity(Fill(kEmpty3D, unsplit)).HangingVertices, 0u);
}

TEST(LeafFill, SquareWithASideMidpointConformsToItsTwoFinerNeighbours)
{
  const LeafBox big = Square(0, 0, 4);
  const std::vector<OctreeLeaf> leaves{ Uniform(big, 1, 1u << 1), Uniform(Square(4, 0, 2), 1),
    Uniform(Square(4, 2, 2), 1) };
  const SimplexMesh mesh = Fill(kEmpty2D, leaves);
  EXPECT_EQ(mesh.NumberOfCells(), 5u + 2u + 2u);
  EXPECT_EQ(mesh.Points.size(), 4u + 1u + 1u + 3u); // big corners, centre, midpoint; finer leaves' other corners
  EXPECT_TRUE(MeasureConformity(mesh).Conforming());
  ExpectAngleBound(mesh);
}

TEST(LeafFill, SharedCornersBecomeOneVertex)
{
  // Two uniform cubes side by side: 8 + 4 points, 12 tetrahedra, and the
  // shared face is triangulated alike from both sides.
  const SimplexMesh mesh = Fill(kEmpty3D, { Uniform(Cube(0, 0, 0, 2), 1), Uniform(Cube(2, 0, 0, 2), 4) });
  EXPECT_EQ(mesh.NumberOfCells(), 12u);
  EXPECT_EQ(mesh.Points.size(), 12u);
  EXPECT_TRUE(MeasureConformity(mesh).Conforming());
}

// ---- proper (boundary) leaves -----------------------------------------------------

TEST(LeafFill, ProperCubeCutByAPlaneLabelsEachCellByItsSide)
{
  // Label 2 above the plane between layers 5 and 6 (index z = 5.5), label 1
  // below, in the leaf (4..7)^3: the surface is the cone over the midpoints
  // of the four vertical edges, which lies in that plane. Every cell is on
  // one side of it and carries that side's label; each side is half the leaf.
  const LabelImage image = Volume(12, [](int, int, int k) { return k >= 6 ? 2 : 1; });
  const LeafBox box = Cube(4, 4, 4, 4);
  const SimplexMesh mesh = Fill(image, { Proper(box, 1, 2) });
  double below = 0, above = 0;
  for (std::size_t c = 0; c < mesh.NumberOfCells(); ++c)
  {
    double zMin = 1e9, zMax = -1e9;
    for (int i = 0; i < 4; ++i)
    {
      zMin = std::min(zMin, mesh.Points[mesh.Cell(c)[i]][2]);
      zMax = std::max(zMax, mesh.Points[mesh.Cell(c)[i]][2]);
    }
    ASSERT_TRUE(zMax <= 5.5 || zMin >= 5.5) << "cell " << c << " crosses the surface";
    EXPECT_EQ(mesh.Materials[c], zMax <= 5.5 ? 1 : 2) << "cell " << c;
    (zMax <= 5.5 ? below : above) += Measure(mesh, c);
  }
  EXPECT_EQ(below, 6.0 * 32);
  EXPECT_EQ(above, 6.0 * 32);
  ExpectTiling(mesh, Low(box), 4);
  ExpectAngleBound(mesh);
}

TEST(LeafFill, ProperCubeWithOneCornerCutOffLabelsEachCellByItsSide)
{
  // Label 2 in the octant i, j, k >= 6 only: of the leaf (4..7)^3 only its
  // corner (8, 8, 8) is label 2. The surface is the cone from the centre
  // over the triangle of the midpoints of the three edges at that corner,
  // and the region of label 2 is the cone from the centre over the three
  // corner triangles of the faces there: 3 * (1/3 * 2 * 2) = 4 voxels of the
  // 64. In lattice units (u = 2 x + 1), centre (12, 12, 12), that region is
  // where u + v - w, u - v + w and -u + v + w are all >= 12.
  const LabelImage image = Volume(12, [](int i, int j, int k) { return i >= 6 && j >= 6 && k >= 6 ? 2 : 1; });
  const LeafBox box = Cube(4, 4, 4, 4);
  const SimplexMesh mesh = Fill(image, { Proper(box, 1, 2) });
  double second = 0, first = 0;
  for (std::size_t c = 0; c < mesh.NumberOfCells(); ++c)
  {
    const Point3 g = Centroid(mesh, c);
    const double u = 2 * g[0] + 1, v = 2 * g[1] + 1, w = 2 * g[2] + 1;
    const bool corner = u + v - w > 12 && u - v + w > 12 && -u + v + w > 12;
    EXPECT_EQ(mesh.Materials[c], corner ? 2 : 1) << "cell " << c;
    (mesh.Materials[c] == 2 ? second : first) += Measure(mesh, c);
  }
  EXPECT_EQ(second, 6.0 * 4);
  EXPECT_EQ(first, 6.0 * 60);
  ExpectTiling(mesh, Low(box), 4);
  ExpectAngleBound(mesh);
}

TEST(LeafFill, ProperSquaresLabelEachTriangleByItsSide)
{
  // 2D, leaf (4..7)^2: label 2 above the line between rows 5 and 6: a ring of
  // four corners and the midpoints of the left and right sides, six triangles,
  // three per side of the surface (the segments from the centre to those
  // midpoints), each side half the leaf.
  const LeafBox box = Square(4, 4, 4);
  const SimplexMesh halves = Fill(Plane(12, 12, [](int, int j) { return j >= 6 ? 2 : 1; }), { Proper(box, 1, 2) });
  ASSERT_EQ(halves.NumberOfCells(), 6u);
  double area[3] = { 0, 0, 0 };
  for (std::size_t c = 0; c < 6; ++c)
  {
    const bool upper = Centroid(halves, c)[1] > 5.5;
    EXPECT_EQ(halves.Materials[c], upper ? 2 : 1);
    area[halves.Materials[c]] += Measure(halves, c);
  }
  EXPECT_EQ(area[1], 2.0 * 8);
  EXPECT_EQ(area[2], 2.0 * 8);
  ExpectTiling(halves, Low(box), 4);
  ExpectAngleBound(halves);

  // Label 2 in the quadrant i, j >= 6: only the corner (8, 8) is label 2; the
  // surface runs from the centre to the midpoints of the right and top
  // sides, and label 2 is the square between them and that corner, a quarter
  // of the leaf.
  const SimplexMesh corner =
    Fill(Plane(12, 12, [](int i, int j) { return i >= 6 && j >= 6 ? 2 : 1; }), { Proper(box, 1, 2) });
  double cornerArea = 0;
  for (std::size_t c = 0; c < corner.NumberOfCells(); ++c)
  {
    const Point3 g = Centroid(corner, c);
    EXPECT_EQ(corner.Materials[c], g[0] > 5.5 && g[1] > 5.5 ? 2 : 1) << "cell " << c;
    if (corner.Materials[c] == 2)
      cornerArea += Measure(corner, c);
  }
  EXPECT_EQ(cornerArea, 2.0 * 4);
  ExpectTiling(corner, Low(box), 4);
  ExpectAngleBound(corner);
}

TEST(LeafFill, ProperSquareWithAZeroCornerTakesItsLabelsFromTheOtherCorners)
{
  // Label 2 on and above the diagonal j >= i: the leaf (4..7)^2 has 0-points
  // at its corners (4, 4) and (8, 8) (pixels of both labels around them);
  // the surface runs from the centre to both, along the diagonal, and the
  // triangles above it are label 2, below label 1, half the leaf each.
  const LeafBox box = Square(4, 4, 4);
  const SimplexMesh mesh = Fill(Plane(12, 12, [](int i, int j) { return j >= i ? 2 : 1; }), { Proper(box, 1, 2) });
  double area[3] = { 0, 0, 0 };
  for (std::size_t c = 0; c < mesh.NumberOfCells(); ++c)
  {
    const Point3 g = Centroid(mesh, c);
    EXPECT_EQ(mesh.Materials[c], g[1] > g[0] ? 2 : 1) << "cell " << c;
    area[mesh.Materials[c]] += Measure(mesh, c);
  }
  EXPECT_EQ(area[1], 2.0 * 8);
  EXPECT_EQ(area[2], 2.0 * 8);
  ExpectTiling(mesh, Low(box), 4);
  ExpectAngleBound(mesh);
}

TEST(LeafFill, EveryCornerLabellingOfAProperCubeTilesItWithinTheAngleBound)
{
  // The ways to give the corners of a 2^3 leaf labels 1 and 2 (each voxel of
  // the leaf, and the voxels beyond it, carries the label of its corner) with
  // both labels present and no face a saddle (+, -, +, - around it: no face
  // stencil exists for that, and the manifold condition rejects it first):
  // whatever the stencils chosen, the cells tile the leaf, are positively
  // oriented, carry one of the leaf's two labels, and keep 30 degrees.
  // (Whether the octree keeps such a leaf is the manifold condition's
  // business, not the fill's.)
  auto hasSaddleFace = [](unsigned pattern) {
    for (int face = 0; face < 6; ++face)
    {
      const unsigned q0 = (pattern >> FaceCornerToCube(face, 0)) & 1u, q1 = (pattern >> FaceCornerToCube(face, 1)) & 1u,
                     q2 = (pattern >> FaceCornerToCube(face, 2)) & 1u, q3 = (pattern >> FaceCornerToCube(face, 3)) & 1u;
      if (q0 == q3 && q1 == q2 && q0 != q1)
        return true;
    }
    return false;
  };
  int configurations = 0;
  for (unsigned pattern = 1; pattern < 255; ++pattern)
  {
    if (hasSaddleFace(pattern))
      continue;
    ++configurations;
    // Voxel (4 + a, 4 + b, 4 + c) and everything beyond it along the
    // leaf's outward directions get the label of corner a + 2 b + 4 c.
    const LabelImage image = Volume(10, [pattern](int i, int j, int k) {
      const int corner = (i >= 5 ? 1 : 0) | (j >= 5 ? 2 : 0) | (k >= 5 ? 4 : 0);
      return ((pattern >> corner) & 1u) ? 2 : 1;
    });
    const LeafBox box = Cube(4, 4, 4, 2);
    SCOPED_TRACE("corners of label 2: " + std::to_string(pattern));
    const SimplexMesh mesh = Fill(image, { Proper(box, 1, 2) });
    for (std::int32_t m : mesh.Materials)
      ASSERT_TRUE(m == 1 || m == 2);
    ExpectTiling(mesh, Low(box), 2);
    ExpectAngleBound(mesh);
    if (HasFailure())
      return;
  }
  EXPECT_EQ(configurations, 134); // of the 254 with both labels
}

} // namespace
} // namespace labelmesher
