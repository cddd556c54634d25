// SPDX-License-Identifier: GPL-2.0-or-later
// The VTK adapter vtkBezierCurver (Filters/vtkBezierCurver.h) behind
// vtkLabelOctreeMesher, as a C++ pipeline uses it: ports, the cubic Bézier
// cells and their arrays, the field data (parameters, counts, pixel accuracy,
// timings), errors for bad input and abort. The core function has its own
// tests (TestBezierCurver.cxx); these test the plumbing around it.

#include "FilterTestSupport.h"

#include "LabelMesherArrayNames.h"
#include "vtkBezierCurver.h"
#include "vtkMeshDecimator.h"
#include "vtkLabelOctreeMesher.h"

#include "vtkCell.h"
#include "vtkCellData.h"
#include "vtkCellTypes.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkIntArray.h"
#include "vtkPointData.h"
#include "vtkInformation.h"
#include "vtkNew.h"
#include "vtkStringArray.h"
#include "vtkUnstructuredGrid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace arrays = labelmesher::arrays;
using namespace labelmesher::testing;

namespace
{

} // namespace

TEST(vtkBezierCurver, CurvesTheMesherOutputIntoValidCubicTrianglesWithItsArrays)
{
  auto image = MakeVtkImage(MakeDiscSliceXZ(32, 11.3), { 0.5, 0.5, 0.5 }, { 1, 2, 3 });
  vtkNew<vtkLabelOctreeMesher> mesher;
  mesher->SetInputData(image);
  vtkNew<vtkBezierCurver> curver;
  EXPECT_EQ(curver->GetNumberOfInputPorts(), 2);
  EXPECT_EQ(curver->GetNumberOfOutputPorts(), 1);
  EXPECT_STREQ(
    curver->GetInputPortInformation(0)->Get(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE()), "vtkUnstructuredGrid");
  EXPECT_EQ(curver->GetInputPortInformation(1)->Get(vtkAlgorithm::INPUT_IS_OPTIONAL()), 1);
  curver->SetInputConnection(0, mesher->GetOutputPort(0));
  curver->SetInputDataObject(1, image);
  curver->SetSmoothness(1);
  curver->SetTension(0.25);
  MessageRecorder errors(curver, vtkCommand::ErrorEvent);
  curver->Update();
  EXPECT_TRUE(errors.Messages.empty());

  vtkUnstructuredGrid* curved = curver->GetOutput();
  const vtkIdType linearCells = mesher->GetOutput()->GetNumberOfCells();
  ASSERT_GE(curved->GetNumberOfCells(), linearCells); // ears are split, never merged
  vtkNew<vtkCellTypes> types;
  curved->GetCellTypes(types);
  ASSERT_EQ(types->GetNumberOfTypes(), 1);
  EXPECT_EQ(types->GetCellType(0), VTK_BEZIER_TRIANGLE);
  EXPECT_EQ(curved->GetCell(0)->GetNumberOfPoints(), 10);
  double bounds[6];
  curved->GetBounds(bounds);
  EXPECT_EQ(bounds[2], 2.0); // stays in the image's plane y = 2
  EXPECT_EQ(bounds[3], 2.0);

  vtkDataArray* material = curved->GetCellData()->GetScalars();
  ASSERT_NE(material, nullptr);
  EXPECT_STREQ(material->GetName(), arrays::Material);
  vtkDataArray* lower = curved->GetCellData()->GetArray(arrays::MinimumJacobian);
  vtkDataArray* scaled = curved->GetCellData()->GetArray(arrays::ScaledJacobian);
  vtkDataArray* valid = curved->GetCellData()->GetArray(arrays::Valid);
  ASSERT_TRUE(lower && scaled && valid);
  for (vtkIdType c = 0; c < curved->GetNumberOfCells(); ++c)
  {
    EXPECT_GT(lower->GetComponent(c, 0), 0.0);
    EXPECT_GT(scaled->GetComponent(c, 0), 0.0);
    EXPECT_LE(scaled->GetComponent(c, 0), 1.0 + 1e-12);
    EXPECT_EQ(valid->GetComponent(c, 0), 1.0);
  }

  EXPECT_EQ(FieldScalar(curved, arrays::Smoothness), 1.0);
  EXPECT_EQ(FieldScalar(curved, arrays::Tension), 0.25);
  EXPECT_EQ(FieldScalar(curved, arrays::InvalidCells), 0.0);
  EXPECT_EQ(FieldScalar(curved, arrays::InterfaceChains), 1.0); // one closed circle
  EXPECT_EQ(FieldScalar(curved, arrays::ClosedInterfaceChains), 1.0);
  EXPECT_GT(FieldScalar(curved, arrays::CurvedEdges), 0.0);
  EXPECT_EQ(FieldScalar(curved, arrays::Pixels), 32.0 * 32.0);
  EXPECT_GE(FieldScalar(curved, arrays::MisclassifiedPixelsLinear), 0.0);
  EXPECT_GE(FieldScalar(curved, arrays::MisclassifiedPixelsCurved), 0.0);
  // The bounds the mesher recorded, kept on the curves (in voxels, although
  // the mesh is in physical units: the map from pixels is taken into account).
  const double resolution = FieldScalar(curved, arrays::CurvedMeasureResolution);
  EXPECT_GT(resolution, 0.0);
  EXPECT_LT(resolution, 0.01);
  EXPECT_EQ(FieldScalar(curved, arrays::ImageToMeshDistance), mesher->GetImageToMeshDistance());
  EXPECT_EQ(FieldScalar(curved, arrays::MeshToImageDistance), mesher->GetMeshToImageDistance());
  EXPECT_LE(FieldScalar(curved, arrays::MeasuredImageToMeshDistance), mesher->GetImageToMeshDistance() + resolution);
  EXPECT_LE(FieldScalar(curved, arrays::MeasuredMeshToImageDistance), mesher->GetMeshToImageDistance() + resolution);
  EXPECT_GT(FieldScalar(curved, arrays::MeasuredMeshToImageDistance), 0.0);
  EXPECT_EQ(FieldScalar(curved, arrays::InterfaceCrossings), 0.0);
  EXPECT_EQ(FieldScalar(curved, arrays::TopologyMatches), 1.0);
  EXPECT_EQ(FieldScalar(curved, arrays::UncertifiedPieces), 0.0);
  EXPECT_GE(FieldScalar(curved, arrays::UntanglingRounds), 1.0);
  EXPECT_LE(FieldScalar(curved, arrays::StraightenedPieces), FieldScalar(curved, arrays::ShortenedPieces));
  auto* names = vtkStringArray::SafeDownCast(curved->GetFieldData()->GetAbstractArray(arrays::StageName));
  ASSERT_NE(names, nullptr);
  EXPECT_EQ(names->GetValue(names->GetNumberOfValues() - 1), "curved distances");
}

