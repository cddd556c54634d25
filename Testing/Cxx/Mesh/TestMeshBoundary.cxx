// SPDX-License-Identifier: GPL-2.0-or-later
//
// ExtractMaterialInterfaces (Filters/Core/Mesh/MeshBoundary.h) and
// SelectMaterials (Filters/Core/Mesh/MeshSelection.h) on small hand-made
// meshes: exact face counts, the material pair of every face, the
// orientation convention (a face's normal points away from the cell it was
// taken from, whose material is Sides[f].first; in 2D the segment runs
// counter-clockwise around that cell, its normal being the direction turned
// clockwise), faces on the bounding box against material 0, and the sub-mesh
// of chosen materials with unused points dropped and cell order kept.

#include "Mesh/MeshBoundary.h"
#include "Mesh/MeshSelection.h"
#include "Support/Geometry.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>
#include <set>
#include <utility>

namespace labelmesher
{
namespace
{

using geometry::Cross;
using geometry::Dot;
using geometry::Sub;

/// Adds a tetrahedron (reordered to positive orientation) or triangle (made
/// counter-clockwise), as the mesher's cells are.
void AddCell(SimplexMesh& mesh, std::array<std::int64_t, 4> v, std::int32_t material)
{
  const auto& P = mesh.Points;
  if (mesh.Dimension == 3)
  {
    if (Dot(Sub(P[v[1]], P[v[0]]), Cross(Sub(P[v[2]], P[v[0]]), Sub(P[v[3]], P[v[0]]))) < 0)
      std::swap(v[1], v[2]);
    mesh.Connectivity.insert(mesh.Connectivity.end(), v.begin(), v.end());
  }
  else
  {
    if (Cross(Sub(P[v[1]], P[v[0]]), Sub(P[v[2]], P[v[0]]))[2] < 0)
      std::swap(v[1], v[2]);
    mesh.Connectivity.insert(mesh.Connectivity.end(), v.begin(), v.begin() + 3);
  }
  mesh.Materials.push_back(material);
}

/// The unit cube as the six Kuhn tetrahedra around its diagonal from (0,0,0)
/// to (1,1,1), listed around that diagonal so that consecutive ones (and the
/// last and the first) share a face: axis orders 012, 102, 120, 210, 201, 021.
SimplexMesh KuhnCube(const std::array<std::int32_t, 6>& materials)
{
  SimplexMesh mesh;
  mesh.Dimension = 3;
  for (int c = 0; c < 8; ++c)
    mesh.Points.push_back({ double(c & 1), double((c >> 1) & 1), double((c >> 2) & 1) });
  const int orders[6][3] = { { 0, 1, 2 }, { 1, 0, 2 }, { 1, 2, 0 }, { 2, 1, 0 }, { 2, 0, 1 }, { 0, 2, 1 } };
  for (int t = 0; t < 6; ++t)
  {
    const int a = 1 << orders[t][0], ab = a | (1 << orders[t][1]);
    AddCell(mesh, { 0, a, ab, 7 }, materials[t]);
  }
  return mesh;
}

/// The vertex (3D) or vertices of the cell of material `material` that holds
/// every vertex of face f, other than the face's own; -1 if there is none.
std::int64_t OppositeVertex(const SimplexMesh& mesh, const SimplexMesh& faces, std::size_t f, std::int32_t material)
{
  const int nf = faces.VerticesPerCell();
  for (std::size_t c = 0; c < mesh.NumberOfCells(); ++c)
  {
    if (mesh.Materials[c] != material)
      continue;
    const std::int64_t* cell = mesh.Cell(c);
    int shared = 0;
    std::int64_t other = -1;
    for (int i = 0; i < mesh.VerticesPerCell(); ++i)
    {
      const bool onFace = std::find(faces.Cell(f), faces.Cell(f) + nf, cell[i]) != faces.Cell(f) + nf;
      shared += onFace;
      if (!onFace)
        other = cell[i];
    }
    if (shared == nf)
      return other;
  }
  return -1;
}

/// Signed offset of point q from face f along its normal: negative behind it.
double Side(const SimplexMesh& faces, std::size_t f, const Point3& q)
{
  const std::int64_t* v = faces.Cell(f);
  const Point3& a = faces.Points[v[0]];
  if (faces.Dimension == 1)
  {
    const Point3 d = Sub(faces.Points[v[1]], a);
    const Point3 normal{ d[1], -d[0], 0 }; // the direction turned clockwise
    return Dot(normal, Sub(q, a));
  }
  return Dot(Cross(Sub(faces.Points[v[1]], a), Sub(faces.Points[v[2]], a)), Sub(q, a));
}

/// Every face: its material is its first side's; the cell it was taken from
/// (material first) lies behind it; the cell across (material second, if
/// not 0 or if a cell of material 0 is there) lies in front.
void ExpectOrientationConvention(const SimplexMesh& mesh, const MaterialInterfaces& interfaces)
{
  ASSERT_EQ(interfaces.Sides.size(), interfaces.Faces.NumberOfCells());
  for (std::size_t f = 0; f < interfaces.Faces.NumberOfCells(); ++f)
  {
    const auto [first, second] = interfaces.Sides[f];
    EXPECT_NE(first, second) << "face " << f;
    EXPECT_EQ(interfaces.Faces.Materials[f], first) << "face " << f;
    const std::int64_t behind = OppositeVertex(mesh, interfaces.Faces, f, first);
    ASSERT_GE(behind, 0) << "face " << f << " has no cell of material " << first;
    EXPECT_LT(Side(interfaces.Faces, f, mesh.Points[behind]), 0.0) << "face " << f;
    const std::int64_t across = OppositeVertex(mesh, interfaces.Faces, f, second);
    if (across >= 0)
    {
      EXPECT_GT(Side(interfaces.Faces, f, mesh.Points[across]), 0.0) << "face " << f;
    }
  }
}

/// (smaller, larger) material pair -> number of faces.
std::map<std::pair<std::int32_t, std::int32_t>, int> PairCounts(const MaterialInterfaces& interfaces)
{
  std::map<std::pair<std::int32_t, std::int32_t>, int> counts;
  for (const auto& [a, b] : interfaces.Sides)
    ++counts[{ std::min(a, b), std::max(a, b) }];
  return counts;
}

std::set<std::int64_t> FaceVertices(const SimplexMesh& faces, std::size_t f)
{
  return std::set<std::int64_t>(faces.Cell(f), faces.Cell(f) + faces.VerticesPerCell());
}

// ---- ExtractMaterialInterfaces -------------------------------------------------

TEST(MeshBoundary, TwoTetrahedraOfDifferentMaterialsSharingAFace)
{
  // (a, b, c, d) of material 1 above the triangle a b c in z = 0, (a, b, c, e)
  // of material 2 below it. Every vertex lies on the bounding box, so every
  // face is examined: the shared face between 1 and 2, and the three other
  // faces of each against the outside (material 0).
  SimplexMesh mesh;
  mesh.Dimension = 3;
  mesh.Points = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 0, 0, -1 } };
  AddCell(mesh, { 0, 1, 2, 3 }, 1);
  AddCell(mesh, { 0, 1, 2, 4 }, 2);
  const MaterialInterfaces interfaces = ExtractMaterialInterfaces(mesh);
  EXPECT_EQ(interfaces.Faces.Dimension, 2);
  EXPECT_EQ(interfaces.Faces.Points, mesh.Points); // the faces share the mesh's points
  ASSERT_EQ(interfaces.Faces.NumberOfCells(), 7u);
  const auto counts = PairCounts(interfaces);
  EXPECT_EQ(counts.at({ 1, 2 }), 1);
  EXPECT_EQ(counts.at({ 0, 1 }), 3);
  EXPECT_EQ(counts.at({ 0, 2 }), 3);
  for (std::size_t f = 0; f < 7; ++f)
  {
    const auto [first, second] = interfaces.Sides[f];
    if (second == 0)
      EXPECT_NE(first, 0); // the outside is never the side a face is taken from
    else
      EXPECT_EQ(FaceVertices(interfaces.Faces, f), (std::set<std::int64_t>{ 0, 1, 2 }));
  }
  ExpectOrientationConvention(mesh, interfaces);
}

