// SPDX-License-Identifier: GPL-2.0-or-later
// Both distance bounds on curved faces, certified on their flattenings.
#include "Quadratic/QuadraticFidelity.h"

#include "Criteria/DistanceBound.h"
#include "Support/BoxBins.h"
#include "Support/Geometry.h"
#include "Support/ParallelChunks.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <unordered_map>

namespace labelmesher
{
using namespace geometry;

std::array<Point3, 6> FaceNodes(const QuadraticMesh& mesh, const MaterialFace& face)
{
  std::array<Point3, 6> nodes;
  for (int k = 0; k < 3; ++k)
  {
    nodes[k] = mesh.Linear.Points[static_cast<std::size_t>(face.Points[k])];
    nodes[3 + k] = mesh.MidNode(static_cast<std::size_t>(face.Edges[k]));
  }
  return nodes;
}

namespace
{

Point3 EvaluateFace(const std::array<Point3, 6>& n, double l0, double l1, double l2)
{
  const double l[3] = { l0, l1, l2 };
  Point3 x{ 0.0, 0.0, 0.0 };
  for (int k = 0; k < 3; ++k)
  {
    x = Add(x, Scale(n[k], l[k] * (2.0 * l[k] - 1.0)));
    x = Add(x, Scale(n[3 + k], 4.0 * l[(k + 1) % 3] * l[(k + 2) % 3]));
  }
  return x;
}

Point3 Min(const Point3& a, const Point3& b) { return { std::min(a[0], b[0]), std::min(a[1], b[1]), std::min(a[2], b[2]) }; }
Point3 Max(const Point3& a, const Point3& b) { return { std::max(a[0], b[0]), std::max(a[1], b[1]), std::max(a[2], b[2]) }; }

/// The face's Bézier control points: it lies in their convex hull.
std::array<Point3, 6> ControlPoints(const std::array<Point3, 6>& n)
{
  std::array<Point3, 6> c = n;
  for (int k = 0; k < 3; ++k)
    c[3 + k] = Sub(Scale(n[3 + k], 2.0), Scale(Add(n[(k + 1) % 3], n[(k + 2) % 3]), 0.5));
  return c;
}

/// The control points the face has with every edge at its full fitted offset: a pulled-back
/// curve's control points lie between those and the straight ones, so this hull holds every
/// shape the face had or will have (curves only shrink).
std::array<Point3, 6> FullScaleControlPoints(const QuadraticMesh& mesh, const MaterialFace& face)
{
  std::array<Point3, 6> c;
  for (int k = 0; k < 3; ++k)
  {
    c[k] = mesh.Linear.Points[static_cast<std::size_t>(face.Points[k])];
    const auto edge = static_cast<std::size_t>(face.Edges[k]);
    const Point3& a = mesh.Linear.Points[static_cast<std::size_t>(mesh.Edges[edge][0])];
    const Point3& b = mesh.Linear.Points[static_cast<std::size_t>(mesh.Edges[edge][1])];
    c[3 + k] = Add(Scale(Add(a, b), 0.5), Scale(mesh.Offset[edge], 2.0)); // 2 m − (a + b)/2 at scale 1
  }
  return c;
}

bool FaceIsCurved(const QuadraticMesh& mesh, const MaterialFace& face)
{
  for (std::int64_t e : face.Edges)
    if (mesh.Curved(static_cast<std::size_t>(e)))
      return true;
  return false;
}

ConvexPiece Triangle(const std::array<Point3, 3>& t)
{
  ConvexPiece p;
  p.Count = 3;
  for (int k = 0; k < 3; ++k)
    p.Points[k] = t[k];
  return p;
}

/// The face between voxel (i, j, k) and its neighbour along +axis.
ConvexPiece VoxelFace(int i, int j, int k, int axis)
{
  const Point3 c{ i + (axis == 0 ? 0.5 : 0.0), j + (axis == 1 ? 0.5 : 0.0), k + (axis == 2 ? 0.5 : 0.0) };
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  ConvexPiece p;
  p.Count = 4;
  const double su[4] = { -0.5, 0.5, 0.5, -0.5 }, sv[4] = { -0.5, -0.5, 0.5, 0.5 };
  for (int q = 0; q < 4; ++q)
  {
    p.Points[q] = c;
    p.Points[q][u] += su[q];
    p.Points[q][v] += sv[q];
  }
  return p;
}

struct VoxelBox
{
  int Lo[3], Hi[3];
};

/// The voxels (outside ones included, as label 0) whose faces may lie within
/// `reach` of the points.
template <class Points>
VoxelBox VoxelsNear(const Points& points, double reach, const LabelImage& image)
{
  VoxelBox box;
  for (int a = 0; a < 3; ++a)
  {
    double lo = points[0][a], hi = lo;
    for (const Point3& p : points)
      lo = std::min(lo, p[a]), hi = std::max(hi, p[a]);
    box.Lo[a] = std::max(-1, static_cast<int>(std::floor(lo - reach)) - 1);
    box.Hi[a] = std::min(image.Dimensions[a], static_cast<int>(std::ceil(hi + reach)) + 1);
  }
  return box;
}

/// Calls f(i, j, k, axis) for each voxel face of the box between a voxel of
/// material m and one of another label.
template <class F>
void ForEachBoundaryFace(const LabelImage& image, const VoxelBox& box, std::int32_t m, F&& f)
{
  for (int k = box.Lo[2]; k <= box.Hi[2]; ++k)
    for (int j = box.Lo[1]; j <= box.Hi[1]; ++j)
      for (int i = box.Lo[0]; i <= box.Hi[0]; ++i)
      {
        const bool here = image.At(i, j, k) == m;
        if (i < box.Hi[0] && here != (image.At(i + 1, j, k) == m))
          f(i, j, k, 0);
        if (j < box.Hi[1] && here != (image.At(i, j + 1, k) == m))
          f(i, j, k, 1);
        if (k < box.Hi[2] && here != (image.At(i, j, k + 1) == m))
          f(i, j, k, 2);
      }
}

} // namespace

int FlatteningLevel(const std::array<Point3, 6>& n, double tolerance)
{
  double bend = 0.0;
  for (int k = 0; k < 3; ++k)
    bend = std::max(bend, Norm(Sub(Add(n[(k + 1) % 3], n[(k + 2) % 3]), Scale(n[3 + k], 2.0))));
  double error = 2.0 / 3.0 * bend;
  for (int level = 0; level <= 5; ++level, error /= 4.0)
    if (error <= tolerance)
      return level;
  return -1;
}

std::vector<std::array<Point3, 3>> FlattenFace(const std::array<Point3, 6>& nodes, int level)
{
  const int n = 1 << level;
  auto at = [&](int i, int j) { return EvaluateFace(nodes, double(n - i - j) / n, double(i) / n, double(j) / n); };
  std::vector<std::array<Point3, 3>> triangles;
  triangles.reserve(static_cast<std::size_t>(n) * n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i + j < n; ++i)
    {
      triangles.push_back({ at(i, j), at(i + 1, j), at(i, j + 1) });
      if (i + j + 1 < n)
        triangles.push_back({ at(i + 1, j), at(i + 1, j + 1), at(i, j + 1) });
    }
  return triangles;
}

std::vector<std::size_t> FacesBreakingDistances(const QuadraticMesh& mesh, const std::vector<MaterialFace>& faces,
  const LabelImage& image, const QuadraticBounds& bounds, const std::vector<char>* changed,
  const std::function<bool()>& keepGoing)
{
  auto retest = [&](std::size_t f) { return !changed || (*changed)[f]; };
  // Asked between chunks by the calling thread only (it alone may talk to an observer); once it
  // says stop, the other chunks end too and the call throws.
  std::atomic<bool> stop{ false };
  auto stopping = [&](unsigned thread) {
    if (thread == 0 && keepGoing && !stop && !keepGoing())
      stop = true;
    return stop.load();
  };
  const double T = bounds.Tolerance;
  std::vector<char> failing(faces.size(), 0);
  // Curved faces' flattening levels (-1: none within 4^5); the sub-triangles are made where they
  // are used, never all at once (they took 0.7 GB on digimouse).
  std::vector<signed char> level(faces.size(), -1);
  std::vector<std::array<Point3, 6>> nodes(faces.size()), hull(faces.size());
  auto flatten = [&](std::size_t f) {
    return level[f] < 0 ? std::vector<std::array<Point3, 3>>{} : FlattenFace(nodes[f], level[f]);
  };
  std::vector<std::size_t> curved;
  for (std::size_t f = 0; f < faces.size(); ++f)
  {
    nodes[f] = FaceNodes(mesh, faces[f]);
    hull[f] = ControlPoints(nodes[f]);
    if (!FaceIsCurved(mesh, faces[f]))
      continue;
    curved.push_back(f);
    const int needed = FlatteningLevel(nodes[f], T);
    if (needed < 0 || bounds.MeshToImage < T || bounds.ImageToMesh < T)
    {
      failing[f] = 1;
      continue;
    }
    level[f] = static_cast<signed char>(needed);
  }

  // Mesh to image: each sub-triangle near the image boundary of each non-zero material beside it.
  const double meshReach = bounds.MeshToImage - T;
  // Faces are independent here (each writes its own flag): both cores take them.
  ParallelChunks(curved.size(), 64, [&](unsigned thread, std::size_t begin, std::size_t end) {
  if (stopping(thread))
    return;
  for (std::size_t index = begin; index < end; ++index)
  {
    const std::size_t f = curved[index];
    if (failing[f] || !retest(f))
      continue;
    const std::vector<std::array<Point3, 3>> flattened = flatten(f);
    for (std::int32_t m : { faces[f].Below, faces[f].Above })
    {
      if (m == 0 || failing[f])
        continue;
      std::vector<ConvexPiece> targets;
      ForEachBoundaryFace(image, VoxelsNear(hull[f], meshReach + 1.0, image), m,
        [&](int i, int j, int k, int axis) { targets.push_back(VoxelFace(i, j, k, axis)); });
      std::vector<ConvexPiece> near;
      for (const std::array<Point3, 3>& triangle : flattened)
      {
        const ConvexPiece t = Triangle(triangle);
        // Only voxel faces within reach of the sub-triangle (its points are within `radius` of
        // its centroid) can certify it: the exact test gets those.
        const Point3 centroid = Scale(Add(Add(t.Points[0], t.Points[1]), t.Points[2]), 1.0 / 3.0);
        double radius = 0.0;
        for (int q = 0; q < 3; ++q)
          radius = std::max(radius, Distance(centroid, t.Points[q]));
        const double reach = (meshReach + radius) * (meshReach + radius);
        near.clear();
        for (const ConvexPiece& v : targets)
          if (SquaredDistanceToBox(centroid, Min(v.Points[0], v.Points[2]), Max(v.Points[0], v.Points[2])) <= reach)
            near.push_back(v);
        if (!WithinDistance(t, near, meshReach))
        {
          failing[f] = 1;
          break;
        }
      }
    }
  }
  });

  if (stop)
    throw AbortRequested{};

  // Image to mesh: voxel faces of m near a curved face of m, against m's faces within reach.
  const double h = bounds.ImageToMesh;
  std::vector<std::array<Point3, 2>> hullBox(faces.size()); // low and high corners
  for (std::size_t f = 0; f < faces.size(); ++f)
  {
    hullBox[f] = { hull[f][0], hull[f][0] };
    for (const Point3& p : hull[f])
      hullBox[f] = { Min(hullBox[f][0], p), Max(hullBox[f][1], p) };
  }
  BoxBins3 bins(4.0);
  for (std::size_t f = 0; f < faces.size(); ++f)
  {
    std::array<double, 3> lo, hi;
    for (int a = 0; a < 3; ++a)
    {
      lo[a] = hi[a] = hull[f][0][a];
      for (const Point3& p : hull[f])
        lo[a] = std::min(lo[a], p[a]), hi[a] = std::max(hi[a], p[a]);
      lo[a] -= h + 1.0, hi[a] += h + 1.0; // a voxel face's points are within 0.71 of its centre
    }
    bins.Insert(f, lo, hi);
  }
  auto bounds_ = [](const MaterialFace& face, std::int32_t m) {
    return face.Below == m || (!face.OnBox && face.Above == m);
  };
  std::vector<std::int32_t> materials;
  for (std::size_t f : curved)
    for (std::int32_t m : { faces[f].Below, faces[f].Above })
      if (m != 0)
        materials.push_back(m);
  std::sort(materials.begin(), materials.end());
  materials.erase(std::unique(materials.begin(), materials.end()), materials.end());
  // Per material, the voxel faces to test, each once: those near a changed face (curved, or
  // straight again: its curve may have covered them, hence near any shape it has had: its
  // full-scale hull). Keys pack voxel (i + 1, j + 1, k + 1) and the axis; the list is made unique
  // whenever it has grown (neighbouring faces' boxes overlap), so it stays near its final size.
  const long long nx = image.Dimensions[0] + 2, ny = image.Dimensions[1] + 2;
  std::vector<std::vector<std::size_t>> blamed(MaxThreads());
  std::vector<long long> voxelFaces;
  auto makeUnique = [&voxelFaces]() {
    std::sort(voxelFaces.begin(), voxelFaces.end());
    voxelFaces.erase(std::unique(voxelFaces.begin(), voxelFaces.end()), voxelFaces.end());
  };
  for (std::int32_t m : materials)
  {
    voxelFaces.clear();
    std::size_t unique = 0;
    for (std::size_t f = 0; f < faces.size(); ++f)
    {
      if (!bounds_(faces[f], m) || !(changed ? (*changed)[f] : FaceIsCurved(mesh, faces[f])))
        continue;
      ForEachBoundaryFace(image, VoxelsNear(FullScaleControlPoints(mesh, faces[f]), h + 1.0, image), m,
        [&](int i, int j, int k, int axis) { voxelFaces.push_back((((k + 1) * ny + (j + 1)) * nx + (i + 1)) * 3 + axis); });
      if (voxelFaces.size() > 2 * unique + (1u << 20))
      {
        makeUnique();
        unique = voxelFaces.size();
      }
    }
    makeUnique();
    // Each voxel face against m's faces within reach; independent, so both cores take them, and
    // each thread lists the curved faces to blame (flags: the order does not matter).
    ParallelChunks(voxelFaces.size(), 4096, [&](unsigned thread, std::size_t begin, std::size_t end) {
      if (stopping(thread))
        return;
      std::vector<ConvexPiece> straight, all;
      std::vector<std::size_t> near; // curved faces whose boxes reach the voxel face
      // Consecutive voxel faces are neighbours (sorted by position): the faces near them repeat.
      // The cache is bounded by its sub-triangles (a face has 1 to 1,024), about 19 MB a thread.
      std::unordered_map<std::size_t, std::vector<std::array<Point3, 3>>> flattened;
      std::size_t cachedTriangles = 0;
      auto flattening = [&](std::size_t g) -> const std::vector<std::array<Point3, 3>>& {
        auto known = flattened.find(g);
        if (known == flattened.end())
        {
          if (cachedTriangles >= (1u << 18))
            flattened.clear(), cachedTriangles = 0;
          known = flattened.emplace(g, flatten(g)).first;
          cachedTriangles += known->second.size();
        }
        return known->second;
      };
      for (std::size_t index = begin; index < end; ++index)
      {
        long long key = voxelFaces[index];
        const int axis = static_cast<int>(key % 3);
        key /= 3;
        const int i = static_cast<int>(key % nx) - 1, j = static_cast<int>((key / nx) % ny) - 1,
                  k = static_cast<int>(key / (nx * ny)) - 1;
        const ConvexPiece voxel = VoxelFace(i, j, k, axis);
        const Point3 centre = Scale(Add(voxel.Points[0], voxel.Points[2]), 0.5);
        straight.clear(), all.clear(), near.clear();
        // Only pieces within h of some point of the voxel face can certify it (its points are
        // within sqrt(1/2) of its centre): the others are left out of the exact test.
        const double reach = (h + 0.7072) * (h + 0.7072);
        auto inReach = [&](const ConvexPiece& t) {
          return SquaredDistanceToTriangle(centre, t.Points[0], t.Points[1], t.Points[2]) <= reach;
        };
        for (std::size_t g : bins.At({ centre[0], centre[1], centre[2] }))
        {
          // A face lies in the hull of its control points, its straight form too (the corners are
          // control points): a face whose hull's box is out of reach cannot certify the voxel face
          // curved or straight, so it is neither tested nor blamed (and when every curved face is out
          // of reach, the pieces within reach are the linear mesh's, as the decimator certified).
          if (!bounds_(faces[g], m) || SquaredDistanceToBox(centre, hullBox[g][0], hullBox[g][1]) > reach)
            continue;
          if (!FaceIsCurved(mesh, faces[g]))
          {
            const ConvexPiece t = Triangle({ nodes[g][0], nodes[g][1], nodes[g][2] });
            if (inReach(t))
              straight.push_back(t), all.push_back(t);
          }
          else
          {
            near.push_back(g);
            for (const std::array<Point3, 3>& triangle : flattening(g))
            {
              const ConvexPiece t = Triangle(triangle);
              if (inReach(t))
                all.push_back(t);
            }
          }
        }
        if (near.empty())
          continue; // the linear mesh's own boundary here: certified by the decimator
        if (WithinDistance(voxel, straight, h) || WithinDistance(voxel, all, h - T))
          continue;
        blamed[thread].insert(blamed[thread].end(), near.begin(), near.end());
      }
    });
    if (stop)
      throw AbortRequested{};
    for (std::vector<std::size_t>& list : blamed)
    {
      for (std::size_t g : list)
        failing[g] = 1;
      list.clear();
    }
  }
  std::vector<std::size_t> out;
  for (std::size_t f = 0; f < faces.size(); ++f)
    if (failing[f])
      out.push_back(f);
  return out;
}

} // namespace labelmesher
