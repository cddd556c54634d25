// SPDX-License-Identifier: GPL-2.0-or-later
// The VTK adapter vtkMeshDecimator (Filters/vtkMeshDecimator.h) behind
// vtkLabelOctreeMesher, as a pipeline uses it: ports, the decimated cells and
// their arrays, the field data (parameters, counts, measured guarantees), the
// physical placement kept under a reflecting direction matrix, one error and
// an empty output for each kind of bad input, and abort. The core has its own
// tests (Decimation/TestMeshDecimator.cxx, Decimation/TestDecimatorProperties.cxx).

#include "FilterTestSupport.h"

#include "LabelMesherArrayNames.h"
#include "vtkLabelOctreeMesher.h"
#include "vtkMeshDecimator.h"

#include "vtkCellData.h"
#include "vtkCellTypes.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkStringArray.h"
#include "vtkUnstructuredGrid.h"

#include <gtest/gtest.h>

#include <functional>

namespace arrays = labelmesher::arrays;
using namespace labelmesher::testing;

namespace
{

/// mesher (background kept) -> decimator, on `image`.
struct Pipeline
{
  explicit Pipeline(vtkImageData* image)
  {
    Mesher->SetInputData(image);
    Mesher->SetIncludeBackground(true);
    Mesher->SetImageToMeshDistance(1.5);
    Mesher->SetMeshToImageDistance(2.0);
    Decimator->SetInputConnection(0, Mesher->GetOutputPort(0));
    Decimator->SetInputDataObject(1, image);
  }
  vtkNew<vtkLabelOctreeMesher> Mesher;
  vtkNew<vtkMeshDecimator> Decimator;
};

/// The mesher's output with one more cell, a vertex (labelled 1).
vtkSmartPointer<vtkUnstructuredGrid> WithAVertexCell(vtkAlgorithm* mesher)
{
  mesher->Update();
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->DeepCopy(mesher->GetOutputDataObject(0));
  const vtkIdType point = 0;
  const vtkIdType cell = grid->InsertNextCell(VTK_VERTEX, 1, &point);
  grid->GetCellData()->GetArray(labelmesher::arrays::Material)->InsertTuple1(cell, 1);
  return grid;
}

} // namespace

