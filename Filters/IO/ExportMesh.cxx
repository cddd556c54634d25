// SPDX-License-Identifier: GPL-2.0-or-later
// Flattens the filters' VTK outputs into the writers' ExportMesh.
#include "ExportMesh.h"

#include "SafeFile.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cstring>
#include <map>
#include <numeric>
#include <unordered_map>

namespace labelmesher
{
namespace io
{
namespace
{

/// Exact coordinates as a hash key: the interface surface's points are the
/// mesh's points computed by the same transform, so they compare bit for bit.
struct PointKey
{
  std::array<double, 3> X;
  bool operator==(const PointKey& o) const { return this->X == o.X; }
};
struct PointKeyHash
{
  std::size_t operator()(const PointKey& k) const
  {
    std::size_t h = 1469598103934665603ull;
    for (double v : k.X)
    {
      std::uint64_t bits;
      std::memcpy(&bits, &v, sizeof bits);
      h = (h ^ bits) * 1099511628211ull;
    }
    return h;
  }
};

template <typename Key>
void GroupRuns(const std::vector<Key>& sortedKeys, std::vector<Key>& keys, std::vector<ExportMesh::Group>& groups)
{
  for (std::size_t i = 0; i < sortedKeys.size();)
  {
    std::size_t j = i;
    while (j < sortedKeys.size() && sortedKeys[j] == sortedKeys[i])
    {
      ++j;
    }
    keys.push_back(sortedKeys[i]);
    groups.push_back({ i, j });
    i = j;
  }
}

/// Faces (NodesPerFace() nodes each) and the pair each separates, sorted by pair (stably) into
/// out.Faces, out.Interfaces and out.InterfaceFaces.
void GroupFacesByPair(const std::vector<ExportMesh::Pair>& pairs, const std::vector<std::int64_t>& faces, ExportMesh& out)
{
  const auto faceNodes = static_cast<std::size_t>(out.NodesPerFace());
  std::vector<std::size_t> faceOrder(pairs.size());
  std::iota(faceOrder.begin(), faceOrder.end(), std::size_t{ 0 });
  std::stable_sort(faceOrder.begin(), faceOrder.end(), [&](std::size_t a, std::size_t b) { return pairs[a] < pairs[b]; });
  std::vector<ExportMesh::Pair> sortedPairs;
  sortedPairs.reserve(pairs.size());
  out.Faces.reserve(faces.size());
  for (std::size_t f : faceOrder)
  {
    sortedPairs.push_back(pairs[f]);
    out.Faces.insert(out.Faces.end(), faces.begin() + static_cast<std::ptrdiff_t>(f * faceNodes),
      faces.begin() + static_cast<std::ptrdiff_t>((f + 1) * faceNodes));
  }
  GroupRuns(sortedPairs, out.Interfaces, out.InterfaceFaces);
}

/// The interfaces of a quadratic mesh taken from its cells, as the linear interface surface has
/// them: every facet between cells of two materials, and every facet of one cell alone (against
/// the background or the image's box: material 0; background cells' own box facets, 0 against 0
/// with the background written, bound nothing). Tetrahedra give 6-node triangles (corners, then
/// the mid-nodes of edges 0-1, 1-2, 2-0: VTK's and Gmsh's order), oriented out of the cell of the
/// smaller material; triangles give 3-node segments (ends, then the mid-node), each running as
/// its edge in the cell of the smaller material (counter-clockwise in a flat mesh: that material
/// on its left). Cells are sorted by material; facets come in order of first use.
void QuadraticInterfaceFacets(ExportMesh& out)
{
  // A positively oriented tetrahedron's faces, outward: corners, then the cell's node slots
  // (4-9: edges 01, 12, 20, 03, 13, 23) of the face's edges 0-1, 1-2, 2-0. A triangle's edges:
  // ends, then the mid-node's slot (3-5: edges 01, 12, 20).
  static constexpr int kFace[4][6] = { { 1, 2, 3, 5, 9, 8 }, { 0, 3, 2, 7, 9, 6 }, { 0, 1, 3, 4, 8, 7 },
    { 0, 2, 1, 6, 5, 4 } };
  static constexpr int kEdge[3][6] = { { 0, 1, 3 }, { 1, 2, 4 }, { 2, 0, 5 } };
  const bool volume = out.Dimension == 3;
  const auto facets = static_cast<std::size_t>(volume ? 4 : 3);
  const auto corners = static_cast<std::size_t>(out.Dimension); // of a facet
  const auto cellNodes = static_cast<std::size_t>(out.NodesPerCell());
  const auto facetNodes = static_cast<std::size_t>(out.NodesPerFace());
  auto slotOf = [&](std::size_t facet, std::size_t k) {
    return static_cast<std::size_t>(volume ? kFace[facet][k] : kEdge[facet][k]);
  };
  struct Use
  {
    std::array<std::int64_t, 3> Key; ///< the facet's sorted corners (a segment's third: -1)
    std::size_t Slot;                ///< cell * facets + facet
  };
  std::vector<Use> uses;
  uses.reserve(out.NumberOfCells() * facets);
  for (std::size_t c = 0; c < out.NumberOfCells(); ++c)
    for (std::size_t f = 0; f < facets; ++f)
    {
      std::array<std::int64_t, 3> key{ -1, -1, -1 };
      for (std::size_t k = 0; k < corners; ++k)
        key[k] = out.Cells[c * cellNodes + slotOf(f, k)];
      std::sort(key.begin(), key.begin() + static_cast<std::ptrdiff_t>(corners));
      uses.push_back({ key, c * facets + f });
    }
  std::sort(uses.begin(), uses.end(), [](const Use& a, const Use& b) {
    return a.Key != b.Key ? a.Key < b.Key : a.Slot < b.Slot;
  });
  std::vector<std::pair<std::size_t, std::int32_t>> found; // (slot, the material beyond it)
  for (std::size_t u = 0; u < uses.size();)
  {
    std::size_t next = u + 1;
    while (next < uses.size() && uses[next].Key == uses[u].Key)
      ++next;
    const std::int32_t first = out.CellMaterial[uses[u].Slot / facets];
    const std::int32_t second = next - u >= 2 ? out.CellMaterial[uses[u + 1].Slot / facets] : 0;
    if (first != second)
      found.emplace_back(uses[u].Slot, second);
    u = next;
  }
  std::sort(found.begin(), found.end());
  std::vector<ExportMesh::Pair> pairs;
  std::vector<std::int64_t> nodes;
  for (const auto& [slot, other] : found)
  {
    const std::size_t c = slot / facets, f = slot % facets;
    const std::int32_t a = out.CellMaterial[c];
    pairs.push_back({ std::min(a, other), std::max(a, other) });
    for (std::size_t k = 0; k < facetNodes; ++k)
      nodes.push_back(out.Cells[c * cellNodes + slotOf(f, k)]);
  }
  GroupFacesByPair(pairs, nodes, out);
}

/// The cubic Bezier triangles' control points (VTK order: corners, two per edge, the centre) moved
/// to the Lagrange nodes of the same cubic map, at the barycentric points (i, j, k) / 3. A point
/// on an edge depends on that edge's four control points alone, so cells sharing the edge give it
/// the same position: the Lagrange mesh is as conforming as the Bezier one, and the two describe
/// the same curved cells exactly (degree 3 both ways).
void BezierToLagrange(vtkUnstructuredGrid* mesh, std::vector<std::array<double, 3>>& points)
{
  const std::vector<std::array<double, 3>> control = points;
  auto at = [&control](vtkIdType id) -> const std::array<double, 3>& { return control[static_cast<std::size_t>(id)]; };
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    mesh->GetCellPoints(c, ids);
    if (ids->GetNumberOfIds() != 10)
    {
      throw WriteError("a Bezier triangle of degree other than 3: only cubic ones can be written");
    }
    static constexpr int Edge[3][2] = { { 0, 1 }, { 1, 2 }, { 2, 0 } };
    for (int e = 0; e < 3; ++e)
    {
      // B(t) = (1-t)^3 a + 3 (1-t)^2 t c1 + 3 (1-t) t^2 c2 + t^3 b at t = 1/3 and 2/3.
      const auto& a = at(ids->GetId(Edge[e][0]));
      const auto& b = at(ids->GetId(Edge[e][1]));
      const auto& c1 = at(ids->GetId(3 + 2 * e));
      const auto& c2 = at(ids->GetId(4 + 2 * e));
      for (int k = 0; k < 3; ++k)
      {
        points[static_cast<std::size_t>(ids->GetId(3 + 2 * e))][k] = (8 * a[k] + 12 * c1[k] + 6 * c2[k] + b[k]) / 27.0;
        points[static_cast<std::size_t>(ids->GetId(4 + 2 * e))][k] = (a[k] + 6 * c1[k] + 12 * c2[k] + 8 * b[k]) / 27.0;
      }
    }
    // The centre (1/3, 1/3, 1/3): weights 1 at the corners, 3 at the edge points, 6 at the centre, over 27.
    std::array<double, 3> centre{ 0.0, 0.0, 0.0 };
    for (int slot = 0; slot < 10; ++slot)
    {
      const double w = slot < 3 ? 1.0 : (slot < 9 ? 3.0 : 6.0);
      for (int k = 0; k < 3; ++k)
        centre[k] += w * at(ids->GetId(slot))[k] / 27.0;
    }
    points[static_cast<std::size_t>(ids->GetId(9))] = centre;
  }
}

} // namespace

ExportMesh MakeExportMesh(vtkUnstructuredGrid* mesh, vtkPolyData* interfaces, const MaterialTable& table)
{
  ExportMesh out;
  out.Table = table;
  const vtkIdType nCells = mesh->GetNumberOfCells();
  vtkDataArray* material = mesh->GetCellData()->GetArray("Material");
  if (!material || material->GetNumberOfComponents() != 1)
  {
    throw WriteError("the mesh has no Material cell array");
  }
  int cellType = nCells > 0 ? mesh->GetCellType(0) : VTK_TETRA;
  if (cellType != VTK_TETRA && cellType != VTK_TRIANGLE && cellType != VTK_BEZIER_TRIANGLE &&
    cellType != VTK_QUADRATIC_TETRA && cellType != VTK_QUADRATIC_TRIANGLE)
  {
    throw WriteError("only linear tetrahedra and triangles, quadratic tetrahedra and triangles and cubic Bezier "
                     "triangles can be written");
  }
  out.Dimension = cellType == VTK_TETRA || cellType == VTK_QUADRATIC_TETRA ? 3 : 2;
  if (cellType == VTK_BEZIER_TRIANGLE)
    out.Order = 3;
  else if (cellType == VTK_QUADRATIC_TETRA || cellType == VTK_QUADRATIC_TRIANGLE)
    out.Order = 2;
  const int nodes = out.NodesPerCell();

  out.Points.resize(static_cast<std::size_t>(mesh->GetNumberOfPoints()));
  for (vtkIdType p = 0; p < mesh->GetNumberOfPoints(); ++p)
  {
    mesh->GetPoint(p, out.Points[static_cast<std::size_t>(p)].data());
  }
  if (out.Order == 3)
  {
    BezierToLagrange(mesh, out.Points);
  }

  std::vector<std::int32_t> labels(static_cast<std::size_t>(nCells));
  for (vtkIdType c = 0; c < nCells; ++c)
  {
    if (mesh->GetCellType(c) != cellType) // (BezierToLagrange has checked the cubic ones' ten points)
    {
      throw WriteError("the mesh mixes cell types; only all-tetrahedra or all-triangle meshes can be written in this format");
    }
    labels[static_cast<std::size_t>(c)] = static_cast<std::int32_t>(material->GetComponent(c, 0));
  }
  std::vector<std::size_t> order(labels.size());
  std::iota(order.begin(), order.end(), std::size_t{ 0 });
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return labels[a] < labels[b]; });
  out.Cells.reserve(order.size() * static_cast<std::size_t>(nodes));
  out.CellMaterial.reserve(order.size());
  vtkNew<vtkIdList> ids;
  for (std::size_t c : order)
  {
    mesh->GetCellPoints(static_cast<vtkIdType>(c), ids);
    for (int k = 0; k < nodes; ++k)
    {
      out.Cells.push_back(ids->GetId(k));
    }
    out.CellMaterial.push_back(labels[c]);
  }
  GroupRuns(out.CellMaterial, out.Materials, out.MaterialCells);

  // The filters' interface surface is linear; a quadratic mesh's interfaces come from its cells.
  if (interfaces && interfaces->GetNumberOfCells() > 0 && out.Order != 2)
  {
    vtkDataArray* sides = interfaces->GetCellData()->GetArray("Materials");
    if (!sides || sides->GetNumberOfComponents() != 2)
    {
      throw WriteError("the interface surface has no two-component Materials cell array");
    }
    std::unordered_map<PointKey, std::int64_t, PointKeyHash> index;
    index.reserve(out.Points.size());
    for (std::size_t p = 0; p < out.Points.size(); ++p)
    {
      index.emplace(PointKey{ out.Points[p] }, static_cast<std::int64_t>(p));
    }
    const int faceNodes = out.NodesPerFace();
    const vtkIdType nFaces = interfaces->GetNumberOfCells();
    std::vector<ExportMesh::Pair> pairs(static_cast<std::size_t>(nFaces));
    std::vector<std::int64_t> faces(static_cast<std::size_t>(nFaces * faceNodes));
    for (vtkIdType f = 0; f < nFaces; ++f)
    {
      interfaces->GetCellPoints(f, ids);
      if (ids->GetNumberOfIds() != faceNodes)
      {
        throw WriteError("the interface surface's cells do not match the mesh's dimension");
      }
      for (int k = 0; k < faceNodes; ++k)
      {
        PointKey key;
        interfaces->GetPoint(ids->GetId(k), key.X.data());
        auto found = index.find(key);
        if (found == index.end())
        {
          throw WriteError("the interface surface is not on the mesh's points (not this mesh's port 1)");
        }
        faces[static_cast<std::size_t>(f * faceNodes + k)] = found->second;
      }
      const auto a = static_cast<std::int32_t>(sides->GetComponent(f, 0));
      const auto b = static_cast<std::int32_t>(sides->GetComponent(f, 1));
      pairs[static_cast<std::size_t>(f)] = { std::min(a, b), std::max(a, b) };
    }
    GroupFacesByPair(pairs, faces, out);
  }
  else if (out.Order == 2)
  {
    QuadraticInterfaceFacets(out);
  }

  if (out.Dimension == 2 && !out.Points.empty())
  {
    for (int axis = 2; axis >= 0 && out.FlatAxis < 0; --axis)
    {
      const double v = out.Points[0][static_cast<std::size_t>(axis)];
      if (std::all_of(out.Points.begin(), out.Points.end(), [&](const std::array<double, 3>& p) { return p[static_cast<std::size_t>(axis)] == v; }))
      {
        out.FlatAxis = axis;
      }
    }
  }
  return out;
}

