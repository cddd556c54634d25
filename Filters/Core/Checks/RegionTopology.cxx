// SPDX-License-Identifier: GPL-2.0-or-later
/**
 * @file RegionTopology.cxx
 * CompareTopology: the topological guarantee of the ORD mesh (dissertation
 * section 2.3 and 3.2): every material region of the mesh has the same number
 * of connected components and the same Euler characteristic as the union of
 * the closed voxels of that label.
 *
 * Image side (closed voxels, a cubical complex):
 *  - the labels are first copied into a padded volume of compact material
 *    indices (one voxel of background all around, so no bounds checks), one
 *    byte per voxel up to 255 materials (a LabelImage);
 *  - chi = V - E + F - C is a streaming count: every lattice vertex, edge,
 *    face and voxel is visited once and counted for each distinct material
 *    among the (8, 4, 2, 1) voxels incident to it. O(voxels), no hashing.
 *  - components of closed voxels = 26-connected (8 in 2D) voxel components,
 *    found by a two-slice scan with union-find on provisional labels (memory:
 *    two slices plus one entry per provisional label).
 * Mesh side (closed cells, a simplicial complex):
 *  - every vertex v looks at its incident cells grouped by material and counts
 *    the edges and triangles of which it is the smallest vertex (so each is
 *    counted once per material), plus itself; chi = V - E + F - T.
 *  - components: union-find over cells, joining cells of one material that
 *    share a vertex.
 */

#include "Checks/MeshChecks.h"
#include "Support/UnionFind.h"

#include "Checks/MeshIncidence.h"

#include <algorithm>
#include <numeric>
#include <unordered_map>

