// SPDX-License-Identifier: GPL-2.0-or-later
// The VTK adapter vtkLabelOctreeMesher (Filters/vtkLabelOctreeMesher.h) as a
// pipeline sees it: its ports and their data types, the arrays and field data
// its header promises, physical placement, errors for bad input (one error
// event, empty output, no crash) and abort. The core function has its own
// tests (TestLabelOctreeMesher.cxx); these test the plumbing around it.

#include "FilterTestSupport.h"

#include "LabelMesherArrayNames.h"
#include "vtkLabelOctreeMesher.h"

#include "vtkCellData.h"
#include "vtkCellTypes.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkStringArray.h"
#include "vtkUnstructuredGrid.h"

#include <gtest/gtest.h>

#include <cmath>

namespace arrays = labelmesher::arrays;
using namespace labelmesher::testing;

namespace
{

vtkDataArray* Field(vtkDataObject* data, const char* name)
{
  return data->GetFieldData()->GetArray(name);
}

} // namespace

TEST(vtkLabelOctreeMesher, PortsTakeImageDataAndGiveAGridAndItsInterfaces)
{
  vtkNew<vtkLabelOctreeMesher> mesher;
  EXPECT_EQ(mesher->GetNumberOfInputPorts(), 1);
  EXPECT_EQ(mesher->GetNumberOfOutputPorts(), 2);
  EXPECT_STREQ(mesher->GetInputPortInformation(0)->Get(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE()), "vtkImageData");

  auto image = MakeVtkImage(MakeBallLabels(12, 3.5), { 0.5, 0.5, 0.5 }, { 10, -4, 2 });
  mesher->SetInputData(image);
  mesher->Update();
  vtkUnstructuredGrid* grid = mesher->GetOutput();
  vtkPolyData* interfaces = mesher->GetInterfacesOutput();
  ASSERT_NE(grid, nullptr);
  ASSERT_NE(interfaces, nullptr);
  ASSERT_GT(grid->GetNumberOfCells(), 0);
  EXPECT_EQ(vtkPolyData::SafeDownCast(mesher->GetOutputDataObject(1)), interfaces);
  EXPECT_EQ(CountUnusedPoints(grid), 0);
  EXPECT_EQ(CountUnusedPoints(interfaces), 0) << "the interfaces keep only their own points";

  // Port 0: tetrahedra only, Material (int) as the active cell scalars, no background.
  vtkNew<vtkCellTypes> types;
  grid->GetCellTypes(types);
  ASSERT_EQ(types->GetNumberOfTypes(), 1);
  EXPECT_EQ(types->GetCellType(0), VTK_TETRA);
  vtkDataArray* material = grid->GetCellData()->GetScalars();
  ASSERT_NE(material, nullptr);
  EXPECT_STREQ(material->GetName(), arrays::Material);
  EXPECT_EQ(material->GetDataType(), VTK_INT);
  double range[2];
  material->GetRange(range);
  EXPECT_EQ(range[0], 1.0);
  EXPECT_EQ(range[1], 1.0);

  // Port 1: triangles with the two labels on either side, one of them 1.
  EXPECT_GT(interfaces->GetNumberOfPolys(), 0);
  vtkDataArray* sides = interfaces->GetCellData()->GetArray(arrays::Materials);
  ASSERT_NE(sides, nullptr);
  ASSERT_EQ(sides->GetNumberOfComponents(), 2);
  ASSERT_EQ(sides->GetNumberOfTuples(), interfaces->GetNumberOfPolys());
  for (vtkIdType f = 0; f < sides->GetNumberOfTuples(); ++f)
  {
    const double a = sides->GetComponent(f, 0), b = sides->GetComponent(f, 1);
    EXPECT_NE(a, b);
    EXPECT_TRUE(a == 1 || b == 1);
  }
}