TEST(vtkMeshDecimator, DecimatesTheMesherOutputWithItsArraysAndFieldData)
{
  auto image = MakeVtkImage(MakeBallLabels(20, 7.5), { 0.5, 0.5, 0.5 }, { 10, -4, 2 });
  image->SetDirectionMatrix(0, 1, 0, 1, 0, 0, 0, 0, 1); // a reflection
  Pipeline pipeline(image);
  vtkMeshDecimator* decimator = pipeline.Decimator;
  EXPECT_EQ(decimator->GetNumberOfInputPorts(), 2);
  EXPECT_EQ(decimator->GetNumberOfOutputPorts(), 2);
  EXPECT_STREQ(decimator->GetInputPortInformation(0)->Get(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE()), "vtkUnstructuredGrid");
  EXPECT_STREQ(decimator->GetInputPortInformation(1)->Get(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE()), "vtkImageData");
  decimator->SetMinimumAngle(12.0);
  MessageRecorder errors(decimator, vtkCommand::ErrorEvent);
  decimator->Update();
  EXPECT_TRUE(errors.Messages.empty()) << errors.Messages.front();

  vtkUnstructuredGrid* out = decimator->GetOutput();
  vtkUnstructuredGrid* initial = pipeline.Mesher->GetOutput();
  ASSERT_GT(out->GetNumberOfCells(), 0);
  vtkNew<vtkCellTypes> types;
  out->GetCellTypes(types);
  ASSERT_EQ(types->GetNumberOfTypes(), 1);
  EXPECT_EQ(types->GetCellType(0), VTK_TETRA);
  double range[2];
  out->GetCellData()->GetScalars()->GetRange(range);
  EXPECT_EQ(range[0], 1.0) << "background dropped by default";
  EXPECT_EQ(range[1], 1.0);
  EXPECT_EQ(CountNonPositiveTetrahedra(out), 0);
  EXPECT_EQ(CountUnusedPoints(out), 0) << "the background's points go with its cells";
  EXPECT_EQ(CountUnusedPoints(decimator->GetInterfacesOutput()), 0);
  // Same physical place as the initial mesh: the bounds of the material.
  double before[6], after[6];
  pipeline.Mesher->SetIncludeBackground(false);
  pipeline.Mesher->Update();
  initial->GetBounds(before);
  out->GetBounds(after);
  for (int b = 0; b < 6; ++b)
    EXPECT_NEAR(after[b], before[b], 2.0 * 0.5 + 1e-9) << b; // within the 2-voxel bound
  pipeline.Mesher->SetIncludeBackground(true);
  decimator->Update();
  out = decimator->GetOutput();

  EXPECT_EQ(FieldScalar(out, arrays::AngleBound), 12.0);
  EXPECT_EQ(FieldScalar(out, arrays::ImageToMeshDistance), 1.5) << "taken from the mesher's field data";
  EXPECT_EQ(FieldScalar(out, arrays::MeshToImageDistance), 2.0);
  EXPECT_EQ(FieldScalar(out, arrays::VoxelSize), 0.5);
  EXPECT_EQ(FieldScalar(out, arrays::CellsAfter), out->GetNumberOfCells());
  EXPECT_LT(FieldScalar(out, arrays::CellsAfter) * 3, FieldScalar(out, arrays::CellsBefore));
  EXPECT_GT(FieldScalar(out, arrays::Merges), 0.0);
  EXPECT_GE(FieldScalar(out, arrays::MergeOffers), FieldScalar(out, arrays::Merges));
  EXPECT_GE(FieldScalar(out, arrays::MergesRejectedByQuality), 0.0);
  EXPECT_GE(FieldScalar(out, arrays::MinimumAngle), 12.0 - 1e-9);
  EXPECT_EQ(FieldScalar(out, arrays::InvertedCells), 0.0);
  EXPECT_EQ(FieldScalar(out, arrays::HausdorffBoundsCertified), 1.0);
  EXPECT_LE(FieldScalar(out, arrays::MeasuredImageToMeshDistance), 1.5 + 1e-9);
  EXPECT_LE(FieldScalar(out, arrays::MeasuredMeshToImageDistance), 2.0 + 1e-9);
  EXPECT_EQ(FieldScalar(out, arrays::TopologyMatches), 1.0);
  auto* names = vtkStringArray::SafeDownCast(out->GetFieldData()->GetAbstractArray(arrays::StageName));
  ASSERT_NE(names, nullptr);
  EXPECT_EQ(names->GetValue(0), "decimation setup");

  vtkPolyData* interfaces = decimator->GetInterfacesOutput();
  ASSERT_GT(interfaces->GetNumberOfPolys(), 0);
  EXPECT_NE(interfaces->GetCellData()->GetArray(arrays::Materials), nullptr);
  EXPECT_LT(interfaces->GetNumberOfPolys(), pipeline.Mesher->GetInterfacesOutput()->GetNumberOfPolys());

  // Relocation is on by default and is counted; off, no vertex moves and no
  // fewer cells stay (here its moves are all in the background; the core's
  // and the CLI's tests show the cells it saves).
  EXPECT_TRUE(decimator->GetRelocateInteriorVertices());
  EXPECT_GT(FieldScalar(out, arrays::VerticesRelocated), 0.0);
  const double relocated = FieldScalar(out, arrays::CellsAfter);
  decimator->RelocateInteriorVerticesOff();
  decimator->Update();
  out = decimator->GetOutput();
  EXPECT_EQ(FieldScalar(out, arrays::VerticesRelocated), 0.0);
  EXPECT_GE(FieldScalar(out, arrays::CellsAfter), relocated);
  EXPECT_GE(FieldScalar(out, arrays::MinimumAngle), 12.0 - 1e-9);
}

TEST(vtkMeshDecimator, TwoDimensionalImageGivesTrianglesInItsPlane)
{
  auto image = MakeVtkImage(MakeDiscSliceXZ(32, 12.0), { 1, 1, 1 }, { 0, 3, 0 });
  Pipeline pipeline(image);
  pipeline.Decimator->SetMinimumAngle(30.0);
  pipeline.Decimator->Update();
  vtkUnstructuredGrid* out = pipeline.Decimator->GetOutput();
  ASSERT_GT(out->GetNumberOfCells(), 0);
  EXPECT_EQ(out->GetCellType(0), VTK_TRIANGLE);
  double bounds[6];
  out->GetBounds(bounds);
  EXPECT_EQ(bounds[2], 3.0);
  EXPECT_EQ(bounds[3], 3.0);
  EXPECT_GE(FieldScalar(out, arrays::MinimumAngle), 30.0 - 1e-9);
  EXPECT_EQ(CountUnusedPoints(out), 0);
  EXPECT_EQ(CountUnusedPoints(pipeline.Decimator->GetInterfacesOutput()), 0);
}