TEST(MeshBoundary, KuhnCubeOfTwoMaterials)
{
  // Three tetrahedra around the diagonal of material 1, the next three of
  // material 2: the two faces where the groups meet (through the diagonal and
  // (0,1,1), and through the diagonal and (1,0,0)) separate 1 from 2; the
  // other four inner faces separate a material from itself and are not
  // boundary; the 12 triangles of the cube's faces separate a material from
  // the outside.
  const SimplexMesh mesh = KuhnCube({ 1, 1, 1, 2, 2, 2 });
  const MaterialInterfaces interfaces = ExtractMaterialInterfaces(mesh);
  ASSERT_EQ(interfaces.Faces.NumberOfCells(), 14u);
  const auto counts = PairCounts(interfaces);
  EXPECT_EQ(counts.at({ 1, 2 }), 2);
  EXPECT_EQ(counts.at({ 0, 1 }), 6);
  EXPECT_EQ(counts.at({ 0, 2 }), 6);
  std::set<std::set<std::int64_t>> inner;
  for (std::size_t f = 0; f < 14; ++f)
    if (interfaces.Sides[f].second != 0)
      inner.insert(FaceVertices(interfaces.Faces, f));
  // Point ids: bit 0 x, bit 1 y, bit 2 z; (0,1,1) is 6, (1,0,0) is 1.
  EXPECT_EQ(inner, (std::set<std::set<std::int64_t>>{ { 0, 6, 7 }, { 0, 1, 7 } }));
  ExpectOrientationConvention(mesh, interfaces);
  // Every face against the outside lies in one of the cube's six planes, and
  // its normal points out of the cube.
  for (std::size_t f = 0; f < 14; ++f)
  {
    if (interfaces.Sides[f].second != 0)
      continue;
    const std::int64_t* v = interfaces.Faces.Cell(f);
    bool inAPlane = false;
    for (int a = 0; a < 3; ++a)
    {
      const double x = mesh.Points[v[0]][a];
      inAPlane = inAPlane || (mesh.Points[v[1]][a] == x && mesh.Points[v[2]][a] == x);
    }
    EXPECT_TRUE(inAPlane) << "face " << f;
    EXPECT_LT(Side(interfaces.Faces, f, { 0.5, 0.5, 0.5 }), 0.0) << "face " << f << " points into the cube";
  }
}