TEST(vtkLabelOctreeMesher, FieldDataRecordsParametersTimingsAndMeasuredGuarantees)
{
  vtkNew<vtkLabelOctreeMesher> mesher;
  mesher->SetImageToMeshDistance(1.5);
  mesher->SetMeshToImageDistance(1.0);
  mesher->SetInputData(MakeVtkImage(MakeBallLabels(14, 4.5), { 2.0, 2.0, 2.0 }));
  mesher->Update();
  vtkUnstructuredGrid* grid = mesher->GetOutput();
  ASSERT_GT(grid->GetNumberOfCells(), 0);

  EXPECT_EQ(Field(grid, arrays::ImageToMeshDistance)->GetComponent(0, 0), 1.5);
  EXPECT_EQ(Field(grid, arrays::MeshToImageDistance)->GetComponent(0, 0), 1.0);
  EXPECT_EQ(Field(grid, arrays::IncludeBackground)->GetComponent(0, 0), 0.0);
  EXPECT_EQ(Field(grid, arrays::VoxelSize)->GetComponent(0, 0), 2.0);
  EXPECT_GT(Field(grid, arrays::NumberOfLeaves)->GetComponent(0, 0), 0.0);

  auto* names = vtkStringArray::SafeDownCast(grid->GetFieldData()->GetAbstractArray(arrays::StageName));
  vtkDataArray* seconds = Field(grid, arrays::StageSeconds);
  ASSERT_NE(names, nullptr);
  ASSERT_NE(seconds, nullptr);
  ASSERT_EQ(names->GetNumberOfValues(), seconds->GetNumberOfTuples());
  EXPECT_EQ(names->GetValue(0), "label pyramid");
  EXPECT_EQ(names->GetValue(names->GetNumberOfValues() - 1), "measure: topology");

  // The measured figures are the guarantees (30 degrees, both bounds, topology).
  EXPECT_GE(Field(grid, arrays::MinimumAngle)->GetComponent(0, 0), 30.0 - 1e-9);
  EXPECT_EQ(Field(grid, arrays::InvertedCells)->GetComponent(0, 0), 0.0);
  EXPECT_EQ(Field(grid, arrays::OverSharedFaces)->GetComponent(0, 0), 0.0);
  EXPECT_EQ(Field(grid, arrays::HangingVertices)->GetComponent(0, 0), 0.0);
  EXPECT_EQ(Field(grid, arrays::NonManifoldBoundaryEdges)->GetComponent(0, 0), 0.0);
  EXPECT_LE(Field(grid, arrays::MeasuredImageToMeshDistance)->GetComponent(0, 0), 1.5 + 1e-9);
  EXPECT_LE(Field(grid, arrays::MeasuredMeshToImageDistance)->GetComponent(0, 0), 1.0 + 1e-9);
  vtkDataArray* topologyMaterial = Field(grid, arrays::TopologyMaterial);
  ASSERT_NE(topologyMaterial, nullptr);
  ASSERT_EQ(topologyMaterial->GetNumberOfTuples(), 1);
  EXPECT_EQ(topologyMaterial->GetComponent(0, 0), 1.0);
  EXPECT_EQ(Field(grid, arrays::ImageComponents)->GetComponent(0, 0), 1.0);
  EXPECT_EQ(Field(grid, arrays::ImageEulerCharacteristic)->GetComponent(0, 0), 1.0);
  EXPECT_EQ(Field(grid, arrays::MeshComponents)->GetComponent(0, 0), 1.0);
  EXPECT_EQ(Field(grid, arrays::MeshEulerCharacteristic)->GetComponent(0, 0), 1.0);
  EXPECT_EQ(Field(grid, arrays::TopologyMatches)->GetComponent(0, 0), 1.0);

  // Without measuring, no measured array is there: nothing looks verified that was not.
  mesher->SetMeasureOutput(false);
  mesher->Update();
  for (const char* name : { arrays::MinimumAngle, arrays::MeasuredImageToMeshDistance, arrays::TopologyMatches,
         arrays::HangingVertices })
    EXPECT_EQ(Field(mesher->GetOutput(), name), nullptr) << name;
  EXPECT_GT(mesher->GetOutput()->GetNumberOfCells(), 0);
}

