// SPDX-License-Identifier: GPL-2.0-or-later
// FidelityCheck and ImageBoundaryAnchors (requirement 2 of section 3.1.3) on a 4 x 2 image of two
// labels split at x = 1.5 and a mesh whose interface lies exactly there: a merge that slides the
// interface vertex along the interface keeps both distances at 0 and is accepted at any bound;
// one that tilts the interface to run from the box corner (-0.5, -0.5) (2 voxels from the image
// interface at its far end) is refused at h = 0.5 by either distance alone and accepted at h = 3.
#include "Decimation/EdgeCollapse.h"
#include "Decimation/EditableMesh.h"
#include "Decimation/FidelityCheck.h"
#include "Decimation/ImageBoundary.h"
#include "Decimation/ImageBoundaryAnchors.h"
#include "TwoColumnImage.h"
#include "Support/LabelImage.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <stdexcept>
#include <vector>

namespace
{
using labelmesher::EdgeCollapse;
using labelmesher::EditableMesh;
using labelmesher::FidelityCheck;
using labelmesher::ImageBoundary;
using labelmesher::ImageBoundaryAnchors;
using labelmesher::LabelImage;
using labelmesher::testing::Mesh;
using labelmesher::testing::TwoColumns;

/// The anchors certified on `mesh` at h(I,M) = h1, then whether the merge keeps h(M,I) <= h2 and h(I,M) <= h1.
bool Accepts(const LabelImage& image, const EditableMesh& mesh, double h1, double h2, int from, int to)
{
  const ImageBoundary boundary(image);
  ImageBoundaryAnchors anchors(boundary, h1);
  std::vector<std::uint8_t> frozen(mesh.Position.size(), 0);
  anchors.Initialize(mesh, mesh.InterfaceFaces(), frozen);
  FidelityCheck fidelity(boundary, anchors, h2);
  EdgeCollapse merge;
  EXPECT_TRUE(merge.Plan(mesh, from, to));
  EXPECT_TRUE(merge.PlanInterfaces(mesh));
  return fidelity.Accepts(mesh, merge);
}

TEST(FidelityCheck, InterfaceFacesOfTheInitialMeshLieOnTheImageInterface)
{
  const LabelImage image = TwoColumns();
  const EditableMesh mesh = Mesh(1.5);
  const ImageBoundary boundary(image);
  ImageBoundaryAnchors anchors(boundary, 0.0);
  std::vector<std::uint8_t> frozen(mesh.Position.size(), 0);
  ASSERT_NO_THROW(anchors.Initialize(mesh, mesh.InterfaceFaces(), frozen));
  FidelityCheck fidelity(boundary, anchors, 0.0);
  for (const auto& face : mesh.InterfaceFaces())
    EXPECT_TRUE(fidelity.FaceWithinBound(mesh, face));
}

TEST(FidelityCheck, SlidingAlongTheInterfaceKeepsBothDistances)
{
  const LabelImage image = TwoColumns();
  EXPECT_TRUE(Accepts(image, Mesh(1.5), 0.0, 0.0, 6, 1));
  EXPECT_TRUE(Accepts(image, Mesh(1.5), 0.0, 0.0, 6, 4));
}

TEST(FidelityCheck, TheBoundDecidesAMergeThatTiltsTheInterface)
{
  // 6 into 0: the interface becomes the diagonal 0-4, whose end 0 lies 2 voxels from the image
  // interface (h(M,I) = 2), and the image interface's lower half is then up to 2 voxels from it.
  const LabelImage image = TwoColumns();
  EXPECT_FALSE(Accepts(image, Mesh(1.5), 0.5, 0.5, 6, 0));
  EXPECT_FALSE(Accepts(image, Mesh(1.5), 3.0, 0.5, 6, 0)) << "h(M,I) alone must refuse it";
  EXPECT_FALSE(Accepts(image, Mesh(1.5), 0.5, 3.0, 6, 0)) << "h(I,M) alone must refuse it";
  EXPECT_TRUE(Accepts(image, Mesh(1.5), 3.0, 3.0, 6, 0));
}

} // namespace