TEST(MeshBoundary, BackgroundCellsMakeNoFacesAgainstTheOutside)
{
  // The same cube with material 0 for the first three tetrahedra: their faces
  // on the bounding box separate 0 from the outside (0) and are not boundary;
  // the two inner faces separate 0 from 3; the material-3 tetrahedra keep
  // their six faces on the box.
  const SimplexMesh mesh = KuhnCube({ 0, 0, 0, 3, 3, 3 });
  const MaterialInterfaces interfaces = ExtractMaterialInterfaces(mesh);
  ASSERT_EQ(interfaces.Faces.NumberOfCells(), 8u);
  const auto counts = PairCounts(interfaces);
  EXPECT_EQ(counts.at({ 0, 3 }), 8);
  int inner = 0;
  for (std::size_t f = 0; f < 8; ++f)
  {
    // A face against the outside is taken from its material-3 cell; an inner
    // face from either cell, with the other on its second side.
    const bool onBox =
      OppositeVertex(mesh, interfaces.Faces, f, 0) < 0 || OppositeVertex(mesh, interfaces.Faces, f, 3) < 0;
    if (onBox)
      EXPECT_EQ(interfaces.Sides[f], (std::pair<std::int32_t, std::int32_t>{ 3, 0 }));
    else
      ++inner;
  }
  EXPECT_EQ(inner, 2);
  ExpectOrientationConvention(mesh, interfaces);

  // One material throughout: only the 12 faces on the box, none inside.
  const SimplexMesh whole = KuhnCube({ 5, 5, 5, 5, 5, 5 });
  const MaterialInterfaces box = ExtractMaterialInterfaces(whole);
  ASSERT_EQ(box.Faces.NumberOfCells(), 12u);
  double area = 0;
  for (std::size_t f = 0; f < 12; ++f)
  {
    EXPECT_EQ(box.Sides[f], (std::pair<std::int32_t, std::int32_t>{ 5, 0 }));
    const std::int64_t* v = box.Faces.Cell(f);
    const Point3 &a = whole.Points[v[0]], &b = whole.Points[v[1]], &c = whole.Points[v[2]];
    area += 0.5 * geometry::Norm(Cross(Sub(b, a), Sub(c, a)));
  }
  EXPECT_DOUBLE_EQ(area, 6.0);
  ExpectOrientationConvention(whole, box);
  // All background: no boundary at all.
  EXPECT_EQ(ExtractMaterialInterfaces(KuhnCube({ 0, 0, 0, 0, 0, 0 })).Faces.NumberOfCells(), 0u);
}