std::vector<std::size_t> WrittenAxes(const ExportMesh& mesh)
{
  std::vector<std::size_t> axes;
  for (std::size_t a = 0; a < 3; ++a)
  {
    if (!(mesh.Dimension == 2 && static_cast<int>(a) == mesh.FlatAxis))
    {
      axes.push_back(a);
    }
  }
  return axes;
}

double PlanarArea(const ExportMesh& mesh, const std::int64_t* cell)
{
  // The two axes besides FlatAxis, in order.
  const std::size_t u = mesh.FlatAxis == 0 ? 1 : 0, v = mesh.FlatAxis == 2 ? 1 : 2;
  const auto& a = mesh.Points[static_cast<std::size_t>(cell[0])];
  const auto& b = mesh.Points[static_cast<std::size_t>(cell[1])];
  const auto& c = mesh.Points[static_cast<std::size_t>(cell[2])];
  return (b[u] - a[u]) * (c[v] - a[v]) - (b[v] - a[v]) * (c[u] - a[u]);
}

void FlipTriangle(const ExportMesh& mesh, std::int64_t* cell)
{
  std::swap(cell[1], cell[2]);
  if (mesh.Order == 2)
    std::swap(cell[3], cell[5]); // edge 0-1 becomes 0-2 (was 2-0); edge 1-2 stays its own
}

} // namespace io
} // namespace labelmesher