TEST(vtkMeshDecimator, BadInputIsOneErrorAndAnEmptyOutput)
{
  auto image = MakeVtkImage(MakeBallLabels(12, 4.0));
  struct Case
  {
    const char* Name;
    std::function<void(Pipeline&)> Spoil;
    const char* Expected;
  };
  const std::vector<Case> cases = {
    { "no image on port 1", [](Pipeline& p) { p.Decimator->SetInputDataObject(1, nullptr); }, "port 1" },
    { "another image", [](Pipeline& p) { p.Decimator->SetInputDataObject(1, MakeVtkImage(MakeBallLabels(20, 6.0))); },
      "cover the image" },
    { "no background", [](Pipeline& p) { p.Mesher->SetIncludeBackground(false); }, "fill its box" },
    { "angle above the proven bound", [](Pipeline& p) { p.Decimator->SetMinimumAngle(35.0); }, "minimum angle" },
    { "memory limit", [](Pipeline& p) { p.Decimator->SetMemoryLimit(1.0); }, "memory limit of 1 MiB" },
    { "a cell that is not a tetrahedron", [](Pipeline& p) { p.Decimator->SetInputDataObject(0, WithAVertexCell(p.Mesher)); },
      "is not a tetrahedron (VTK type 1)" },
  };
  for (const Case& c : cases)
  {
    Pipeline pipeline(image);
    c.Spoil(pipeline);
    MessageRecorder errors(pipeline.Decimator, vtkCommand::ErrorEvent);
    pipeline.Decimator->Update();
    EXPECT_EQ(pipeline.Decimator->GetOutput()->GetNumberOfCells(), 0) << c.Name;
    ASSERT_EQ(errors.Messages.size(), 1u) << c.Name;
    EXPECT_NE(errors.Messages[0].find(c.Expected), std::string::npos) << c.Name << ": " << errors.Messages[0];
  }
  // A tighter bound than the mesh was made with (a 2D disc uses its
  // allowance; 3D meshes are voxel-exact and hold any bound).
  {
    auto disc = MakeVtkImage(MakeDiscSliceXZ(40, 15.0));
    Pipeline tighter(disc);
    tighter.Decimator->SetMeshToImageDistance(0.0);
    MessageRecorder errors(tighter.Decimator, vtkCommand::ErrorEvent);
    tighter.Decimator->Update();
    EXPECT_EQ(tighter.Decimator->GetOutput()->GetNumberOfCells(), 0);
    ASSERT_EQ(errors.Messages.size(), 1u);
    EXPECT_NE(errors.Messages[0].find("does not hold h("), std::string::npos) << errors.Messages[0];
  }
  // No Material array.
  Pipeline pipeline(image);
  pipeline.Mesher->Update();
  vtkNew<vtkUnstructuredGrid> bare;
  bare->ShallowCopy(pipeline.Mesher->GetOutput());
  bare->GetCellData()->RemoveArray(arrays::Material);
  vtkNew<vtkMeshDecimator> decimator;
  decimator->SetInputData(0, bare);
  decimator->SetInputDataObject(1, image);
  MessageRecorder errors(decimator, vtkCommand::ErrorEvent);
  decimator->Update();
  EXPECT_EQ(decimator->GetOutput()->GetNumberOfCells(), 0);
  ASSERT_EQ(errors.Messages.size(), 1u);
  EXPECT_NE(errors.Messages[0].find("Material"), std::string::npos) << errors.Messages[0];
}

TEST(vtkMeshDecimator, AbortStopsTheRunWithAnEmptyOutputAndAWarning)
{
  auto image = MakeVtkImage(MakeBallLabels(24, 9.0));
  Pipeline pipeline(image);
  pipeline.Mesher->Update();
  AbortAtStage abort(pipeline.Decimator, "decimation");
  MessageRecorder warnings(pipeline.Decimator, vtkCommand::WarningEvent);
  pipeline.Decimator->Update();
  EXPECT_TRUE(abort.Reached);
  EXPECT_EQ(pipeline.Decimator->GetOutput()->GetNumberOfCells(), 0);
  ASSERT_EQ(warnings.Messages.size(), 1u);
  EXPECT_NE(warnings.Messages[0].find("aborted"), std::string::npos);
}