TEST(MeshBoundary, TwoDimensionalSquareOfTwoTriangles)
{
  // The unit square split along its diagonal (0,0)-(1,1): material 4 below,
  // 9 above. Segments: the diagonal between 4 and 9 and the four sides
  // against the outside, each counter-clockwise around its cell.
  SimplexMesh mesh;
  mesh.Dimension = 2;
  mesh.Points = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 } };
  AddCell(mesh, { 0, 1, 2, -1 }, 4);
  AddCell(mesh, { 0, 2, 3, -1 }, 9);
  const MaterialInterfaces interfaces = ExtractMaterialInterfaces(mesh);
  EXPECT_EQ(interfaces.Faces.Dimension, 1);
  ASSERT_EQ(interfaces.Faces.NumberOfCells(), 5u);
  const auto counts = PairCounts(interfaces);
  EXPECT_EQ(counts.at({ 4, 9 }), 1);
  EXPECT_EQ(counts.at({ 0, 4 }), 2);
  EXPECT_EQ(counts.at({ 0, 9 }), 2);
  double length = 0;
  for (std::size_t f = 0; f < 5; ++f)
  {
    if (interfaces.Sides[f].second != 0)
      EXPECT_EQ(FaceVertices(interfaces.Faces, f), (std::set<std::int64_t>{ 0, 2 }));
    else
      length += geometry::Distance(mesh.Points[interfaces.Faces.Cell(f)[0]], mesh.Points[interfaces.Faces.Cell(f)[1]]);
  }
  EXPECT_DOUBLE_EQ(length, 4.0);
  ExpectOrientationConvention(mesh, interfaces);

  // A 2x1 rectangle of four triangles, background on the left: the segment
  // between the halves and the three outer sides of the right half.
  SimplexMesh strip;
  strip.Dimension = 2;
  strip.Points = { { 0, 0, 0 }, { 1, 0, 0 }, { 2, 0, 0 }, { 0, 1, 0 }, { 1, 1, 0 }, { 2, 1, 0 } };
  AddCell(strip, { 0, 1, 4, -1 }, 0);
  AddCell(strip, { 0, 4, 3, -1 }, 0);
  AddCell(strip, { 1, 2, 5, -1 }, 6);
  AddCell(strip, { 1, 5, 4, -1 }, 6);
  const MaterialInterfaces half = ExtractMaterialInterfaces(strip);
  ASSERT_EQ(half.Faces.NumberOfCells(), 4u);
  EXPECT_EQ(PairCounts(half).at({ 0, 6 }), 4);
  ExpectOrientationConvention(strip, half);
}

// ---- SelectMaterials ------------------------------------------------------------

