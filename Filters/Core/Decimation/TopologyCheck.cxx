// SPDX-License-Identifier: GPL-2.0-or-later
// Requirement 3 of section 3.1.3: the link condition on every stratum a merge touches.
#include "Decimation/TopologyCheck.h"

#include <algorithm>
#include <limits>

namespace labelmesher
{
namespace
{

/// The extra vertex w of the boundary trick: it sorts after every real vertex.
constexpr VertexId kCone = std::numeric_limits<VertexId>::max();

template <typename T>
void SortUnique(std::vector<T>& v)
{
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

template <typename T>
bool Includes(const std::vector<T>& sortedSuperset, const std::vector<T>& sortedSubset)
{
  return std::includes(sortedSuperset.begin(), sortedSuperset.end(), sortedSubset.begin(), sortedSubset.end());
}

void AddOutsideLabels(std::uint8_t planes, std::vector<std::int32_t>& labels)
{
  for (int f = 0; f < 6; ++f)
    if (planes & (1u << f))
      labels.push_back(EditableMesh::OutsideLabel(f));
}

} // namespace

bool TopologyCheck::IsInterior(const EditableMesh& mesh, VertexId v)
{
  if (mesh.BoxPlanes[v] != 0)
    return false;
  const auto& cells = mesh.CellsOf[v];
  for (CellId c : cells)
    if (mesh.Labels[c] != mesh.Labels[cells[0]])
      return false;
  return true;
}

void TopologyCheck::Bind(const EditableMesh& mesh)
{
  Dimension = mesh.Dimension;
  if (Seen.size() != mesh.Position.size())
  {
    Seen.assign(mesh.Position.size(), 0u);
    LocalId.assign(mesh.Position.size(), 0);
    Epoch = 0;
  }
}

bool TopologyCheck::Accepts(const EditableMesh& mesh, const EdgeCollapse& merge)
{
  Bind(mesh);
  return StrataAllowMove(mesh, merge) && LinkConditions(mesh, merge) && Commutes(mesh, merge);
}

void TopologyCheck::FeatureNeighbours(const std::vector<InterfaceFace>& faces, VertexId v, std::vector<VertexId>& out)
{
  // Edge (v, x) is a feature edge unless exactly zero or two interface faces
  // of one pair contain it (one sheet passes through it).
  auto& uses = EdgeUses;
  uses.clear();
  for (const InterfaceFace& f : faces)
  {
    if (!f.Contains(v))
      continue;
    for (int i = 0; i < 3; ++i)
      if (f.Vertices[i] >= 0 && f.Vertices[i] != v)
        uses.push_back({ f.Vertices[i], { f.Low, f.High } });
  }
  std::sort(uses.begin(), uses.end());
  out.clear();
  for (std::size_t u = 0; u < uses.size();)
  {
    std::size_t w = u + 1;
    while (w < uses.size() && uses[w].first == uses[u].first)
      ++w;
    if (w - u != 2 || uses[u].second != uses[u + 1].second)
      out.push_back(uses[u].first);
    u = w;
  }
}

bool TopologyCheck::StrataAllowMove(const EditableMesh& mesh, const EdgeCollapse& merge)
{
  const VertexId a = merge.From, b = merge.To;
  // Labels around a, and around the edge ab (cells with both vertices, box
  // planes with both).
  LabelsA.clear();
  LabelsAB.clear();
  for (CellId c : merge.Removed)
  {
    LabelsA.push_back(mesh.Labels[c]);
    LabelsAB.push_back(mesh.Labels[c]);
  }
  for (CellId c : merge.Moved)
    LabelsA.push_back(mesh.Labels[c]);
  AddOutsideLabels(mesh.BoxPlanes[a], LabelsA);
  AddOutsideLabels(mesh.BoxPlanes[a] & mesh.BoxPlanes[b], LabelsAB);
  SortUnique(LabelsA);
  SortUnique(LabelsAB);
  if (!Includes(LabelsAB, LabelsA))
    return false;

  // Interface pairs around a, and around ab.
  PairsA.clear();
  PairsAB.clear();
  for (const InterfaceFace& f : merge.Before)
  {
    if (!f.Contains(a))
      continue;
    PairsA.push_back({ f.Low, f.High });
    if (f.Contains(b))
      PairsAB.push_back({ f.Low, f.High });
  }
  SortUnique(PairsA);
  SortUnique(PairsAB);
  if (!Includes(PairsAB, PairsA))
    return false;

  if (Dimension == 2)
  {
    // A vertex on one interface has exactly two interface edges of one pair;
    // anything else is a corner (junction, pinch, the box's corner).
    int count = 0;
    const InterfaceFace* first = nullptr;
    for (const InterfaceFace& f : merge.Before)
      if (f.Contains(a))
      {
        if (first && !f.SamePair(*first))
          return false;
        first = first ? first : &f;
        ++count;
      }
    return count == 0 || count == 2;
  }
  FeatureNeighbours(merge.Before, a, FeatureA);
  if (FeatureA.empty())
    return true;
  return FeatureA.size() == 2 && std::find(FeatureA.begin(), FeatureA.end(), b) != FeatureA.end();
}

bool TopologyCheck::LinkCondition(VertexId a, VertexId b)
{
  // Faces of the links are sets of up to three vertices; numbered locally
  // (the two stars hold at most a few hundred vertices) a face packs into one
  // 32-bit key, 10 bits per vertex, 0 for none.
  // Local numbers by first sight (a stamp per mesh vertex, so no sort).
  if (++Epoch == 0)
  {
    std::fill(Seen.begin(), Seen.end(), 0u);
    Epoch = 1;
  }
  std::uint32_t count = 0, coneId = 0;
  auto local = [&](VertexId v) -> std::uint32_t {
    if (v == kCone)
      return coneId ? coneId : (coneId = ++count);
    if (Seen[v] != Epoch)
    {
      Seen[v] = Epoch;
      LocalId[v] = static_cast<std::uint16_t>(std::min<std::uint32_t>(++count, 1023));
    }
    return LocalId[v];
  };
  SA.clear();
  SB.clear();
  SAB.clear();
  auto addSubsets = [](const std::uint32_t* v, int n, std::vector<std::uint32_t>& out) {
    for (int mask = 1; mask < (1 << n); ++mask)
    {
      std::uint32_t key = 0;
      for (int i = 0; i < n; ++i)
        if (mask & (1 << i))
          key = (key << 10) | v[i];
      out.push_back(key);
    }
  };
  for (std::size_t t = 0; t < Tops.size(); ++t)
  {
    const auto& top = Tops[t];
    std::uint32_t rest[4];
    int n = 0;
    bool hasA = false, hasB = false;
    for (int i = 0; i < TopSizes[t]; ++i)
    {
      if (top[i] == a)
        hasA = true;
      else if (top[i] == b)
        hasB = true;
      else
        rest[n++] = local(top[i]);
    }
    if (hasA && hasB)
    {
      addSubsets(rest, n, SAB);
      addSubsets(rest, n, SA);
      addSubsets(rest, n, SB);
    }
    else if (hasA)
      addSubsets(rest, n, SA);
    else if (hasB)
      addSubsets(rest, n, SB);
  }
  if (count >= 1023)
    return false; // too large to judge this way: refuse, never accept unproven
  // Lk(a) & Lk(b) must lie in Lk(ab): every face of Lk(a) found in Lk(b)
  // must be in Lk(ab) (repeats in Lk(a) only repeat the test).
  std::sort(SB.begin(), SB.end());
  std::sort(SAB.begin(), SAB.end());
  for (std::uint32_t key : SA)
    if (std::binary_search(SB.begin(), SB.end(), key) && !std::binary_search(SAB.begin(), SAB.end(), key))
      return false;
  return true;
}

bool TopologyCheck::AcceptsInteriorMove(const EditableMesh& mesh, const EdgeCollapse& merge)
{
  // a inside one material, off the box: no stratum, interface or curve
  // passes through its star, so the merge changes none of them, and K's link
  // condition is all there is (Lk(a) has no cone vertex).
  Bind(mesh);
  const int nv = mesh.VerticesPerCell();
  Tops.clear();
  TopSizes.clear();
  for (const auto* list : { &merge.Removed, &merge.Moved })
    for (CellId c : *list)
    {
      auto cell = mesh.Cells[c];
      std::sort(cell.begin(), cell.begin() + nv);
      Tops.push_back(cell);
      TopSizes.push_back(nv);
    }
  for (CellId c : mesh.CellsOf[merge.To])
    if (!mesh.Contains(c, merge.From))
    {
      auto cell = mesh.Cells[c];
      std::sort(cell.begin(), cell.begin() + nv);
      Tops.push_back(cell);
      TopSizes.push_back(nv);
    }
  return LinkCondition(merge.From, merge.To);
}

bool TopologyCheck::LinkConditions(const EditableMesh& mesh, const EdgeCollapse& merge)
{
  const VertexId a = merge.From, b = merge.To;
  const int nv = mesh.VerticesPerCell();
  auto addCell = [&](CellId c) {
    auto cell = mesh.Cells[c];
    std::sort(cell.begin(), cell.begin() + nv);
    Tops.push_back(cell);
    TopSizes.push_back(nv);
  };
  auto addFace = [&](const InterfaceFace& f, bool cone) {
    std::array<VertexId, 4> top{ f.Vertices[0], f.Vertices[1], f.Vertices[2], -1 };
    const int n = Dimension;
    if (cone)
      top[n] = kCone;
    Tops.push_back(top);
    TopSizes.push_back(cone ? n + 1 : n);
  };
  // K with the cone over the box's faces.
  Tops.clear();
  TopSizes.clear();
  for (const auto* list : { &merge.Removed, &merge.Moved, &merge.Kept })
    for (CellId c : *list)
      addCell(c);
  for (const InterfaceFace& f : merge.Before)
    if (EditableMesh::IsOutside(f.Low))
      addFace(f, true);
  if (!LinkCondition(a, b))
    return false;

  // Each material around a.
  for (std::int32_t m : LabelsA)
  {
    if (EditableMesh::IsOutside(m))
      continue;
    Tops.clear();
    TopSizes.clear();
    for (const auto* list : { &merge.Removed, &merge.Moved, &merge.Kept })
      for (CellId c : *list)
        if (mesh.Labels[c] == m)
          addCell(c);
    if (!LinkCondition(a, b))
      return false;
  }

  // Each interface around a.
  for (const auto& pair : PairsA)
  {
    Tops.clear();
    TopSizes.clear();
    for (const InterfaceFace& f : merge.Before)
      if (f.Low == pair.first && f.High == pair.second)
        addFace(f, false);
    if (!LinkCondition(a, b))
      return false;
  }

  // The feature curves: a 1-complex, whose edges have empty links.
  if (Dimension == 3)
  {
    FeatureNeighbours(merge.Before, b, FeatureB);
    for (VertexId x : FeatureA)
      if (x != b && std::find(FeatureB.begin(), FeatureB.end(), x) != FeatureB.end())
        return false;
  }
  return true;
}

bool TopologyCheck::Commutes(const EditableMesh& mesh, const EdgeCollapse& merge)
{
  const VertexId a = merge.From, b = merge.To;
  // The interface faces after are the images of those before.
  Image.clear();
  for (InterfaceFace f : merge.Before)
  {
    if (f.Contains(a) && f.Contains(b))
      continue; // collapses onto a lower face
    for (auto& v : f.Vertices)
      if (v == a)
        v = b;
    std::sort(f.Vertices.begin(), f.Vertices.begin() + Dimension);
    Image.push_back(f);
  }
  SortUnique(Image);
  // Only faces touching b after are listed in After; images of faces that did
  // not touch a or b are not in Before.
  if (Image != merge.After)
    return false;

  // A vanishing cell of material m leaves its face (R without a = R without b
  // after the merge) to m only if one of its two faces was inside m.
  for (CellId c : merge.Removed)
  {
    int interfaceFaces = 0;
    for (VertexId skip : { a, b })
    {
      InterfaceFace key{ { -1, -1, -1 }, 0, 0 };
      int n = 0;
      for (int i = 0; i < mesh.VerticesPerCell(); ++i)
        if (mesh.Cells[c][i] != skip)
          key.Vertices[n++] = mesh.Cells[c][i];
      std::sort(key.Vertices.begin(), key.Vertices.begin() + n);
      const auto it = std::lower_bound(merge.Before.begin(), merge.Before.end(), key,
        [](const InterfaceFace& x, const InterfaceFace& y) { return x.Vertices < y.Vertices; });
      interfaceFaces += it != merge.Before.end() && it->Vertices == key.Vertices;
    }
    if (interfaceFaces == 2)
      return false;
  }

  // A vanishing interface face (it holds a and b) leaves its image, one
  // dimension lower, covered by a face of its pair.
  for (const InterfaceFace& f : merge.Before)
  {
    if (!(f.Contains(a) && f.Contains(b)))
      continue;
    VertexId other = -1;
    for (int i = 0; i < Dimension; ++i)
      if (f.Vertices[i] != a && f.Vertices[i] != b)
        other = f.Vertices[i];
    bool covered = false;
    for (const InterfaceFace& g : merge.After)
      covered = covered || (g.SamePair(f) && g.Contains(b) && (other < 0 || g.Contains(other)));
    if (!covered)
      return false;
  }

  // The feature edges around b after are the images of those around a and b.
  if (Dimension == 3)
  {
    FeatureNeighbours(merge.After, b, FeatureAfter);
    std::vector<VertexId> image;
    for (VertexId x : FeatureA)
      if (x != b)
        image.push_back(x);
    for (VertexId x : FeatureB)
      if (x != a)
        image.push_back(x);
    SortUnique(image);
    if (image != FeatureAfter)
      return false;
  }
  return true;
}

} // namespace labelmesher
