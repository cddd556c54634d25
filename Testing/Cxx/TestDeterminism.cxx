// SPDX-License-Identifier: GPL-2.0-or-later
//
// The output of MeshLabelImage (Filters/Core/LabelOctreeMesher.h) does not
// depend on the number of threads (Support/ParallelChunks.h promises it):
// Points, Connectivity and Materials of the mesh and of the boundary,
// InterfaceMaterials and NumberOfLeaves are the same byte for byte with
// SetThreadLimit(1) and with 2, 3 and 8 threads (more than this machine's
// cores, on purpose). The inputs are large enough that the parallel paths
// run: the octree judges leaves on several threads once the pending leaves
// hold 65,536 voxels or more, the interface extraction scans runs of 65,536
// cells and sorts in parallel above 2 x 65,536 face records; each test first
// checks that its input takes the paths it is there for. The decimator's
// output and counts do not depend on the threads either.
//
// The two real volumes are read from Resources/Data (gzip NRRD) with ITK
// (Support/IO/LabelImageFile.h).

#include "Decimation/MeshDecimator.h"
#include "Decimation/RegionScheduler.h"
#include "LabelImageFile.h"
#include "LabelOctreeMesher.h"
#include "Support/ParallelChunks.h"
#include "SyntheticShapes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace labelmesher
{
namespace
{

/// The project's bundled copy (Resources/Data), else the shared data's.
/// LABELMESHER_SHARED_DATA_DIR is "<source dir>/../shared/data".
std::string DataFile(const std::string& bundled, const std::string& shared)
{
  const std::string sharedDir = LABELMESHER_SHARED_DATA_DIR, suffix = "/../shared/data";
  std::vector<std::string> candidates;
  const bool beside = sharedDir.size() > suffix.size() &&
    sharedDir.compare(sharedDir.size() - suffix.size(), suffix.size(), suffix) == 0;
  if (beside)
    candidates.push_back(sharedDir.substr(0, sharedDir.size() - suffix.size()) + "/Resources/Data/" + bundled);
  candidates.push_back(sharedDir + "/" + shared);
  for (const std::string& path : candidates)
    if (std::ifstream(path))
      return path;
  return candidates.front();
}

// ---- the comparison ----------------------------------------------------------------

/// Restores the default thread limit however the test ends.
struct ThreadLimitGuard
{
  ~ThreadLimitGuard() { SetThreadLimit(0); }
};

template <typename T>
bool SameBytes(const std::vector<T>& a, const std::vector<T>& b)
{
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

void ExpectSameOutput(const MesherResult& a, const MesherResult& b, unsigned threads)
{
  EXPECT_EQ(a.NumberOfLeaves, b.NumberOfLeaves) << threads << " threads";
  EXPECT_EQ(a.Mesh.Dimension, b.Mesh.Dimension);
  EXPECT_TRUE(SameBytes(a.Mesh.Points, b.Mesh.Points)) << "Mesh.Points, " << threads << " threads";
  EXPECT_TRUE(SameBytes(a.Mesh.Connectivity, b.Mesh.Connectivity)) << "Mesh.Connectivity, " << threads << " threads";
  EXPECT_TRUE(SameBytes(a.Mesh.Materials, b.Mesh.Materials)) << "Mesh.Materials, " << threads << " threads";
  EXPECT_EQ(a.Interfaces.Dimension, b.Interfaces.Dimension);
  EXPECT_TRUE(SameBytes(a.Interfaces.Points, b.Interfaces.Points)) << "Interfaces.Points, " << threads << " threads";
  EXPECT_TRUE(SameBytes(a.Interfaces.Connectivity, b.Interfaces.Connectivity))
    << "Interfaces.Connectivity, " << threads << " threads";
  EXPECT_TRUE(SameBytes(a.Interfaces.Materials, b.Interfaces.Materials)) << "Interfaces.Materials, " << threads << " threads";
  EXPECT_EQ(a.InterfaceMaterials, b.InterfaceMaterials) << "InterfaceMaterials, " << threads << " threads";
}

/// The face records ExtractMaterialInterfaces sorts (MeshBoundary.h: only
/// faces near interfaces or on the bounding box are looked at): every face,
/// once per cell using it, whose vertices each touch two materials or lie on
/// the mesh's bounding box.
std::size_t FaceRecords(const SimplexMesh& mesh)
{
  const int n = mesh.VerticesPerCell();
  constexpr std::int64_t unseen = -1, mixed = -2;
  std::vector<std::int64_t> material(mesh.Points.size(), unseen);
  for (std::size_t c = 0; c < mesh.NumberOfCells(); ++c)
    for (int i = 0; i < n; ++i)
    {
      std::int64_t& m = material[mesh.Cell(c)[i]];
      m = m == unseen ? mesh.Materials[c] : (m == mesh.Materials[c] ? m : mixed);
    }
  Point3 lo = mesh.Points[0], hi = lo;
  for (const Point3& p : mesh.Points)
    for (int a = 0; a < 3; ++a)
      lo[a] = std::min(lo[a], p[a]), hi[a] = std::max(hi[a], p[a]);
  std::vector<unsigned char> near(mesh.Points.size());
  for (std::size_t v = 0; v < near.size(); ++v)
  {
    near[v] = material[v] == mixed;
    for (int a = 0; a < mesh.Dimension; ++a)
      near[v] = near[v] || mesh.Points[v][a] == lo[a] || mesh.Points[v][a] == hi[a];
  }
  std::size_t records = 0;
  for (std::size_t c = 0; c < mesh.NumberOfCells(); ++c)
  {
    int count = 0;
    for (int i = 0; i < n; ++i)
      count += near[mesh.Cell(c)[i]];
    records += count == n ? n : (count == n - 1 ? 1 : 0); // faces whose vertices all qualify
  }
  return records;
}

/// The parallel paths an input is meant to take.
enum Paths : unsigned
{
  kOctree = 1,   ///< the octree's root leaf (the largest side rounded up to a power of two) holds >= 65,536 voxels
  kCellScan = 2, ///< more than one run of 65,536 cells to scan for interface faces
  kSort = 4,     ///< at least 2 x 65,536 face records to sort
  kAllPaths = 7
};

/// Meshes `image` with one thread, then with 2, 3 and 8, and compares; first
/// checks that the input takes the parallel paths `paths`.
void ExpectThreadCountDoesNotMatter(const LabelImage& image, const MesherParameters& parameters, unsigned paths)
{
  ThreadLimitGuard restore;
  int side = 1;
  while (side < std::max({ image.Dimensions[0], image.Dimensions[1], image.Dimensions[2] }))
    side *= 2;
  if (paths & kOctree)
  {
    ASSERT_GE(std::pow(double(side), image.Dimension()), 65536.0) << "too small for the parallel octree";
  }
  SetThreadLimit(1);
  const MesherResult reference = MeshLabelImage(image, parameters);
  if (paths & kCellScan)
  {
    ASSERT_GT(reference.Mesh.NumberOfCells(), 65536u) << "too small for the parallel interface scan";
  }
  if (paths & kSort)
  {
    ASSERT_GE(FaceRecords(reference.Mesh), 2u * 65536u) << "too small for the parallel sort";
  }
  for (unsigned threads : { 2u, 3u, 8u })
  {
    SetThreadLimit(threads);
    ASSERT_EQ(MaxThreads(), threads);
    ExpectSameOutput(reference, MeshLabelImage(image, parameters), threads);
  }
}

/// Distinct non-zero labels and the largest: what Resources/Data/README.md
/// says of each file, a check of the reader.
std::pair<std::size_t, std::int32_t> LabelsOf(const LabelImage& image)
{
  const std::vector<std::int32_t> all = image.LabelsAsInt32();
  std::set<std::int32_t> labels(all.begin(), all.end());
  labels.erase(0);
  return { labels.size(), labels.empty() ? 0 : *labels.rbegin() };
}

TEST(Determinism, TotalSegmentatorVolumeIsTheSameOnAnyNumberOfThreads)
{
  // 122 x 101 x 30 voxels, 41 labels (largest id 117): the octree cube is 128^3.
  const LabelImage image = testing::ReadLabelImageFile(DataFile("totalseg_example_seg.nrrd", "3d/totalseg_example_seg.nrrd")).Image;
  ASSERT_EQ(image.Dimensions, (std::array<int, 3>{ 122, 101, 30 }));
  ASSERT_EQ(LabelsOf(image), (std::pair<std::size_t, std::int32_t>{ 41, 117 }));
  ExpectThreadCountDoesNotMatter(image, {}, kAllPaths);
}

TEST(Determinism, RatHeadVolumeIsTheSameOnAnyNumberOfThreads)
{
  // 50 x 53 x 44 voxels, one label touching the image border; h = 1 and 2.
  // One label has too little boundary for the parallel sort (about 99,000
  // face records), so this one covers the octree and the cell scan only.
  const LabelImage image = testing::ReadLabelImageFile(DataFile("rat_head.nrrd", "3d/iso2mesh_rat_head.nrrd")).Image;
  ASSERT_EQ(image.Dimensions, (std::array<int, 3>{ 50, 53, 44 }));
  ASSERT_EQ(LabelsOf(image), (std::pair<std::size_t, std::int32_t>{ 1, 1 }));
  MesherParameters parameters;
  parameters.ImageToMeshDistance = 1.0;
  parameters.MeshToImageDistance = 2.0;
  ExpectThreadCountDoesNotMatter(image, parameters, kOctree | kCellScan);
}

TEST(Determinism, CassiniVolumeIsTheSameOnAnyNumberOfThreads)
{
  // The Cassini benchmark shape (two materials touching at the neck), 120^3:
  // at 96^3 the interface extraction sorts too few face records (about
  // 93,000) to do it in parallel.
  ExpectThreadCountDoesNotMatter(testing::MakeCassiniVolume(120), {}, kAllPaths);
}

TEST(Determinism, TwoDimensionalImageIsTheSameOnAnyNumberOfThreads)
{
  // 700 x 600 pixels: two touching discs (labels 1 and 2) over concentric
  // elliptic rings of labels 3, 4 and background, 5 pixels wide: boundary
  // almost everywhere, meshed pixel-exactly (h = 0).
  LabelImage image = testing::MakeTouchingBlobs2D(700, 600);
  for (int j = 0; j < 600; ++j)
    for (int i = 0; i < 700; ++i)
      if (image(i, j, 0) == 0)
      {
        const double r = std::hypot((i - 349.5) / 1.3, j - 299.5);
        image(i, j, 0) = (static_cast<int>(r / 5.0) % 3 == 0) ? 0 : 2 + static_cast<int>(r / 5.0) % 3;
      }
  MesherParameters exact;
  exact.ImageToMeshDistance = exact.MeshToImageDistance = 0.0;
  ExpectThreadCountDoesNotMatter(image, exact, kAllPaths);
}

/// The decimator's regions (runs of the Morton order, decimated on their own
/// with frozen borders, then the borders) must not depend on the threads
/// that run them: the same mesh and the same counts with 1, 2, 3 and 8.
void ExpectDecimationDoesNotDependOnThreads(const LabelImage& image, const MesherParameters& mesher)
{
  SetThreadLimit(1);
  const SimplexMesh initial = MeshLabelImage(image, mesher).Mesh;
  DecimationParameters parameters;
  parameters.ImageToMeshDistance = mesher.ImageToMeshDistance;
  parameters.MeshToImageDistance = mesher.MeshToImageDistance;
  const DecimationResult reference = DecimateMesh(image, initial, parameters);
  ASSERT_GE(reference.Counts.VerticesBefore, 2 * kDecimationRegionVertices) << "too small to be cut into regions";
  ASSERT_LT(reference.Counts.CellsAfter * 4, reference.Counts.CellsBefore) << "it should decimate";
  for (unsigned threads : { 2u, 3u, 8u })
  {
    SetThreadLimit(threads);
    const DecimationResult result = DecimateMesh(image, initial, parameters);
    SetThreadLimit(0);
    EXPECT_EQ(result.Mesh.Points, reference.Mesh.Points) << threads << " threads";
    EXPECT_EQ(result.Mesh.Connectivity, reference.Mesh.Connectivity) << threads << " threads";
    EXPECT_EQ(result.Mesh.Materials, reference.Mesh.Materials) << threads << " threads";
    EXPECT_EQ(result.Interfaces.Connectivity, reference.Interfaces.Connectivity) << threads << " threads";
    EXPECT_EQ(result.Counts.Merges, reference.Counts.Merges) << threads << " threads";
    EXPECT_EQ(result.Counts.Offers, reference.Counts.Offers) << threads << " threads";
    EXPECT_EQ(result.Counts.RejectedByQuality, reference.Counts.RejectedByQuality) << threads << " threads";
    EXPECT_EQ(result.Counts.RejectedByTopology, reference.Counts.RejectedByTopology) << threads << " threads";
    EXPECT_EQ(result.Counts.RejectedByFidelity, reference.Counts.RejectedByFidelity) << threads << " threads";
  }
  SetThreadLimit(0);
}

TEST(Determinism, DecimatedTotalSegmentatorVolumeIsTheSameOnAnyNumberOfThreads)
{
  // About 160,000 vertices with the background, ten regions: the input on
  // which region runs once overlapped by one position (a vertex queued by the
  // run next to its own, edited by two threads at once; the meshes agreed,
  // the refusal counts did not).
  const LabelImage image = testing::ReadLabelImageFile(DataFile("totalseg_example_seg.nrrd", "3d/totalseg_example_seg.nrrd")).Image;
  ExpectDecimationDoesNotDependOnThreads(image, {});
}

TEST(Determinism, DecimatedCassiniIsTheSameOnAnyNumberOfThreads)
{
  ExpectDecimationDoesNotDependOnThreads(testing::MakeCassiniVolume(96), {});
}

} // namespace
} // namespace labelmesher