/// Order 2: VTK_QUADRATIC_TRIANGLE cells on the input's vertices, shared mid-nodes, and a map that
/// VTK's own quadratic triangle evaluates with a positive Jacobian whose smallest over largest is
/// at least the bound at every sample (finite differences of EvaluateLocation).
TEST(vtkBezierCurver, OrderTwoGivesValidQuadraticTrianglesThatVTKEvaluates)
{
  auto image = MakeVtkImage(MakeDiscSliceXZ(32, 11.3), { 0.5, 0.5, 0.5 }, { 1, 2, 3 });
  vtkNew<vtkLabelOctreeMesher> mesher;
  mesher->SetInputData(image);
  vtkNew<vtkBezierCurver> curver;
  curver->SetInputConnection(0, mesher->GetOutputPort(0));
  curver->SetInputDataObject(1, image);
  curver->SetOrder(2);
  MessageRecorder errors(curver, vtkCommand::ErrorEvent);
  curver->Update();
  EXPECT_TRUE(errors.Messages.empty());
  vtkUnstructuredGrid* curved = curver->GetOutput();
  vtkNew<vtkCellTypes> types;
  curved->GetCellTypes(types);
  ASSERT_EQ(types->GetNumberOfTypes(), 1);
  EXPECT_EQ(types->GetCellType(0), VTK_QUADRATIC_TRIANGLE);
  EXPECT_EQ(FieldScalar(curved, arrays::Order), 2.0);
  EXPECT_EQ(FieldScalar(curved, arrays::InvalidCells), 0.0);
  EXPECT_GT(FieldScalar(curved, arrays::CurvedEdges), 0.0);
  EXPECT_LT(FieldScalar(curved, arrays::MisclassifiedPixelsCurved), FieldScalar(curved, arrays::MisclassifiedPixelsLinear));
  vtkUnstructuredGrid* linear = mesher->GetOutput();
  for (vtkIdType p = 0; p < linear->GetNumberOfPoints(); ++p)
  {
    double a[3], b[3];
    linear->GetPoint(p, a);
    curved->GetPoint(p, b);
    ASSERT_EQ(std::vector<double>(a, a + 3), std::vector<double>(b, b + 3)) << "vertex " << p << " moved";
  }
  // The image lies in y = 2: det J in (x, z), sign fixed by the first sample.
  double smallestRatio = 1.0, sign = 0.0;
  for (vtkIdType c = 0; c < curved->GetNumberOfCells(); ++c)
  {
    vtkCell* cell = curved->GetCell(c);
    ASSERT_EQ(cell->GetNumberOfPoints(), 6);
    double smallest = VTK_DOUBLE_MAX, largest = -VTK_DOUBLE_MAX;
    constexpr int n = 8;
    constexpr double h = 1e-6;
    for (int i = 0; i <= n; ++i)
      for (int j = 0; i + j <= n; ++j)
      {
        double r[3] = { (i + 0.25) / (n + 1.0), (j + 0.25) / (n + 1.0), 0.0 }, x0[3], xr[3], xs[3], w[6];
        int sub = 0;
        cell->EvaluateLocation(sub, r, x0, w);
        double rr[3] = { r[0] + h, r[1], 0.0 }, rs[3] = { r[0], r[1] + h, 0.0 };
        cell->EvaluateLocation(sub, rr, xr, w);
        cell->EvaluateLocation(sub, rs, xs, w);
        const double det = ((xr[0] - x0[0]) * (xs[2] - x0[2]) - (xr[2] - x0[2]) * (xs[0] - x0[0])) / (h * h);
        if (sign == 0.0)
          sign = det > 0.0 ? 1.0 : -1.0;
        smallest = std::min(smallest, sign * det);
        largest = std::max(largest, sign * det);
      }
    ASSERT_GT(smallest, 0.0) << "cell " << c << " inverted where VTK evaluates it";
    smallestRatio = std::min(smallestRatio, smallest / largest);
  }
  EXPECT_GE(smallestRatio, curver->GetMinimumScaledJacobian() - 1e-4);
}

