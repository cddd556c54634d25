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
/// voxels) their bounding boxes meet. Each entry carries its face's box, so
/// that a query tests it without reaching for the face's vertices: a bin of
/// the voxel-exact mesh of a many-label image holds hundreds of faces, few of
/// them near a given image face (digimouse: ~400 to a query, ~120 near).
class FaceGrid
{
public:
  FaceGrid(const EditableMesh& mesh, const std::vector<InterfaceFace>& faces)
  {
    std::vector<Entry> boxes(faces.size());
    for (std::size_t f = 0; f < faces.size(); ++f)
    {
      Entry& e = boxes[f];
      e.Face = static_cast<std::uint32_t>(f);
      e.Low = e.High = mesh.Position[faces[f].Vertices[0]];
      for (int i = 1; i < mesh.Dimension; ++i)
        for (int a = 0; a < 3; ++a)
        {
          e.Low[a] = std::min(e.Low[a], mesh.Position[faces[f].Vertices[i]][a]);
          e.High[a] = std::max(e.High[a], mesh.Position[faces[f].Vertices[i]][a]);
        }
    }
    // Bins aligned on the box, over the faces' bounding box only: a block of
    // the streamed pipeline is small in the whole mesh's box.
    int low[3], high[3];
    for (int a = 0; a < 3; ++a)
    {
      low[a] = faces.empty() ? mesh.BoxLow[a] : INT32_MAX;
      high[a] = faces.empty() ? mesh.BoxLow[a] : INT32_MIN;
    }
    for (const Entry& e : boxes)
      for (int a = 0; a < 3; ++a)
      {
        low[a] = std::min(low[a], e.Low[a]);
        high[a] = std::max(high[a], e.High[a]);
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
      for (const Entry& e : boxes)
      {
        int lo[3], hi[3];
        for (int a = 0; a < 3; ++a)
        {
          lo[a] = BinOf(e.Low[a], a);
          hi[a] = BinOf(e.High[a], a);
        }
        for (int z = lo[2]; z <= hi[2]; ++z)
          for (int y = lo[1]; y <= hi[1]; ++y)
            for (int x = lo[0]; x <= hi[0]; ++x)
            {
              const std::size_t bin = Index(x, y, z);
              if (pass == 0)
                ++Start[bin + 1];
              else
                Items[next[bin]++] = e;
            }
      }
    }
  }

  /// Faces whose bounding boxes meet the index-space box [lo, hi], each
  /// once, in increasing order; with `wholeBins`, every face of the bins
  /// that meet it.
  void Query(const Point3& lo, const Point3& hi, std::vector<std::uint32_t>& out, bool wholeBins = false) const
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
    const Point3 doubledLow{ 2.0 * lo[0], 2.0 * lo[1], 2.0 * lo[2] };
    const Point3 doubledHigh{ 2.0 * hi[0], 2.0 * hi[1], 2.0 * hi[2] };
    for (int z = from[2]; z <= to[2]; ++z)
      for (int y = from[1]; y <= to[1]; ++y)
        for (int x = from[0]; x <= to[0]; ++x)
        {
          const std::size_t bin = Index(x, y, z);
          for (std::uint32_t i = Start[bin]; i < Start[bin + 1]; ++i)
            if (wholeBins || Items[i].Meets(doubledLow, doubledHigh))
              out.push_back(Items[i].Face);
        }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
  }

private:
  struct Entry
  {
    std::uint32_t Face;
    Lattice Low, High; ///< the face's bounding box, doubled lattice
    bool Meets(const Point3& lo, const Point3& hi) const
    {
      for (int a = 0; a < 3; ++a)
        if (High[a] < lo[a] || Low[a] > hi[a])
          return false;
      return true;
    }
  };
  static constexpr int kBin = 8;
  int Unclamped(double doubled, int axis) const
  {
    return static_cast<int>(std::clamp(std::floor((doubled - Low[axis]) / kBin), -1.0, double(Bins[axis])));
  }
  int BinOf(double doubled, int axis) const { return std::clamp(Unclamped(doubled, axis), 0, Bins[axis] - 1); }
  std::size_t Index(int x, int y, int z) const { return (static_cast<std::size_t>(z) * Bins[1] + y) * Bins[0] + x; }
  int Low[3], Bins[3];
  std::vector<std::uint32_t> Start;
  std::vector<Entry> Items;
};

/// The vertices of the faces `list` of `faces` that separate `side`, sorted, each once.
void SideVertices(const std::vector<InterfaceFace>& faces, const std::vector<std::uint32_t>& list, std::int32_t side,
  int dimension, std::vector<VertexId>& out)
{
  out.clear();
  for (std::uint32_t f : list)
    if (faces[f].Separates(side))
      out.insert(out.end(), faces[f].Vertices.begin(), faces[f].Vertices.begin() + dimension);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
}

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
      // Faces whose boxes miss this box are farther than h from every point
      // of the image face: they certify nothing.
      grid.Query(lo, hi, near);
      candidates.clear();
      for (std::uint32_t f : near)
        if (faces[f].Separates(ItemSide[item]))
          candidates.push_back(faces[f]);
      auto anchor = Certify(mesh, static_cast<std::int32_t>(item), candidates, -1, pieces);
      if (anchor[0] < 0)
      {
        // A star that certifies it: the faces around one vertex of the candidates.
        SideVertices(faces, near, ItemSide[item], Dimension, vertices);
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
        // Frozen: the vertices of every face of its side in the grid bins
        // around it, not only of those it rests on (freezing only those left
        // 17 % more cells on Cassini 400).
        grid.Query(lo, hi, near, true);
        SideVertices(faces, near, ItemSide[item], Dimension, pinnedVertices[item]);
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