TEST(MeshSelection, KeepsTheChosenCellsInOrderAndRenumbersTheirPointsByFirstUse)
{
  SimplexMesh mesh;
  mesh.Dimension = 2;
  for (int p = 0; p < 7; ++p)
    mesh.Points.push_back({ double(p), double(p * p), 0 }); // p6 is used by no cell
  mesh.Connectivity = { 0, 1, 2, /**/ 2, 3, 4, /**/ 4, 5, 0, /**/ 4, 1, 3 };
  mesh.Materials = { 0, 3, 0, 1 };

  const SimplexMesh foreground = SelectMaterials(mesh);
  EXPECT_EQ(foreground.Dimension, 2);
  EXPECT_EQ(foreground.Materials, (std::vector<std::int32_t>{ 3, 1 }));
  // First use: p2 -> 0, p3 -> 1, p4 -> 2 (cell 1), then p1 -> 3 (cell 3).
  EXPECT_EQ(foreground.Connectivity, (std::vector<std::int64_t>{ 0, 1, 2, 2, 3, 1 }));
  EXPECT_EQ(foreground.Points, (std::vector<Point3>{ mesh.Points[2], mesh.Points[3], mesh.Points[4], mesh.Points[1] }));

  const SimplexMesh everything = SelectMaterials(mesh, true);
  EXPECT_EQ(everything.Materials, mesh.Materials);
  EXPECT_EQ(everything.Connectivity, (std::vector<std::int64_t>{ 0, 1, 2, 2, 3, 4, 4, 5, 0, 4, 1, 3 }));
  ASSERT_EQ(everything.Points.size(), 6u); // the unused p6 is dropped
  for (int p = 0; p < 6; ++p)
    EXPECT_EQ(everything.Points[p], mesh.Points[p]);

  // Tetrahedra: four ids per cell, vertex order kept (so orientation too).
  const SimplexMesh cube = KuhnCube({ 0, 2, 2, 0, 0, 0 });
  const SimplexMesh two = SelectMaterials(cube);
  ASSERT_EQ(two.NumberOfCells(), 2u);
  EXPECT_EQ(two.Dimension, 3);
  for (std::size_t c = 0; c < 2; ++c)
    for (int i = 0; i < 4; ++i)
      EXPECT_EQ(two.Points[two.Cell(c)[i]], cube.Points[cube.Cell(c + 1)[i]]);
  // Tetrahedra 102 and 120 share the face (0, (0,1,0), (1,1,1)): five corners.
  EXPECT_EQ(two.Points.size(), 5u);
}

TEST(MeshSelection, TakingTheMeshOverGivesTheCopysResult)
{
  // Renumbering in place must match the copy: first-use order, unused points
  // dropped, points already in order left alone (the mesher's case).
  SimplexMesh mesh;
  mesh.Dimension = 2;
  for (int p = 0; p < 7; ++p)
    mesh.Points.push_back({ double(p), double(p * p), 0 });
  const std::vector<std::vector<std::int64_t>> connectivities = {
    { 0, 1, 2, 2, 3, 4, 4, 5, 0, 4, 1, 3 }, // in order, p6 unused
    { 6, 1, 2, 2, 3, 4, 4, 5, 0, 4, 1, 3 }, // out of order, all used
    { 0, 1, 2, 1, 3, 2, 3, 4, 2, 4, 5, 6 }, // in order, all used: nothing moves
  };
  for (const auto& connectivity : connectivities)
    for (const auto& materials : { std::vector<std::int32_t>{ 1, 3, 2, 1 }, std::vector<std::int32_t>{ 0, 3, 0, 1 } })
      for (bool background : { false, true })
      {
        mesh.Connectivity = connectivity;
        mesh.Materials = materials;
        const SimplexMesh copied = SelectMaterials(static_cast<const SimplexMesh&>(mesh), background);
        SimplexMesh handed = mesh;
        const SimplexMesh taken = SelectMaterials(std::move(handed), background);
        EXPECT_EQ(taken.Dimension, copied.Dimension);
        EXPECT_EQ(taken.Points, copied.Points);
        EXPECT_EQ(taken.Connectivity, copied.Connectivity);
        EXPECT_EQ(taken.Materials, copied.Materials);
      }
}

TEST(MeshSelection, NothingSelectedGivesAnEmptyMesh)
{
  const SimplexMesh empty = SelectMaterials(KuhnCube({ 0, 0, 0, 0, 0, 0 }));
  EXPECT_EQ(empty.NumberOfCells(), 0u);
  EXPECT_TRUE(empty.Points.empty());
  EXPECT_TRUE(empty.Connectivity.empty());
  EXPECT_EQ(empty.Dimension, 3);
}

} // namespace
} // namespace labelmesher
