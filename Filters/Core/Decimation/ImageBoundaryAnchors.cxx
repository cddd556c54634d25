// SPDX-License-Identifier: GPL-2.0-or-later
// Keeps a certificate of h(I,M) for every image boundary face side, re-made locally after each merge.
#include "Decimation/ImageBoundaryAnchors.h"

#include "Support/Geometry.h"
#include "Support/ParallelChunks.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace labelmesher
{
namespace
{

constexpr double kRoundOff = 1e-9;

/// Every corner of `image` within h of `face`: then, by convexity of the
/// distance to a convex set, every point of it is.
bool CornersWithin(const ConvexPiece& image, const ConvexPiece& face, double h)
{
  const double h2 = (h + kRoundOff) * (h + kRoundOff);
  for (int c = 0; c < image.Count; ++c)
  {
    const double d2 = face.Count == 2
      ? geometry::SquaredDistanceToSegment(image.Points[c], face.Points[0], face.Points[1])
      : geometry::SquaredDistanceToTriangle(image.Points[c], face.Points[0], face.Points[1], face.Points[2]);
    if (d2 > h2)
      return false;
  }
  return true;
}

/// Mesh interface faces by the grid bins (of 8 doubled-lattice units, 4
/// voxels) their bounding boxes meet.
class FaceGrid
{
public:
  FaceGrid(const EditableMesh& mesh, const std::vector<InterfaceFace>& faces)
    : Mesh(mesh)
    , Faces(faces)
  {
    // Bins aligned on the box, over the faces' bounding box only: a block of
    // the streamed pipeline is small in the whole mesh's box.
    int low[3], high[3];
    for (int a = 0; a < 3; ++a)
    {
      low[a] = faces.empty() ? mesh.BoxLow[a] : INT32_MAX;
      high[a] = faces.empty() ? mesh.BoxLow[a] : INT32_MIN;
    }
    for (const InterfaceFace& f : faces)
      for (int i = 0; i < mesh.Dimension; ++i)
        for (int a = 0; a < 3; ++a)
        {
          low[a] = std::min(low[a], mesh.Position[f.Vertices[i]][a]);
          high[a] = std::max(high[a], mesh.Position[f.Vertices[i]][a]);
        }
    for (int a = 0; a < 3; ++a)
    {
      Low[a] = mesh.BoxLow[a] + kBin * ((low[a] - mesh.BoxLow[a]) / kBin);
      Bins[a] = (high[a] - Low[a]) / kBin + 1;
    }
    Start.assign(static_cast<std::size_t>(Bins[0]) * Bins[1] * Bins[2] + 1, 0);
    for (int pass = 0; pass < 2; ++pass)
    {
      std::vector<std::uint32_t> next;
      if (pass == 1)
      {
        for (std::size_t b = 0; b + 1 < Start.size(); ++b)
          Start[b + 1] += Start[b];
        Items.resize(Start.back());
        next.assign(Start.begin(), Start.end() - 1);
      }
      for (std::size_t f = 0; f < faces.size(); ++f)
      {
        int lo[3], hi[3];
        Bounds(faces[f], lo, hi);
        for (int z = lo[2]; z <= hi[2]; ++z)
          for (int y = lo[1]; y <= hi[1]; ++y)
            for (int x = lo[0]; x <= hi[0]; ++x)
            {
              const std::size_t bin = Index(x, y, z);
              if (pass == 0)
                ++Start[bin + 1];
              else
                Items[next[bin]++] = static_cast<std::uint32_t>(f);
            }
      }
    }
  }

  /// Faces whose bins meet the index-space box [lo, hi], each once.
  void Query(const Point3& lo, const Point3& hi, std::vector<std::uint32_t>& out) const
  {
    out.clear();
    // Bins beyond the grid hold no face: clipped, not clamped.
    int from[3], to[3];
    for (int a = 0; a < 3; ++a)
    {
      from[a] = std::max(0, Unclamped(std::floor(2.0 * lo[a]), a));
      to[a] = std::min(Bins[a] - 1, Unclamped(std::ceil(2.0 * hi[a]), a));
      if (from[a] > to[a])
        return;
    }
    for (int z = from[2]; z <= to[2]; ++z)
      for (int y = from[1]; y <= to[1]; ++y)
        for (int x = from[0]; x <= to[0]; ++x)
        {
          const std::size_t bin = Index(x, y, z);
          out.insert(out.end(), Items.begin() + Start[bin], Items.begin() + Start[bin + 1]);
        }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
  }

private:
  static constexpr int kBin = 8;
  int Unclamped(double doubled, int axis) const
  {
    return static_cast<int>(std::clamp(std::floor((doubled - Low[axis]) / kBin), -1.0, double(Bins[axis])));
  }
  int BinOf(double doubled, int axis) const { return std::clamp(Unclamped(doubled, axis), 0, Bins[axis] - 1); }
  std::size_t Index(int x, int y, int z) const { return (static_cast<std::size_t>(z) * Bins[1] + y) * Bins[0] + x; }
  void Bounds(const InterfaceFace& f, int lo[3], int hi[3]) const
  {
    for (int a = 0; a < 3; ++a)
    {
      int mn = Mesh.Position[f.Vertices[0]][a], mx = mn;
      for (int i = 1; i < Mesh.Dimension; ++i)
      {
        mn = std::min(mn, Mesh.Position[f.Vertices[i]][a]);
        mx = std::max(mx, Mesh.Position[f.Vertices[i]][a]);
      }
      lo[a] = BinOf(mn, a);
      hi[a] = BinOf(mx, a);
    }
  }
  const EditableMesh& Mesh;
  const std::vector<InterfaceFace>& Faces;
  int Low[3], Bins[3];
  std::vector<std::uint32_t> Start, Items;
};

} // namespace

ConvexPiece MeshFacePiece(const EditableMesh& mesh, const std::array<VertexId, 3>& face)
{
  ConvexPiece piece{ mesh.Dimension, {} };
  for (int i = 0; i < mesh.Dimension; ++i)
  {
    const Lattice& p = mesh.Position[face[i]];
    piece.Points[i] = { p[0] / 2.0, p[1] / 2.0, p[2] / 2.0 };
  }
  return piece;
}

ImageBoundaryAnchors::ImageBoundaryAnchors(const ImageBoundary& boundary, double imageToMesh)
  : Boundary(boundary)
  , H(imageToMesh)
{
  const auto& faces = boundary.Faces();
  for (std::size_t f = 0; f < faces.size(); ++f)
    for (std::int32_t side : { faces[f].Low, faces[f].High })
      if (side != 0)
      {
        ItemFace.push_back(static_cast<std::int32_t>(f));
        ItemSide.push_back(side);
      }
}

std::array<VertexId, 3> ImageBoundaryAnchors::Certify(const EditableMesh& mesh, std::int32_t item,
  const std::vector<InterfaceFace>& faces, VertexId starVertex, std::vector<ConvexPiece>& pieces) const
{
  const ConvexPiece image = Boundary.Piece(static_cast<std::size_t>(ItemFace[item]));
  pieces.clear();
  for (const InterfaceFace& f : faces)
  {
    const ConvexPiece piece = MeshFacePiece(mesh, f.Vertices);
    if (CornersWithin(image, piece, H))
      return f.Vertices;
    pieces.push_back(piece);
  }
  if (starVertex >= 0 && WithinDistance(image, pieces, H))
    return { starVertex, kStar, kStar };
  return { -1, -1, -1 };
}

void ImageBoundaryAnchors::Initialize(const EditableMesh& mesh, const std::vector<InterfaceFace>& faces,
  std::vector<std::uint8_t>& frozen, const std::vector<std::uint8_t>* imageFaces,
  std::vector<std::uint8_t>* uncertified)
{
  Dimension = mesh.Dimension;
  const FaceGrid grid(mesh, faces);
  const std::size_t items = ItemFace.size();
  Anchor.assign(items, { -1, -1, -1 });
  std::vector<std::vector<VertexId>> pinnedVertices(items);
  std::vector<std::int32_t> failures(MaxThreads(), -1);
  std::vector<std::vector<std::int32_t>> missed(MaxThreads()); // with `uncertified`
  ParallelChunks(items, 1024, [&](unsigned thread, std::size_t begin, std::size_t end) {
    std::vector<std::uint32_t> near;
    std::vector<InterfaceFace> candidates, star;
    std::vector<ConvexPiece> pieces;
    std::vector<VertexId> vertices;
    for (std::size_t item = begin; item < end; ++item)
    {
      if (imageFaces && !(*imageFaces)[static_cast<std::size_t>(ItemFace[item])])
        continue;
      const ConvexPiece image = Boundary.Piece(static_cast<std::size_t>(ItemFace[item]));
      Point3 lo, hi;
      BoxAround(image, H + 1e-6, lo, hi);
      grid.Query(lo, hi, near);
      candidates.clear();
      for (std::uint32_t f : near)
        if (faces[f].Separates(ItemSide[item]))
          candidates.push_back(faces[f]);
      auto anchor = Certify(mesh, static_cast<std::int32_t>(item), candidates, -1, pieces);
      if (anchor[0] < 0)
      {
        // A star that certifies it: the faces around one vertex of the candidates.
        vertices.clear();
        for (const InterfaceFace& f : candidates)
          vertices.insert(vertices.end(), f.Vertices.begin(), f.Vertices.begin() + Dimension);
        std::sort(vertices.begin(), vertices.end());
        vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
        for (VertexId v : vertices)
        {
          star.clear();
          for (const InterfaceFace& f : candidates)
            if (f.Contains(v))
              star.push_back(f);
          anchor = Certify(mesh, static_cast<std::int32_t>(item), star, v, pieces);
          if (anchor[0] >= 0)
            break;
        }
      }
      if (anchor[0] < 0)
      {
        pieces.clear();
        for (const InterfaceFace& f : candidates)
          pieces.push_back(MeshFacePiece(mesh, f.Vertices));
        if (!WithinDistance(image, pieces, H))
        {
          if (uncertified)
            missed[thread].push_back(ItemFace[item]);
          else if (failures[thread] < 0)
            failures[thread] = static_cast<std::int32_t>(item);
          continue;
        }
        anchor = { kPinned, kPinned, kPinned };
        pinnedVertices[item] = vertices;
      }
      Anchor[item] = anchor;
    }
  });
  for (std::int32_t failure : failures)
    if (failure >= 0)
    {
      const auto& face = Boundary.Faces()[static_cast<std::size_t>(ItemFace[failure])];
      throw std::invalid_argument("the input mesh does not hold h(I,M) <= " + std::to_string(H) +
        ": the image face of voxel (" + std::to_string(face.Voxel[0]) + ", " + std::to_string(face.Voxel[1]) + ", " +
        std::to_string(face.Voxel[2]) + ") is farther from the mesh boundary of material " +
        std::to_string(ItemSide[failure]) + " (mesh it with this bound or a smaller one first)");
    }

  for (const auto& list : missed)
    for (std::int32_t face : list)
      (*uncertified)[static_cast<std::size_t>(face)] = 1;

  ItemsAt.assign(mesh.Position.size(), {});
  PrunedSize.assign(mesh.Position.size(), 0);
  StarAnchors.assign(mesh.Position.size(), 0);
  for (std::size_t item = 0; item < items; ++item)
  {
    const auto& anchor = Anchor[item];
    if (anchor[0] == -1)
      continue; // not selected
    if (anchor[0] == kPinned)
    {
      for (VertexId v : pinnedVertices[item])
        frozen[v] = 1;
      continue;
    }
    if (IsStar(anchor))
    {
      ItemsAt[anchor[0]].push_back(static_cast<std::int32_t>(item));
      ++StarAnchors[anchor[0]];
      continue;
    }
    for (int i = 0; i < Dimension; ++i)
      ItemsAt[anchor[i]].push_back(static_cast<std::int32_t>(item));
  }
}

bool ImageBoundaryAnchors::Mentions(std::int32_t item, VertexId v) const
{
  const auto& anchor = Anchor[item];
  if (anchor[0] == kPinned)
    return false;
  if (IsStar(anchor))
    return anchor[0] == v;
  return anchor[0] == v || anchor[1] == v || anchor[2] == v;
}

bool ImageBoundaryAnchors::Recertify(
  const EditableMesh& mesh, const EdgeCollapse& merge, std::vector<Update>& updates) const
{
  updates.clear();
  const VertexId a = merge.From, b = merge.To;
  thread_local std::vector<std::int32_t> affected;
  thread_local std::vector<VertexId> around;
  thread_local std::vector<InterfaceFace> faces;
  thread_local std::vector<ConvexPiece> pieces;
  affected.clear();
  for (std::int32_t item : ItemsAt[a])
    if (Mentions(item, a))
      affected.push_back(item);
  // Star certificates of b and of a's neighbours rest on faces the merge changes.
  around.assign(1, b);
  for (const auto* list : { &merge.Moved, &merge.Removed })
    for (CellId c : *list)
      for (int i = 0; i < mesh.VerticesPerCell(); ++i)
        if (mesh.Cells[c][i] != a)
          around.push_back(mesh.Cells[c][i]);
  std::sort(around.begin(), around.end());
  around.erase(std::unique(around.begin(), around.end()), around.end());
  for (VertexId v : around)
    if (StarAnchors[v] > 0)
      for (std::int32_t item : ItemsAt[v])
        if (IsStar(Anchor[item]) && Anchor[item][0] == v)
          affected.push_back(item);
  std::sort(affected.begin(), affected.end());
  affected.erase(std::unique(affected.begin(), affected.end()), affected.end());

  for (std::int32_t item : affected)
  {
    faces.clear();
    for (const InterfaceFace& f : merge.After)
      if (f.Separates(ItemSide[item]))
        faces.push_back(f);
    const auto anchor = Certify(mesh, item, faces, b, pieces);
    if (anchor[0] < 0)
      return false;
    updates.push_back({ item, anchor });
  }
  return true;
}

void ImageBoundaryAnchors::Register(std::int32_t item, VertexId v)
{
  auto& list = ItemsAt[v];
  list.push_back(item);
  if (!Shared && list.size() >= 2 * std::max<std::size_t>(16, PrunedSize[v]))
  {
    // Drop entries whose certificate has moved on, and repeats.
    list.erase(std::remove_if(list.begin(), list.end(), [&](std::int32_t i) { return !Mentions(i, v); }), list.end());
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
    PrunedSize[v] = static_cast<std::uint32_t>(list.size());
  }
}

void ImageBoundaryAnchors::Commit(const EdgeCollapse& merge, const std::vector<Update>& updates)
{
  for (const Update& u : updates)
  {
    if (IsStar(Anchor[u.Item]))
      --StarAnchors[Anchor[u.Item][0]];
    Anchor[u.Item] = u.Anchor;
    if (IsStar(u.Anchor))
    {
      ++StarAnchors[u.Anchor[0]];
      Register(u.Item, u.Anchor[0]);
    }
    else
      for (int i = 0; i < Dimension; ++i)
        Register(u.Item, u.Anchor[i]);
  }
  ItemsAt[merge.From].clear();
  ItemsAt[merge.From].shrink_to_fit();
}

} // namespace labelmesher