TEST(vtkBezierCurver, DecimatedAndCurvedIsMoreAccurateThanLinearWithinTheBounds)
{
  // 60 x 60 (not a cube number, which MakeVtkImage would read as 3D).
  auto image = MakeVtkImage(MakeDiscSliceXZ(60, 22.3), { 0.5, 0.5, 0.5 }, { 1, 2, 3 });
  vtkNew<vtkLabelOctreeMesher> mesher;
  mesher->SetInputData(image);
  mesher->SetIncludeBackground(true);
  vtkNew<vtkMeshDecimator> decimator;
  decimator->SetInputConnection(0, mesher->GetOutputPort(0));
  decimator->SetInputDataObject(1, image);
  vtkNew<vtkBezierCurver> curver;
  curver->SetInputConnection(0, decimator->GetOutputPort(0));
  curver->SetInputDataObject(1, image);
  MessageRecorder errors(curver, vtkCommand::ErrorEvent);
  curver->Update();
  EXPECT_TRUE(errors.Messages.empty()) << (errors.Messages.empty() ? "" : errors.Messages[0]);
  vtkUnstructuredGrid* curved = curver->GetOutput();
  ASSERT_GT(curved->GetNumberOfCells(), 0);
  EXPECT_EQ(FieldScalar(curved, arrays::Smoothness), 1.0); // the default: fitted C1
  EXPECT_EQ(FieldScalar(curved, arrays::InvalidCells), 0.0);
  const double resolution = FieldScalar(curved, arrays::CurvedMeasureResolution);
  EXPECT_LE(FieldScalar(curved, arrays::MeasuredImageToMeshDistance), 2.0 + resolution);
  EXPECT_LE(FieldScalar(curved, arrays::MeasuredMeshToImageDistance), 2.0 + resolution);
  EXPECT_EQ(FieldScalar(curved, arrays::InterfaceCrossings), 0.0);
  EXPECT_EQ(FieldScalar(curved, arrays::TopologyMatches), 1.0);
  const double linear = FieldScalar(curved, arrays::MisclassifiedPixelsLinear);
  const double curvedPixels = FieldScalar(curved, arrays::MisclassifiedPixelsCurved);
  EXPECT_GT(linear, 0.0);
  EXPECT_LT(curvedPixels, 0.67 * linear) << "linear " << linear << ", curved " << curvedPixels;
}