namespace labelmesher
{

namespace
{

struct Counts
{
  long long V = 0, E = 0, F = 0, C = 0;
};


/// Distinct non-zero values among v[0..n): calls f(value) once for each.
template <class F>
inline void ForEachDistinct(const std::int32_t* v, int n, F&& f)
{
  for (int t = 0; t < n; ++t)
  {
    if (v[t] == 0)
      continue;
    bool seen = false;
    for (int s = 0; s < t && !seen; ++s)
      seen = v[s] == v[t];
    if (!seen)
      f(v[t]);
  }
}

/// Image side. `index` maps compact material index (1..M) to the label.
void ImageTopology(const LabelImage& image, std::map<std::int32_t, TopologyComparison>& out)
{
  const int nx = image.Dimensions[0], ny = image.Dimensions[1], nz = image.Dimensions[2];
  if (nx <= 0 || ny <= 0 || nz <= 0 || image.NumberOfVoxels() == 0)
    return;
  // Compact material indices.
  std::vector<std::int32_t> labels; // compact index -> label (0 -> 0)
  labels.push_back(0);
  std::unordered_map<std::int32_t, std::int32_t> toIndex;
  std::int32_t lastLabel = 0, lastIndex = 0;
  auto compact = [&](std::int32_t l) -> std::int32_t {
    if (l == 0)
      return 0;
    if (l == lastLabel)
      return lastIndex;
    auto it = toIndex.find(l);
    if (it == toIndex.end())
    {
      it = toIndex.emplace(l, static_cast<std::int32_t>(labels.size())).first;
      labels.push_back(l);
    }
    lastLabel = l;
    lastIndex = it->second;
    return lastIndex;
  };
  const bool is2D = nz == 1;
  const int px = nx + 2, py = ny + 2, pz = is2D ? 1 : nz + 2;
  const std::int64_t sx = 1, sy = px, sz = static_cast<std::int64_t>(px) * py;
  const int kOff = is2D ? 0 : 1;
  // As narrow as the number of materials allows (LabelImage): at 1024^3 the int32 copy was 4 GiB.
  LabelImage padded(px, py, pz);
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
    {
      image.WithLabels([&](const auto* labels) {
        const auto* src = labels + image.Index(0, j, k);
        const std::size_t dst = static_cast<std::size_t>((k + kOff) * sz + (j + 1) * sy + 1);
        for (int i = 0; i < nx; ++i)
          padded.SetLabel(dst + static_cast<std::size_t>(i), compact(src[i]));
      });
    }
  padded.WithLabels([&](const auto* q) {
    const std::size_t M = labels.size();
    std::vector<Counts> counts(M);
    auto Q = [&](int i, int j, int k) { return q + k * sz + j * sy + i * sx; };

    // Euler characteristic by streaming counts over lattice elements. Padded
    // voxel (i, j, k) is image voxel (i-1, j-1, k-1) (k unshifted in 2D).
    std::int32_t buf[8];
    if (is2D)
    {
      for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i)
        {
          const auto* p = Q(i, j, 0); // pixels (i..i+1, j..j+1)
          buf[0] = p[0]; buf[1] = p[1]; buf[2] = p[sy]; buf[3] = p[sy + 1];
          ForEachDistinct(buf, 4, [&](std::int32_t m) { ++counts[m].V; });
          if (i < nx) // edge along x at lattice y = j: pixels (i+1, j..j+1)
          {
            buf[0] = p[1]; buf[1] = p[sy + 1];
            ForEachDistinct(buf, 2, [&](std::int32_t m) { ++counts[m].E; });
          }
          if (j < ny) // edge along y at lattice x = i: pixels (i..i+1, j+1)
          {
            buf[0] = p[sy]; buf[1] = p[sy + 1];
            ForEachDistinct(buf, 2, [&](std::int32_t m) { ++counts[m].E; });
          }
          if (i < nx && j < ny && p[sy + 1] != 0)
            ++counts[p[sy + 1]].F;
        }
    }
    else
    {
      for (int k = 0; k <= nz; ++k)
        for (int j = 0; j <= ny; ++j)
          for (int i = 0; i <= nx; ++i)
          {
            const auto* p = Q(i, j, k); // voxels (i..i+1, j..j+1, k..k+1)
            const std::int32_t v000 = p[0], v100 = p[1], v010 = p[sy], v110 = p[sy + 1],
                               v001 = p[sz], v101 = p[sz + 1], v011 = p[sz + sy],
                               v111 = p[sz + sy + 1];
            if ((v000 | v100 | v010 | v110 | v001 | v101 | v011 | v111) == 0)
              continue; // nothing incident anywhere in this block
            buf[0] = v000; buf[1] = v100; buf[2] = v010; buf[3] = v110;
            buf[4] = v001; buf[5] = v101; buf[6] = v011; buf[7] = v111;
            ForEachDistinct(buf, 8, [&](std::int32_t m) { ++counts[m].V; });
            if (i < nx) // x-edge: voxels (i+1, j..j+1, k..k+1)
            {
              buf[0] = v100; buf[1] = v110; buf[2] = v101; buf[3] = v111;
              ForEachDistinct(buf, 4, [&](std::int32_t m) { ++counts[m].E; });
            }
            if (j < ny) // y-edge: voxels (i..i+1, j+1, k..k+1)
            {
              buf[0] = v010; buf[1] = v110; buf[2] = v011; buf[3] = v111;
              ForEachDistinct(buf, 4, [&](std::int32_t m) { ++counts[m].E; });
            }
            if (k < nz) // z-edge: voxels (i..i+1, j..j+1, k+1)
            {
              buf[0] = v001; buf[1] = v101; buf[2] = v011; buf[3] = v111;
              ForEachDistinct(buf, 4, [&](std::int32_t m) { ++counts[m].E; });
            }
            if (j < ny && k < nz) // x-face: voxels (i..i+1, j+1, k+1)
            {
              buf[0] = v011; buf[1] = v111;
              ForEachDistinct(buf, 2, [&](std::int32_t m) { ++counts[m].F; });
            }
            if (i < nx && k < nz) // y-face: voxels (i+1, j..j+1, k+1)
            {
              buf[0] = v101; buf[1] = v111;
              ForEachDistinct(buf, 2, [&](std::int32_t m) { ++counts[m].F; });
            }
            if (i < nx && j < ny) // z-face: voxels (i+1, j+1, k..k+1)
            {
              buf[0] = v110; buf[1] = v111;
              ForEachDistinct(buf, 2, [&](std::int32_t m) { ++counts[m].F; });
            }
            if (i < nx && j < ny && k < nz && v111 != 0)
              ++counts[v111].C;
          }
    }

    // Components: two-slice scan, 26- (8-) connectivity, union-find on provisional ids.
    UnionFind uf;
    std::vector<std::int32_t> materialOf; // provisional id -> compact material
    const std::size_t slice = static_cast<std::size_t>(px) * py;
    std::vector<std::int64_t> prev(slice, -1), cur(slice, -1);
    for (int k = 0; k < nz; ++k)
    {
      std::fill(cur.begin(), cur.end(), -1);
      for (int j = 1; j <= ny; ++j)
        for (int i = 1; i <= nx; ++i)
        {
          const std::int32_t m = *Q(i, j, k + kOff);
          if (m == 0)
            continue;
          const std::size_t s = static_cast<std::size_t>(j) * px + i;
          std::int64_t id = -1;
          auto join = [&](std::int64_t other) {
            if (other < 0 || materialOf[other] != m)
              return;
            id = static_cast<std::int64_t>(id < 0 ? uf.Find(static_cast<std::size_t>(other))
                                                  : uf.Unite(static_cast<std::size_t>(id), static_cast<std::size_t>(other)));
          };
          join(cur[s - 1]);
          join(cur[s - px - 1]);
          join(cur[s - px]);
          join(cur[s - px + 1]);
          if (!is2D && k > 0)
            for (int dj = -1; dj <= 1; ++dj)
              for (int di = -1; di <= 1; ++di)
                join(prev[s + dj * px + di]);
          if (id < 0)
          {
            id = static_cast<std::int64_t>(uf.Add());
            materialOf.push_back(m);
          }
          cur[s] = id;
        }
      std::swap(prev, cur);
    }
    std::vector<std::size_t> components(M, 0);
    for (std::size_t id = 0; id < materialOf.size(); ++id)
      if (uf.IsRoot(id))
        ++components[materialOf[id]];

    for (std::size_t m = 1; m < M; ++m)
    {
      RegionTopology& t = out[labels[m]].Image;
      t.Components = components[m];
      t.EulerCharacteristic = counts[m].V - counts[m].E + counts[m].F - counts[m].C;
    }
  });
}

void MeshTopology(const SimplexMesh& mesh, std::map<std::int32_t, TopologyComparison>& out)
{
  const std::size_t nc = mesh.NumberOfCells();
  if (nc == 0)
    return;
  std::vector<std::int32_t> labels(mesh.Materials.begin(), mesh.Materials.end());
  std::sort(labels.begin(), labels.end());
  labels.erase(std::unique(labels.begin(), labels.end()), labels.end());
  auto indexOf = [&](std::int32_t l) {
    return static_cast<std::size_t>(std::lower_bound(labels.begin(), labels.end(), l) - labels.begin());
  };
  std::vector<std::uint32_t> cellMaterial(nc);
  for (std::size_t c = 0; c < nc; ++c)
    cellMaterial[c] = static_cast<std::uint32_t>(indexOf(mesh.Materials[c]));
  const std::size_t M = labels.size();
  std::vector<Counts> counts(M);
  for (std::size_t c = 0; c < nc; ++c)
    ++counts[cellMaterial[c]].C;

  const checks_detail::VertexIncidence inc = checks_detail::BuildVertexIncidence(mesh);
  const int nv = mesh.VerticesPerCell();
  UnionFind uf;
  uf.Reset(nc);
  std::vector<std::uint32_t> local;
  std::vector<std::int64_t> edges;
  std::vector<std::pair<std::int64_t, std::int64_t>> faces;
  for (std::size_t v = 0; v < inc.NumberOfPoints(); ++v)
  {
    local.assign(inc.Begin(v), inc.End(v));
    std::sort(local.begin(), local.end(), [&](std::uint32_t a, std::uint32_t b) {
      return cellMaterial[a] != cellMaterial[b] ? cellMaterial[a] < cellMaterial[b] : a < b;
    });
    const std::int64_t vid = static_cast<std::int64_t>(v);
    for (std::size_t g = 0; g < local.size();)
    {
      std::size_t h = g;
      const std::uint32_t m = cellMaterial[local[g]];
      edges.clear();
      faces.clear();
      while (h < local.size() && cellMaterial[local[h]] == m)
      {
        const std::uint32_t c = local[h];
        if (h > g)
          uf.Unite(local[g], c);
        const std::int64_t* cv = mesh.Cell(c);
        std::int64_t greater[3];
        int n = 0;
        for (int q = 0; q < nv; ++q)
          if (cv[q] > vid && n < 3)
            greater[n++] = cv[q];
        for (int a = 1; a < n; ++a) // insertion sort of at most 3 ids
          for (int b = a; b > 0 && greater[b - 1] > greater[b]; --b)
            std::swap(greater[b - 1], greater[b]);
        for (int a = 0; a < n; ++a)
          edges.push_back(greater[a]);
        if (nv == 4)
          for (int a = 0; a < n; ++a)
            for (int b = a + 1; b < n; ++b)
              faces.emplace_back(greater[a], greater[b]);
        ++h;
      }
      std::sort(edges.begin(), edges.end());
      std::sort(faces.begin(), faces.end());
      Counts& cm = counts[m];
      ++cm.V;
      cm.E += std::unique(edges.begin(), edges.end()) - edges.begin();
      cm.F += std::unique(faces.begin(), faces.end()) - faces.begin();
      g = h;
    }
  }
  std::vector<std::size_t> components(M, 0);
  for (std::size_t c = 0; c < nc; ++c)
    if (uf.IsRoot(c))
      ++components[cellMaterial[c]];
  for (std::size_t m = 0; m < M; ++m)
  {
    if (labels[m] == 0)
      continue;
    RegionTopology& t = out[labels[m]].Mesh;
    t.Components = components[m];
    // In 2D the cells are the triangles themselves (F counts them, no 3-cells).
    t.EulerCharacteristic = nv == 4 ? counts[m].V - counts[m].E + counts[m].F - counts[m].C
                                    : counts[m].V - counts[m].E + counts[m].C;
  }
}

} // namespace

std::map<std::int32_t, TopologyComparison> CompareTopology(
  const LabelImage& image, const SimplexMesh& mesh)
{
  std::map<std::int32_t, TopologyComparison> result;
  ImageTopology(image, result);
  MeshTopology(mesh, result);
  return result;
}

} // namespace labelmesher