TEST(vtkLabelOctreeMesher, PointsArePhysicalAndBackgroundIsKeptOnRequest)
{
  // Spacing 0.5, origin (10, -4, 2), direction: x and y swapped (a reflection,
  // which must not flip the tetrahedra's orientation).
  auto image = MakeVtkImage(MakeBallLabels(12, 3.5), { 0.5, 0.5, 0.5 }, { 10, -4, 2 });
  image->SetDirectionMatrix(0, 1, 0, 1, 0, 0, 0, 0, 1);
  vtkNew<vtkLabelOctreeMesher> mesher;
  mesher->SetInputData(image);
  mesher->SetIncludeBackground(true);
  mesher->Update();
  vtkUnstructuredGrid* grid = mesher->GetOutput();
  double bounds[6];
  grid->GetBounds(bounds);
  // The padded octree domain starts half a voxel before voxel 0 along each axis.
  EXPECT_NEAR(bounds[0], 10 - 0.25, 1e-9); // physical x = origin x + index y * spacing
  EXPECT_NEAR(bounds[2], -4 - 0.25, 1e-9);
  EXPECT_NEAR(bounds[4], 2 - 0.25, 1e-9);
  double range[2];
  grid->GetCellData()->GetScalars()->GetRange(range);
  EXPECT_EQ(range[0], 0.0) << "background cells kept";
  EXPECT_EQ(Field(grid, arrays::IncludeBackground)->GetComponent(0, 0), 1.0);
  EXPECT_EQ(Field(grid, arrays::InvertedCells)->GetComponent(0, 0), 0.0);
  EXPECT_EQ(CountNonPositiveTetrahedra(grid), 0);
}

TEST(vtkLabelOctreeMesher, SingleSliceImageGivesTrianglesInItsPlane)
{
  // A disc in the x-z plane (one slice along y at y = 3).
  auto image = MakeVtkImage(MakeDiscSliceXZ(16, 5.5), { 1.0, 1.0, 1.0 }, { 0, 3, 0 });
  vtkNew<vtkLabelOctreeMesher> mesher;
  mesher->SetInputData(image);
  mesher->Update();
  vtkUnstructuredGrid* grid = mesher->GetOutput();
  ASSERT_GT(grid->GetNumberOfCells(), 0);
  vtkNew<vtkCellTypes> types;
  grid->GetCellTypes(types);
  ASSERT_EQ(types->GetNumberOfTypes(), 1);
  EXPECT_EQ(types->GetCellType(0), VTK_TRIANGLE);
  double bounds[6];
  grid->GetBounds(bounds);
  EXPECT_EQ(bounds[2], 3.0);
  EXPECT_EQ(bounds[3], 3.0);
  EXPECT_GE(Field(grid, arrays::MinimumAngle)->GetComponent(0, 0), 45.0 - 1e-9);
  EXPECT_GT(mesher->GetInterfacesOutput()->GetNumberOfLines(), 0);
  EXPECT_EQ(CountUnusedPoints(mesher->GetInterfacesOutput()), 0);
}

TEST(vtkLabelOctreeMesher, BadInputIsOneErrorAndAnEmptyOutput)
{
  struct Case
  {
    const char* Name;
    vtkSmartPointer<vtkImageData> Image;
    const char* Expected; // a phrase of the error
  };
  std::vector<Case> cases;
  cases.push_back({ "no foreground", MakeVtkImage(std::vector<int>(27, 0)), "foreground" });
  std::vector<int> negative(27, 1);
  negative[4] = -2;
  cases.push_back({ "negative label", MakeVtkImage(negative), "negative" });
  {
    auto image = MakeVtkImage(MakeBallLabels(6, 2.0));
    vtkNew<vtkFloatArray> fractional;
    fractional->SetName("Labels");
    fractional->SetNumberOfValues(image->GetNumberOfPoints());
    for (vtkIdType p = 0; p < image->GetNumberOfPoints(); ++p)
      fractional->SetValue(p, p == 7 ? 1.5f : 1.0f);
    image->GetPointData()->SetScalars(fractional);
    cases.push_back({ "fractional label", image, "integer" });
  }
  {
    auto image = vtkSmartPointer<vtkImageData>::New();
    image->SetDimensions(3, 3, 3);
    cases.push_back({ "no scalars", image, "" });
  }
  // Resampled to cubes of 1e-6 mm the 6^3 image would need 2e20 voxels (found by fuzzing: it
  // asked for 7 GB and more); one sentence instead.
  cases.push_back({ "too anisotropic", MakeVtkImage(MakeBallLabels(6, 2.0), { 1.0, 1.0, 1e-6 }), "too anisotropic" });
  for (const Case& c : cases)
  {
    vtkNew<vtkLabelOctreeMesher> mesher;
    MessageRecorder errors(mesher, vtkCommand::ErrorEvent);
    mesher->SetInputData(c.Image);
    mesher->Update();
    EXPECT_EQ(mesher->GetOutput()->GetNumberOfCells(), 0) << c.Name;
    ASSERT_EQ(errors.Messages.size(), 1u) << c.Name;
    EXPECT_NE(errors.Messages[0].find(c.Expected), std::string::npos) << c.Name << ": " << errors.Messages[0];
  }
}

