// SPDX-License-Identifier: GPL-2.0-or-later
// The decimator's mesh: doubled-lattice integer points, cell incidence, strata of the box.
#include "Decimation/EditableMesh.h"

#include "Support/ParallelChunks.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace labelmesher
{

bool operator<(const InterfaceFace& a, const InterfaceFace& b)
{
  if (a.Vertices != b.Vertices)
    return a.Vertices < b.Vertices;
  if (a.Low != b.Low)
    return a.Low < b.Low;
  return a.High < b.High;
}

bool operator==(const InterfaceFace& a, const InterfaceFace& b)
{
  return a.Vertices == b.Vertices && a.Low == b.Low && a.High == b.High;
}

long long EditableMesh::Orientation(int dimension, const Lattice* p)
{
  // Coordinates are below 2^24 (checked on construction). Below 2^18 the
  // products fit 64 bits; beyond, 128.
  const long long ux = p[1][0] - p[0][0], uy = p[1][1] - p[0][1], vx = p[2][0] - p[0][0], vy = p[2][1] - p[0][1];
  if (dimension == 2)
    return ux * vy - uy * vx;
  const long long uz64 = p[1][2] - p[0][2], vz64 = p[2][2] - p[0][2];
  const long long wx64 = p[3][0] - p[0][0], wy64 = p[3][1] - p[0][1], wz64 = p[3][2] - p[0][2];
  constexpr long long kSmall = 1 << 19;
  if (std::abs(ux) < kSmall && std::abs(uy) < kSmall && std::abs(uz64) < kSmall && std::abs(vx) < kSmall &&
    std::abs(vy) < kSmall && std::abs(vz64) < kSmall && std::abs(wx64) < kSmall && std::abs(wy64) < kSmall &&
    std::abs(wz64) < kSmall)
  {
    const long long det = ux * (vy * wz64 - vz64 * wy64) - uy * (vx * wz64 - vz64 * wx64) + uz64 * (vx * wy64 - vy * wx64);
    return det > 0 ? 1 : (det < 0 ? -1 : 0);
  }
  const __int128 uz = p[1][2] - p[0][2], vz = p[2][2] - p[0][2];
  const __int128 wx = p[3][0] - p[0][0], wy = p[3][1] - p[0][1], wz = p[3][2] - p[0][2];
  const __int128 det = __int128(ux) * (vy * wz - vz * wy) - __int128(uy) * (vx * wz - vz * wx) +
    uz * (__int128(vx) * wy - __int128(vy) * wx);
  return det > 0 ? 1 : (det < 0 ? -1 : 0);
}

EditableMesh::EditableMesh(const SimplexMesh& mesh)
{
  Build(mesh, nullptr, nullptr);
}

EditableMesh::EditableMesh(SimplexMesh&& mesh)
{
  Build(mesh, &mesh, nullptr);
}

EditableMesh::EditableMesh(SimplexMesh&& mesh, const Lattice& boxLow, const Lattice& boxHigh)
{
  const Lattice box[2] = { boxLow, boxHigh };
  Build(mesh, &mesh, box);
}

void EditableMesh::Build(const SimplexMesh& mesh, SimplexMesh* release, const Lattice* box)
{
  Dimension = mesh.Dimension;
  if (Dimension != 2 && Dimension != 3)
    throw std::invalid_argument("the mesh is neither triangles nor tetrahedra");
  const int nv = VerticesPerCell();
  const std::size_t points = mesh.Points.size(), cells = mesh.NumberOfCells();
  if (cells == 0)
    throw std::invalid_argument("the mesh has no cells");
  if (points >= (std::size_t(1) << 31) || cells >= (std::size_t(1) << 31))
    throw std::invalid_argument("the mesh has more than 2^31 points or cells");
  Position.resize(points);
  for (std::size_t p = 0; p < points; ++p)
    for (int a = 0; a < 3; ++a)
    {
      const double doubled = 2.0 * mesh.Points[p][a];
      const double rounded = std::round(doubled);
      if (!(std::abs(doubled - rounded) <= 1e-6) || std::abs(rounded) >= double(1 << 24))
        throw std::invalid_argument("mesh point " + std::to_string(p) +
          " is not on the half-voxel lattice of the image: the mesh does not come from this image's mesher");
      Position[p][a] = static_cast<std::int32_t>(rounded);
    }
  if (release)
    std::vector<Point3>().swap(release->Points);
  Cells.resize(cells);
  Labels.assign(mesh.Materials.begin(), mesh.Materials.end());
  if (release)
    std::vector<std::int32_t>().swap(release->Materials);
  CellAlive.assign(cells, 1);
  CellsOf.resize(points);
  for (std::size_t c = 0; c < cells; ++c)
  {
    Cells[c] = { -1, -1, -1, -1 };
    Lattice p[4];
    for (int i = 0; i < nv; ++i)
    {
      const std::int64_t id = mesh.Connectivity[c * nv + i];
      if (id < 0 || static_cast<std::size_t>(id) >= points)
        throw std::invalid_argument("cell " + std::to_string(c) + " refers to a missing point");
      Cells[c][i] = static_cast<VertexId>(id);
      p[i] = Position[id];
    }
    if (Labels[c] < 0)
      throw std::invalid_argument("cell " + std::to_string(c) + " has a negative material");
    if (Orientation(Dimension, p) <= 0)
      throw std::invalid_argument("cell " + std::to_string(c) + " is inverted or flat");
  }
  if (release)
    std::vector<std::int64_t>().swap(release->Connectivity);
  // Exact capacities: grown by push_back, the lists would hold up to twice
  // their cells, on the largest structure of the run.
  {
    std::vector<std::uint32_t> degree(points, 0);
    for (std::size_t c = 0; c < cells; ++c)
      for (int i = 0; i < nv; ++i)
        ++degree[Cells[c][i]];
    for (std::size_t v = 0; v < points; ++v)
      CellsOf[v].reserve(degree[v]);
  }
  for (std::size_t c = 0; c < cells; ++c)
    for (int i = 0; i < nv; ++i)
      CellsOf[Cells[c][i]].push_back(static_cast<CellId>(c));

  // The box: the bounding box of the points, or a piece's given box.
  BoxLow = Position[Cells[0][0]];
  BoxHigh = BoxLow;
  for (std::size_t p = 0; p < points; ++p)
  {
    if (CellsOf[p].empty())
      continue;
    for (int a = 0; a < 3; ++a)
    {
      BoxLow[a] = std::min(BoxLow[a], Position[p][a]);
      BoxHigh[a] = std::max(BoxHigh[a], Position[p][a]);
    }
  }
  if (box)
  {
    for (int a = 0; a < Dimension; ++a)
      if (BoxLow[a] < box[0][a] || BoxHigh[a] > box[1][a])
        throw std::invalid_argument("a point of the piece lies outside the box it was given");
    BoxLow = box[0];
    BoxHigh = box[1];
  }
  BoxPlanes.assign(points, 0);
  for (std::size_t p = 0; p < points; ++p)
    for (int a = 0; a < Dimension; ++a)
    {
      if (Position[p][a] == BoxLow[a])
        BoxPlanes[p] |= std::uint8_t(1u << (2 * a));
      if (Position[p][a] == BoxHigh[a])
        BoxPlanes[p] |= std::uint8_t(1u << (2 * a + 1));
    }

  // Every face has at most two cells, and a face with one lies on the box
  // (or, in a piece, on its border).
  std::vector<std::size_t> problems(MaxThreads(), cells);
  std::vector<int> kinds(MaxThreads(), 0);
  std::vector<std::vector<VertexId>> border(MaxThreads());
  ParallelChunks(points, 4096, [&](unsigned thread, std::size_t begin, std::size_t end) {
    std::vector<FaceUse> scratch;
    for (std::size_t v = begin; v < end; ++v)
      ForEachFaceFrom(static_cast<VertexId>(v), scratch, [&](const FaceUse* uses, std::size_t count) {
        int kind = 0;
        if (count > 2)
          kind = 1;
        else if (count == 1 && OutsidePlane(uses[0].Vertices) < 0)
        {
          if (box)
            border[thread].insert(border[thread].end(), uses[0].Vertices.begin(), uses[0].Vertices.begin() + Dimension);
          else
            kind = 2;
        }
        if (kind != 0 && static_cast<std::size_t>(uses[0].Cell) < problems[thread])
        {
          problems[thread] = static_cast<std::size_t>(uses[0].Cell);
          kinds[thread] = kind;
        }
      });
  });
  std::size_t first = cells;
  int kind = 0;
  for (std::size_t t = 0; t < problems.size(); ++t)
    if (problems[t] < first)
    {
      first = problems[t];
      kind = kinds[t];
    }
  if (kind == 1)
    throw std::invalid_argument("a face of cell " + std::to_string(first) + " is shared by more than two cells");
  if (box)
  {
    Border.assign(points, 0);
    for (const auto& list : border)
      for (VertexId v : list)
        Border[v] = 1;
  }
  if (kind == 2)
    throw std::invalid_argument("a face of cell " + std::to_string(first) +
      " has one cell but is not on the mesh's bounding box: the mesh must fill its box (keep the background "
      "cells, Material 0, e.g. vtkLabelOctreeMesher with IncludeBackground on)");
}

int EditableMesh::OutsidePlane(const std::array<VertexId, 3>& face) const
{
  std::uint8_t planes = 0xff;
  for (int i = 0; i < Dimension; ++i)
    planes &= BoxPlanes[face[i]];
  for (int plane = 0; plane < 6; ++plane)
    if (planes & (1u << plane))
      return plane;
  return -1;
}

std::vector<InterfaceFace> EditableMesh::InterfaceFaces() const
{
  // Per chunk of vertices, merged in vertex order: the same list on any
  // number of threads.
  const std::size_t chunk = 16384, chunks = (Position.size() + chunk - 1) / chunk;
  std::vector<std::vector<InterfaceFace>> parts(chunks);
  ParallelChunks(chunks, 1, [&](unsigned, std::size_t begin, std::size_t end) {
    std::vector<FaceUse> scratch;
    for (std::size_t part = begin; part < end; ++part)
      for (std::size_t v = part * chunk; v < std::min(Position.size(), (part + 1) * chunk); ++v)
        ForEachFaceFrom(static_cast<VertexId>(v), scratch, [&](const FaceUse* uses, std::size_t count) {
          const std::int32_t inside = Labels[uses[0].Cell];
          const int plane = count == 2 ? -1 : OutsidePlane(uses[0].Vertices);
          if (count == 1 && plane < 0)
            return; // a piece's border: the other side is not here
          const std::int32_t other = count == 2 ? Labels[uses[1].Cell] : OutsideLabel(plane);
          if (other != inside)
            parts[part].push_back(InterfaceFace{ uses[0].Vertices, std::min(inside, other), std::max(inside, other) });
        });
  });
  std::vector<InterfaceFace> faces;
  for (auto& part : parts)
    faces.insert(faces.end(), part.begin(), part.end());
  return faces;
}

bool EditableMesh::Contains(CellId c, VertexId v) const
{
  const auto& cell = Cells[c];
  return cell[0] == v || cell[1] == v || cell[2] == v || (Dimension == 3 && cell[3] == v);
}

std::size_t EditableMesh::AliveCells() const
{
  return static_cast<std::size_t>(std::count(CellAlive.begin(), CellAlive.end(), std::uint8_t(1)));
}

std::size_t EditableMesh::AliveVertices() const
{
  std::size_t n = 0;
  for (const auto& list : CellsOf)
    n += !list.empty();
  return n;
}

SimplexMesh EditableMesh::ToSimplexMesh() const
{
  SimplexMesh out;
  out.Dimension = Dimension;
  const int nv = VerticesPerCell();
  std::vector<std::int64_t> renumber(Position.size(), -1);
  for (std::size_t c = 0; c < Cells.size(); ++c)
  {
    if (!CellAlive[c])
      continue;
    for (int i = 0; i < nv; ++i)
    {
      const VertexId v = Cells[c][i];
      if (renumber[v] < 0)
      {
        renumber[v] = static_cast<std::int64_t>(out.Points.size());
        out.Points.push_back({ Position[v][0] / 2.0, Position[v][1] / 2.0, Dimension == 2 ? 0.0 : Position[v][2] / 2.0 });
      }
      out.Connectivity.push_back(renumber[v]);
    }
    out.Materials.push_back(Labels[c]);
  }
  return out;
}

} // namespace labelmesher
