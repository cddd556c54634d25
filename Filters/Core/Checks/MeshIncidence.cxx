// SPDX-License-Identifier: GPL-2.0-or-later
// The vertex-to-cell incidence and the distinct facets and edges of a simplex mesh, for the checks only.
#include "Checks/MeshIncidence.h"

#include <stdexcept>

namespace labelmesher
{
namespace checks_detail
{

VertexIncidence BuildVertexIncidence(const SimplexMesh& mesh)
{
  if (mesh.NumberOfCells() > 0xffffffffull)
    throw std::length_error("MeshChecks: more than 2^32 cells");
  VertexIncidence inc;
  const std::size_t np = mesh.Points.size();
  const int nv = mesh.VerticesPerCell();
  inc.Offsets.assign(np + 1, 0);
  for (std::size_t c = 0; c < mesh.NumberOfCells(); ++c)
  {
    const std::int64_t* cv = mesh.Cell(c);
    for (int q = 0; q < nv; ++q)
      if (cv[q] >= 0 && static_cast<std::size_t>(cv[q]) < np)
        ++inc.Offsets[cv[q] + 1];
  }
  for (std::size_t v = 0; v < np; ++v)
    inc.Offsets[v + 1] += inc.Offsets[v];
  inc.Cells.resize(inc.Offsets[np]);
  std::vector<std::int64_t> fill(inc.Offsets.begin(), inc.Offsets.end() - 1);
  for (std::size_t c = 0; c < mesh.NumberOfCells(); ++c)
  {
    const std::int64_t* cv = mesh.Cell(c);
    for (int q = 0; q < nv; ++q)
      if (cv[q] >= 0 && static_cast<std::size_t>(cv[q]) < np)
        inc.Cells[fill[cv[q]]++] = static_cast<std::uint32_t>(c);
  }
  return inc;
}

std::vector<BoundaryFacetRecord> ExtractMeshBoundary(
  const SimplexMesh& mesh, const VertexIncidence& incidence)
{
  // Parallel over vertex ranges; records concatenated in range order, so the
  // result does not depend on the number of threads.
  constexpr std::size_t Chunk = 4096;
  const std::size_t np = incidence.NumberOfPoints();
  std::vector<std::vector<BoundaryFacetRecord>> perChunk((np + Chunk - 1) / Chunk);
  ParallelChunks(np, Chunk, [&](unsigned, std::size_t first, std::size_t last) {
    std::vector<BoundaryFacetRecord>& records = perChunk[first / Chunk];
    std::vector<std::int32_t> mats;
    ForEachFacet(mesh, incidence, first, last,
      [&](const std::array<std::int64_t, 3>& facet, const std::uint32_t* cells, std::size_t count) {
        mats.clear();
        for (std::size_t i = 0; i < count; ++i)
          mats.push_back(mesh.Materials[cells[i]]);
        std::sort(mats.begin(), mats.end());
        const bool mixed = mats.front() != mats.back();
        if (count != 1 && !mixed)
          return; // interior facet of one material
        mats.erase(std::unique(mats.begin(), mats.end()), mats.end());
        bool first = true;
        for (std::int32_t m : mats)
        {
          if (m == 0)
            continue;
          records.push_back({ facet, m, first });
          first = false;
        }
      });
  });
  std::size_t total = 0;
  for (const auto& r : perChunk)
    total += r.size();
  std::vector<BoundaryFacetRecord> records;
  records.reserve(total);
  for (const auto& r : perChunk)
    records.insert(records.end(), r.begin(), r.end());
  return records;
}

} // namespace checks_detail
} // namespace labelmesher