TEST(vtkLabelOctreeMesher, MemoryLimitRefusesARunBeforeItStarts)
{
  auto image = MakeVtkImage(MakeBallLabels(24, 9.0));
  for (bool decimation : { false, true })
  {
    vtkNew<vtkLabelOctreeMesher> mesher;
    MessageRecorder errors(mesher, vtkCommand::ErrorEvent);
    mesher->SetInputData(image);
    mesher->SetMemoryLimit(1.0); // MiB: less than the process holds already
    mesher->SetCheckMemoryForDecimation(decimation);
    mesher->Update();
    EXPECT_EQ(mesher->GetOutput()->GetNumberOfCells(), 0);
    ASSERT_EQ(errors.Messages.size(), 1u);
    EXPECT_NE(errors.Messages[0].find("needs about"), std::string::npos) << errors.Messages[0];
    EXPECT_NE(errors.Messages[0].find("memory limit of 1 MiB"), std::string::npos) << errors.Messages[0];
  }
  // The estimate is recorded, and counting a decimation makes it no smaller.
  double estimate[2] = { 0.0, 0.0 };
  for (bool decimation : { false, true })
  {
    vtkNew<vtkLabelOctreeMesher> mesher;
    mesher->SetInputData(image);
    mesher->SetMeasureOutput(false);
    mesher->SetMemoryLimit(64.0 * 1024); // 64 GiB: replaces the machine's available memory
    mesher->SetCheckMemoryForDecimation(decimation);
    mesher->Update();
    EXPECT_GT(mesher->GetOutput()->GetNumberOfCells(), 0);
    estimate[decimation] = Field(mesher->GetOutput(), arrays::EstimatedMemory)->GetComponent(0, 0);
    EXPECT_GT(Field(mesher->GetOutput(), arrays::InterfaceFaces)->GetComponent(0, 0), 0.0);
  }
  EXPECT_GT(estimate[0], 0.0);
  EXPECT_GE(estimate[1], estimate[0]);
}

TEST(vtkLabelOctreeMesher, AbortStopsTheRunWithAnEmptyOutputAndAWarning)
{
  for (const char* stopAt : { "octree", "fill", "measure" })
  {
    vtkNew<vtkLabelOctreeMesher> mesher;
    mesher->SetInputData(MakeVtkImage(MakeBallLabels(24, 9.0)));
    AbortAtStage abort(mesher, stopAt);
    MessageRecorder warnings(mesher, vtkCommand::WarningEvent);
    MessageRecorder errors(mesher, vtkCommand::ErrorEvent);
    mesher->Update();
    EXPECT_TRUE(abort.Reached) << stopAt;
    if (std::string(stopAt) == "measure")
    {
      // The mesh is made; measuring is the last stage and the checks do not
      // poll: the output stays complete.
      EXPECT_GT(mesher->GetOutput()->GetNumberOfCells(), 0);
      continue;
    }
    EXPECT_EQ(mesher->GetOutput()->GetNumberOfCells(), 0) << stopAt;
    EXPECT_EQ(errors.Messages.size(), 0u) << stopAt;
    ASSERT_EQ(warnings.Messages.size(), 1u) << stopAt;
    EXPECT_NE(warnings.Messages[0].find("aborted"), std::string::npos);
  }
}
