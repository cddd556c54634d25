// SPDX-License-Identifier: GPL-2.0-or-later
// ImageBoundaryAnchors (the h(I,M) half of requirement 2 of section 3.1.3): every side of every
// image face of a 4 x 2 two-label image gets a certificate on a mesh whose interface lies a voxel
// off the image's only when the bound allows a voxel; a merge that tilts the interface away cannot
// be re-certified at a tight bound and can at a loose one.
#include "Decimation/EdgeCollapse.h"
#include "Decimation/EditableMesh.h"
#include "Decimation/ImageBoundary.h"
#include "Decimation/ImageBoundaryAnchors.h"
#include "TwoColumnImage.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <stdexcept>
#include <vector>

namespace
{
using labelmesher::EdgeCollapse;
using labelmesher::EditableMesh;
using labelmesher::ImageBoundary;
using labelmesher::ImageBoundaryAnchors;
using labelmesher::LabelImage;
using labelmesher::testing::Mesh;
using labelmesher::testing::TwoColumns;

TEST(ImageBoundaryAnchors, AnInitialMeshBeyondTheBoundIsRefused)
{
  // The mesh's interface at x = 0.5, a voxel left of the image's.
  const LabelImage image = TwoColumns();
  const EditableMesh off = Mesh(0.5);
  const ImageBoundary boundary(image);
  std::vector<std::uint8_t> frozen(off.Position.size(), 0);
  ImageBoundaryAnchors tight(boundary, 0.5);
  EXPECT_THROW(tight.Initialize(off, off.InterfaceFaces(), frozen), std::invalid_argument);
  ImageBoundaryAnchors loose(boundary, 1.0);
  EXPECT_NO_THROW(loose.Initialize(off, off.InterfaceFaces(), frozen));
  EXPECT_EQ(loose.NumberOfSides(), tight.NumberOfSides());
  EXPECT_GT(loose.NumberOfSides(), 0u);
}

TEST(ImageBoundaryAnchors, RecertifyAfterAMergeThatTiltsTheInterface)
{
  // 6 into 0 turns the interface into the diagonal 0-4: the image interface's lower half is then
  // up to 2 voxels from the mesh boundary between the labels.
  const LabelImage image = TwoColumns();
  const EditableMesh mesh = Mesh(1.5);
  const ImageBoundary boundary(image);
  EdgeCollapse merge;
  ASSERT_TRUE(merge.Plan(mesh, 6, 0));
  ASSERT_TRUE(merge.PlanInterfaces(mesh));
  for (const double h : { 0.5, 3.0 })
  {
    ImageBoundaryAnchors anchors(boundary, h);
    std::vector<std::uint8_t> frozen(mesh.Position.size(), 0);
    anchors.Initialize(mesh, mesh.InterfaceFaces(), frozen);
    std::vector<ImageBoundaryAnchors::Update> updates;
    EXPECT_EQ(anchors.Recertify(mesh, merge, updates), h > 2.0) << "h = " << h;
  }
}

} // namespace
