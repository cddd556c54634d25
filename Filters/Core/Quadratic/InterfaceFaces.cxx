// SPDX-License-Identifier: GPL-2.0-or-later
// Faces between materials and on the box, and the edges of one smooth sheet.
#include "Quadratic/InterfaceFaces.h"

#include "Support/Geometry.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace labelmesher
{
using namespace geometry;

std::vector<MaterialFace> FindInterfaceFaces(const QuadraticMesh& mesh)
{
  const SimplexMesh& linear = mesh.Linear;
  // Only a face whose corners all touch two materials, or all lie on the mesh's box (a face of
  // one cell), can bound a material: the others are never listed, which keeps this to the
  // interfaces' size (every face of every cell in a map took hundreds of MB on digimouse).
  constexpr std::int64_t kUnseen = -2, kMixed = -1;
  std::vector<std::int64_t> material(linear.Points.size(), kUnseen);
  for (std::size_t c = 0; c < linear.NumberOfCells(); ++c)
    for (int k = 0; k < 4; ++k)
    {
      std::int64_t& m = material[static_cast<std::size_t>(linear.Cell(c)[k])];
      m = m == kUnseen ? linear.Materials[c] : (m == linear.Materials[c] ? m : kMixed);
    }
  Point3 lo = linear.Points.empty() ? Point3{ 0, 0, 0 } : linear.Points[0], hi = lo;
  for (const Point3& p : linear.Points)
    for (int a = 0; a < 3; ++a)
      lo[a] = std::min(lo[a], p[a]), hi[a] = std::max(hi[a], p[a]);
  std::vector<char> candidate(linear.Points.size(), 0);
  for (std::size_t v = 0; v < candidate.size(); ++v)
  {
    bool onBox = false;
    for (int a = 0; a < 3; ++a)
      onBox = onBox || linear.Points[v][a] == lo[a] || linear.Points[v][a] == hi[a];
    candidate[v] = material[v] == kMixed || onBox;
  }
  // Each candidate face once per cell using it, sorted by its corners then its cell: a face of
  // two cells comes twice in a row, the first cell first (a fixed order, as a map's).
  struct Use
  {
    std::array<std::int64_t, 3> Key;
    std::size_t Cell;
    int Opposite;
  };
  std::vector<Use> uses;
  for (std::size_t c = 0; c < linear.NumberOfCells(); ++c)
  {
    const std::int64_t* v = linear.Cell(c);
    for (int k = 0; k < 4; ++k)
    {
      std::array<std::int64_t, 3> key{ v[(k + 1) % 4], v[(k + 2) % 4], v[(k + 3) % 4] };
      if (!candidate[static_cast<std::size_t>(key[0])] || !candidate[static_cast<std::size_t>(key[1])] ||
        !candidate[static_cast<std::size_t>(key[2])])
        continue;
      std::sort(key.begin(), key.end());
      uses.push_back({ key, c, k });
    }
  }
  std::sort(uses.begin(), uses.end(), [](const Use& a, const Use& b) {
    if (a.Key[0] != b.Key[0])
      return a.Key[0] < b.Key[0];
    if (a.Key[1] != b.Key[1])
      return a.Key[1] < b.Key[1];
    if (a.Key[2] != b.Key[2])
      return a.Key[2] < b.Key[2];
    return a.Cell < b.Cell;
  });
  struct Seen
  {
    std::size_t Cell;
    int Opposite;
    std::int64_t Other = -1;
  };
  std::vector<Seen> faces;
  for (std::size_t u = 0; u < uses.size();)
  {
    std::size_t next = u + 1;
    while (next < uses.size() && uses[next].Key == uses[u].Key)
      ++next;
    faces.push_back({ uses[u].Cell, uses[u].Opposite, next - u >= 2 ? static_cast<std::int64_t>(uses[u + 1].Cell) : -1 });
    u = next;
  }
  uses = std::vector<Use>();
  // The candidates hold every face of one cell only if the mesh fills its box (then such faces
  // lie on it): their area must be the box's, or faces were missed (and their edges could curve).
  double boundary = 0.0;
  for (const Seen& seen : faces)
    if (seen.Other < 0)
    {
      const std::int64_t* v = linear.Cell(seen.Cell);
      const int k = seen.Opposite;
      const Point3& a = linear.Points[static_cast<std::size_t>(v[(k + 1) % 4])];
      boundary += 0.5 *
        Norm(Cross(Sub(linear.Points[static_cast<std::size_t>(v[(k + 2) % 4])], a),
          Sub(linear.Points[static_cast<std::size_t>(v[(k + 3) % 4])], a)));
    }
  const Point3 size = Sub(hi, lo);
  const double box = 2.0 * (size[0] * size[1] + size[1] * size[2] + size[0] * size[2]);
  if (!(std::fabs(boundary - box) <= 1e-9 * box))
    throw std::invalid_argument("quadratic curving needs a mesh that fills its box, background cells included "
                                "(its boundary has area " + std::to_string(boundary) + ", its box " +
      std::to_string(box) + ")");
  std::vector<MaterialFace> out;
  for (const Seen& seen : faces)
  {
    const std::int32_t here = linear.Materials[seen.Cell];
    const bool onBox = seen.Other < 0;
    const std::int32_t there = onBox ? here : linear.Materials[static_cast<std::size_t>(seen.Other)];
    if (!onBox && here == there)
      continue;
    const std::int64_t* v = linear.Cell(seen.Cell);
    const int k = seen.Opposite;
    // Corners of the face opposite corner k, ordered so that the normal points out of the cell.
    std::array<std::int64_t, 3> p{ v[(k + 1) % 4], v[(k + 2) % 4], v[(k + 3) % 4] };
    const auto& P = linear.Points;
    const Point3& a = P[static_cast<std::size_t>(p[0])];
    if (Dot(Cross(Sub(P[static_cast<std::size_t>(p[1])], a), Sub(P[static_cast<std::size_t>(p[2])], a)),
          Sub(a, P[static_cast<std::size_t>(v[k])])) < 0.0)
      std::swap(p[1], p[2]);
    MaterialFace face;
    face.Points = p;
    face.OnBox = onBox;
    face.Below = std::min(here, there);
    face.Above = std::max(here, there);
    if (!onBox && here > there)
      std::swap(face.Points[1], face.Points[2]); // the normal points from Below to Above
    const std::size_t cell = seen.Cell;
    for (int j = 0; j < 3; ++j)
    {
      const std::int64_t a = face.Points[(j + 1) % 3], b = face.Points[(j + 2) % 3];
      for (int e = 0; e < 6; ++e)
      {
        const std::int64_t x = v[kTetraEdges[e][0]], y = v[kTetraEdges[e][1]];
        if ((x == a && y == b) || (x == b && y == a))
          face.Edges[j] = mesh.CellEdges[cell * 6 + e];
      }
    }
    out.push_back(face);
  }
  return out;
}

Point3 FaceNormal(const QuadraticMesh& mesh, const MaterialFace& face)
{
  const auto& P = mesh.Linear.Points;
  const Point3& a = P[static_cast<std::size_t>(face.Points[0])];
  const Point3 n = Cross(Sub(P[static_cast<std::size_t>(face.Points[1])], a), Sub(P[static_cast<std::size_t>(face.Points[2])], a));
  const double length = Norm(n);
  return length > 0.0 ? Scale(n, 1.0 / length) : n;
}

std::vector<char> CurvableEdges(const QuadraticMesh& mesh, const std::vector<MaterialFace>& faces,
  const std::array<double, 6>& box)
{
  const std::size_t edges = mesh.Edges.size();
  std::vector<int> count(edges, 0);
  std::vector<char> blocked(edges, 0);
  std::vector<std::pair<std::int32_t, std::int32_t>> pair(edges, { 0, 0 });
  std::vector<Point3> normal(edges, Point3{ 0.0, 0.0, 0.0 });
  for (const MaterialFace& f : faces)
  {
    const Point3 n = FaceNormal(mesh, f);
    for (std::int64_t id : f.Edges)
    {
      const auto e = static_cast<std::size_t>(id);
      if (f.OnBox || (count[e] > 0 && pair[e] != std::make_pair(f.Below, f.Above)))
        blocked[e] = 1;
      if (count[e] == 1 && Dot(normal[e], n) <= 0.0)
        blocked[e] = 1; // a fold: the two faces turn by 90 degrees or more
      pair[e] = { f.Below, f.Above };
      normal[e] = n;
      ++count[e];
    }
  }
  auto onBoxSide = [&](const Point3& a, const Point3& b) {
    for (int axis = 0; axis < 3; ++axis)
      for (double side : { box[2 * axis], box[2 * axis + 1] })
        if (a[axis] == side && b[axis] == side)
          return true;
    return false;
  };
  std::vector<char> curvable(edges, 0);
  for (std::size_t e = 0; e < edges; ++e)
  {
    const Point3& a = mesh.Linear.Points[static_cast<std::size_t>(mesh.Edges[e][0])];
    const Point3& b = mesh.Linear.Points[static_cast<std::size_t>(mesh.Edges[e][1])];
    curvable[e] = count[e] == 2 && !blocked[e] && !onBoxSide(a, b);
  }
  return curvable;
}

} // namespace labelmesher