TEST(vtkBezierCurver, ReadsTheLabelArraySelectedOnPort1)
{
  // The labels in a named array beside zero scalars: selected, they give the
  // curve of the plain image; the scalars alone would be an empty image.
  auto image = MakeVtkImage(MakeDiscSliceXZ(40, 14.3));
  vtkNew<vtkLabelOctreeMesher> mesher;
  mesher->SetInputData(image);
  auto curve = [&](vtkImageData* onPort1, const char* selected) {
    vtkNew<vtkBezierCurver> curver;
    curver->SetInputConnection(0, mesher->GetOutputPort(0));
    curver->SetInputDataObject(1, onPort1);
    if (selected)
      curver->SetInputArrayToProcess(0, 1, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, selected);
    MessageRecorder errors(curver, vtkCommand::ErrorEvent);
    curver->Update();
    EXPECT_TRUE(errors.Messages.empty()) << (errors.Messages.empty() ? "" : errors.Messages[0]);
    return FieldScalar(curver->GetOutput(), arrays::MisclassifiedPixelsCurved);
  };
  const double plain = curve(image, nullptr);
  vtkNew<vtkImageData> relabelled;
  relabelled->DeepCopy(image);
  vtkNew<vtkIntArray> labels;
  labels->DeepCopy(image->GetPointData()->GetScalars());
  labels->SetName("labels");
  vtkNew<vtkIntArray> zeros;
  zeros->SetName("intensity");
  zeros->SetNumberOfTuples(labels->GetNumberOfTuples());
  zeros->Fill(0);
  relabelled->GetPointData()->SetScalars(zeros);
  relabelled->GetPointData()->AddArray(labels);
  EXPECT_EQ(curve(relabelled, "labels"), plain);
}

