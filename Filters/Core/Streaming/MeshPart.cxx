// SPDX-License-Identifier: GPL-2.0-or-later
// A part of the streamed pipeline as bytes: fixed-width fields, lengths first.
#include "Streaming/MeshPart.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <stdexcept>

namespace labelmesher
{
namespace
{

constexpr std::uint32_t kMagic = 0x4c4d5031;           // "LMP1"
constexpr std::uint32_t kAssignmentMagic = 0x4c4d4131; // "LMA1"

class Writer
{
public:
  template <typename T>
  void Value(const T& v)
  {
    const char* p = reinterpret_cast<const char*>(&v);
    Bytes.insert(Bytes.end(), p, p + sizeof(T));
  }
  template <typename T>
  void Array(const std::vector<T>& v)
  {
    Value(static_cast<std::uint64_t>(v.size()));
    const char* p = reinterpret_cast<const char*>(v.data());
    Bytes.insert(Bytes.end(), p, p + v.size() * sizeof(T));
  }
  void Text(const std::string& s) { Array(std::vector<char>(s.begin(), s.end())); }
  std::vector<char> Bytes;
};

class Reader
{
public:
  /// `what` names the message in errors: "a mesh part's message", "a process's assignment".
  Reader(const std::vector<char>& bytes, const char* what)
    : Bytes(bytes)
    , What(what)
  {
  }
  template <typename T>
  T Value()
  {
    T v;
    Take(&v, sizeof(T));
    return v;
  }
  template <typename T>
  std::vector<T> Array()
  {
    const auto n = Value<std::uint64_t>();
    if (n > (Bytes.size() - At) / sizeof(T))
      throw std::runtime_error(std::string(What) + " is cut short");
    std::vector<T> v(static_cast<std::size_t>(n));
    Take(v.data(), v.size() * sizeof(T));
    return v;
  }
  std::string Text()
  {
    const std::vector<char> c = Array<char>();
    return std::string(c.begin(), c.end());
  }
  bool AtEnd() const { return At == Bytes.size(); }
  std::size_t Left() const { return Bytes.size() - At; }

private:
  void Take(void* to, std::size_t n)
  {
    if (n > Bytes.size() - At)
      throw std::runtime_error(std::string(What) + " is cut short");
    if (n > 0)
      std::memcpy(to, Bytes.data() + At, n);
    At += n;
  }
  const std::vector<char>& Bytes;
  const char* What;
  std::size_t At = 0;
};

void WriteCounts(Writer& w, const DecimationCounts& c)
{
  for (std::size_t v : { c.CellsBefore, c.CellsAfter, c.VerticesBefore, c.VerticesAfter, c.Offers, c.Merges,
         c.RejectedByQuality, c.RejectedByTopology, c.RejectedByFidelity, c.Relocations, c.FrozenVertices })
    w.Value(static_cast<std::uint64_t>(v));
}

DecimationCounts ReadCounts(Reader& r)
{
  DecimationCounts c;
  for (std::size_t* v : { &c.CellsBefore, &c.CellsAfter, &c.VerticesBefore, &c.VerticesAfter, &c.Offers, &c.Merges,
         &c.RejectedByQuality, &c.RejectedByTopology, &c.RejectedByFidelity, &c.Relocations, &c.FrozenVertices })
    *v = static_cast<std::size_t>(r.Value<std::uint64_t>());
  return c;
}

} // namespace

std::vector<char> PackPartMessage(const PartMessage& message)
{
  Writer w;
  w.Value(kMagic);
  w.Value(static_cast<std::uint8_t>(message.Failed));
  if (message.Failed)
  {
    w.Text(message.Reason);
    return std::move(w.Bytes);
  }
  const MeshPart& p = message.Part;
  w.Value(static_cast<std::int32_t>(p.Mesh.Dimension));
  w.Array(p.Mesh.Points);
  w.Array(p.Mesh.Connectivity);
  w.Array(p.Mesh.Materials);
  w.Array(p.Offered);
  w.Array(p.Border);
  WriteCounts(w, p.Counts);
  for (std::size_t v : { p.Blocks, p.LargestBlockCells, p.ForegroundCellsBefore, p.BorderPasses,
         p.LargestAssembledCells })
    w.Value(static_cast<std::uint64_t>(v));
  w.Value(static_cast<std::uint64_t>(p.Timings.size()));
  for (const StageTiming& t : p.Timings)
  {
    w.Text(t.Stage);
    w.Value(t.Seconds);
  }
  return std::move(w.Bytes);
}

PartMessage UnpackPartMessage(const std::vector<char>& bytes)
{
  Reader r(bytes, "a mesh part's message");
  if (r.Value<std::uint32_t>() != kMagic)
    throw std::runtime_error("a mesh part's message does not start as one");
  PartMessage message;
  message.Failed = r.Value<std::uint8_t>() != 0;
  if (message.Failed)
  {
    message.Reason = r.Text();
    return message;
  }
  MeshPart& p = message.Part;
  p.Mesh.Dimension = r.Value<std::int32_t>();
  if (p.Mesh.Dimension != 2 && p.Mesh.Dimension != 3)
    throw std::runtime_error("a mesh part's message names no dimension");
  p.Mesh.Points = r.Array<Point3>();
  p.Mesh.Connectivity = r.Array<std::int64_t>();
  p.Mesh.Materials = r.Array<std::int32_t>();
  p.Offered = r.Array<std::uint8_t>();
  p.Border = r.Array<std::uint8_t>();
  if (p.Mesh.Connectivity.size() != p.Mesh.Materials.size() * static_cast<std::size_t>(p.Mesh.VerticesPerCell()) ||
    p.Offered.size() != p.Mesh.Points.size() || p.Border.size() != p.Mesh.Points.size())
    throw std::runtime_error("a mesh part's message has arrays of different lengths");
  for (std::int64_t v : p.Mesh.Connectivity)
    if (v < 0 || static_cast<std::uint64_t>(v) >= p.Mesh.Points.size())
      throw std::runtime_error("a mesh part's message names a vertex it does not hold");
  p.Counts = ReadCounts(r);
  for (std::size_t* v : { &p.Blocks, &p.LargestBlockCells, &p.ForegroundCellsBefore, &p.BorderPasses,
         &p.LargestAssembledCells })
    *v = static_cast<std::size_t>(r.Value<std::uint64_t>());
  const auto timings = r.Value<std::uint64_t>();
  for (std::uint64_t t = 0; t < timings; ++t)
  {
    StageTiming timing;
    timing.Stage = r.Text();
    timing.Seconds = r.Value<double>();
    p.Timings.push_back(std::move(timing));
  }
  if (!r.AtEnd())
    throw std::runtime_error("a mesh part's message runs on past its end");
  return message;
}

namespace
{

/// Leaves field by field: the struct's padding is not sent (its bytes are
/// whatever the memory held, so the same assignment would differ in bytes).
constexpr std::size_t kLeafBytes = 7 * sizeof(std::int32_t) + sizeof(std::uint16_t) + sizeof(std::uint8_t);

void WriteLeaves(Writer& w, const std::vector<OctreeLeaf>& leaves)
{
  w.Value(static_cast<std::uint64_t>(leaves.size()));
  for (const OctreeLeaf& leaf : leaves)
  {
    for (int c : leaf.Box.Origin)
      w.Value(static_cast<std::int32_t>(c));
    w.Value(static_cast<std::int32_t>(leaf.Box.Size));
    w.Value(static_cast<std::int32_t>(leaf.Box.Dimension));
    w.Value(leaf.First);
    w.Value(leaf.Second);
    w.Value(leaf.EdgeMidpoints);
    w.Value(leaf.SplitFaces);
  }
}

std::vector<OctreeLeaf> ReadLeaves(Reader& r)
{
  const auto n = r.Value<std::uint64_t>();
  if (n > r.Left() / kLeafBytes)
    throw std::runtime_error("a process's assignment is cut short");
  std::vector<OctreeLeaf> leaves(static_cast<std::size_t>(n));
  for (OctreeLeaf& leaf : leaves)
  {
    for (int& c : leaf.Box.Origin)
      c = r.Value<std::int32_t>();
    leaf.Box.Size = r.Value<std::int32_t>();
    leaf.Box.Dimension = r.Value<std::int32_t>();
    leaf.First = r.Value<std::int32_t>();
    leaf.Second = r.Value<std::int32_t>();
    leaf.EdgeMidpoints = r.Value<std::uint16_t>();
    leaf.SplitFaces = r.Value<std::uint8_t>();
  }
  return leaves;
}

} // namespace

std::vector<char> PackPartAssignment(const PartAssignment& a)
{
  Writer w;
  w.Value(kAssignmentMagic);
  w.Value(static_cast<std::uint8_t>(a.Failed));
  if (a.Failed)
  {
    w.Text(a.Reason);
    return std::move(w.Bytes);
  }
  for (int n : a.ImageDimensions)
    w.Value(static_cast<std::int32_t>(n));
  w.Value(a.Depth);
  WriteLeaves(w, a.Leaves);
  w.Array(a.Starts);
  w.Value(a.EndKey);
  w.Value(a.LeavesBefore);
  w.Value(a.OctreeLeaves);
  w.Value(a.SlabFirst);
  w.Value(a.SlabEnd);
  w.Value(a.SlabHash);
  return std::move(w.Bytes);
}

PartAssignment UnpackPartAssignment(const std::vector<char>& bytes)
{
  Reader r(bytes, "a process's assignment");
  if (r.Value<std::uint32_t>() != kAssignmentMagic)
    throw std::runtime_error("a process's assignment does not start as one");
  PartAssignment a;
  a.Failed = r.Value<std::uint8_t>() != 0;
  if (a.Failed)
  {
    a.Reason = r.Text();
    if (!r.AtEnd())
      throw std::runtime_error("a process's assignment runs on past its end");
    return a;
  }
  for (int& n : a.ImageDimensions)
    n = r.Value<std::int32_t>();
  a.Depth = r.Value<std::int32_t>();
  a.Leaves = ReadLeaves(r);
  a.Starts = r.Array<std::uint64_t>();
  a.EndKey = r.Value<std::uint64_t>();
  a.LeavesBefore = r.Value<std::uint64_t>();
  a.OctreeLeaves = r.Value<std::uint64_t>();
  a.SlabFirst = r.Value<std::int32_t>();
  a.SlabEnd = r.Value<std::int32_t>();
  a.SlabHash = r.Value<std::uint64_t>();
  if (!r.AtEnd())
    throw std::runtime_error("a process's assignment runs on past its end");
  if (a.Starts.empty() || a.Starts.front() != 0 || a.Starts.back() != a.Leaves.size() ||
    !std::is_sorted(a.Starts.begin(), a.Starts.end()) || a.Depth < 1 || a.Depth > 21)
    throw std::runtime_error("a process's assignment is not a run of parts");
  return a;
}

} // namespace labelmesher