TEST(vtkBezierCurver, BadInputIsOneErrorAndAnEmptyOutput)
{
  // Tetrahedra instead of triangles.
  {
    vtkNew<vtkLabelOctreeMesher> mesher;
    mesher->SetInputData(MakeVtkImage(MakeBallLabels(8, 2.5)));
    vtkNew<vtkBezierCurver> curver;
    curver->SetInputConnection(mesher->GetOutputPort(0));
    MessageRecorder errors(curver, vtkCommand::ErrorEvent);
    curver->Update();
    EXPECT_EQ(curver->GetOutput()->GetNumberOfCells(), 0);
    ASSERT_EQ(errors.Messages.size(), 1u);
    EXPECT_NE(errors.Messages[0].find("axis plane"), std::string::npos) << errors.Messages[0];
  }
  // No Material array.
  {
    vtkNew<vtkLabelOctreeMesher> mesher;
    mesher->SetInputData(MakeVtkImage(MakeDiscSliceXZ(12, 4.0)));
    mesher->Update();
    vtkNew<vtkUnstructuredGrid> bare;
    bare->ShallowCopy(mesher->GetOutput());
    bare->GetCellData()->RemoveArray(arrays::Material);
    vtkNew<vtkBezierCurver> curver;
    curver->SetInputData(bare);
    MessageRecorder errors(curver, vtkCommand::ErrorEvent);
    curver->Update();
    EXPECT_EQ(curver->GetOutput()->GetNumberOfCells(), 0);
    ASSERT_EQ(errors.Messages.size(), 1u);
    EXPECT_NE(errors.Messages[0].find("Material"), std::string::npos) << errors.Messages[0];
  }
  // A planar mesh with one cell that is not a triangle (a vertex).
  {
    vtkNew<vtkLabelOctreeMesher> mesher;
    mesher->SetInputData(MakeVtkImage(MakeDiscSliceXZ(12, 4.0)));
    mesher->Update();
    vtkNew<vtkUnstructuredGrid> mixed;
    mixed->DeepCopy(mesher->GetOutput());
    const vtkIdType point = 0;
    const vtkIdType cell = mixed->InsertNextCell(VTK_VERTEX, 1, &point);
    mixed->GetCellData()->GetArray(arrays::Material)->InsertTuple1(cell, 1);
    vtkNew<vtkBezierCurver> curver;
    curver->SetInputData(mixed);
    MessageRecorder errors(curver, vtkCommand::ErrorEvent);
    curver->Update();
    EXPECT_EQ(curver->GetOutput()->GetNumberOfCells(), 0);
    ASSERT_EQ(errors.Messages.size(), 1u);
    EXPECT_NE(errors.Messages[0].find("is not a triangle (VTK type 1)"), std::string::npos) << errors.Messages[0];
  }
  // A 3D image on port 1.
  {
    vtkNew<vtkLabelOctreeMesher> mesher;
    mesher->SetInputData(MakeVtkImage(MakeDiscSliceXZ(12, 4.0)));
    vtkNew<vtkBezierCurver> curver;
    curver->SetInputConnection(mesher->GetOutputPort(0));
    curver->SetInputDataObject(1, MakeVtkImage(MakeBallLabels(6, 2.0)));
    MessageRecorder errors(curver, vtkCommand::ErrorEvent);
    curver->Update();
    EXPECT_EQ(curver->GetOutput()->GetNumberOfCells(), 0);
    ASSERT_EQ(errors.Messages.size(), 1u);
    EXPECT_NE(errors.Messages[0].find("3D"), std::string::npos) << errors.Messages[0];
  }
}

TEST(vtkBezierCurver, AbortStopsTheRunWithAnEmptyOutputAndAWarning)
{
  vtkNew<vtkLabelOctreeMesher> mesher;
  mesher->SetInputData(MakeVtkImage(MakeDiscSliceXZ(48, 17.0)));
  vtkNew<vtkBezierCurver> curver;
  curver->SetInputConnection(mesher->GetOutputPort(0));
  AbortAtStage abort(curver, "");
  MessageRecorder warnings(curver, vtkCommand::WarningEvent);
  curver->Update();
  EXPECT_TRUE(abort.Reached);
  EXPECT_EQ(curver->GetOutput()->GetNumberOfCells(), 0);
  ASSERT_EQ(warnings.Messages.size(), 1u);
  EXPECT_NE(warnings.Messages[0].find("aborted"), std::string::npos);
}
