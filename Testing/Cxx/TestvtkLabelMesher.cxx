// SPDX-License-Identifier: GPL-2.0-or-later
// The VTK adapter vtkLabelMesher (Filters/vtkLabelMesher.h), the one pipeline
// of every front end (mesher and decimator streamed block by block, or the
// mesher alone; then, 2D, the curver), as a pipeline uses it: ports, the cells
// and their arrays, the field data (parameters, counts, streaming figures,
// measured guarantees), the physical placement, one block equal to
// vtkLabelOctreeMesher + vtkMeshDecimator, Decimate off equal to the mesher,
// Curve equal to vtkBezierCurver on the linear mesh, many blocks keeping the
// measured guarantees, one progress over the whole run, one error and an empty
// output for bad input, and abort in every stage. The core has its own tests
// (Streaming/TestStreamedPipeline.cxx).

#include "FilterTestSupport.h"

#include "LabelMesherArrayNames.h"
#include "vtkBezierCurver.h"
#include "vtkLabelMesher.h"
#include "vtkLabelOctreeMesher.h"
#include "vtkMeshDecimator.h"

#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellTypes.h"
#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkIntArray.h"
#include "vtkPointData.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnstructuredGrid.h"

#include <gtest/gtest.h>

#include <set>

#include <algorithm>
#include <functional>
#include <string>
#include <vector>

namespace arrays = labelmesher::arrays;
using namespace labelmesher::testing;

namespace
{
/// Two balls of labels 1 and 2 side by side in an n^3 volume, so that blocks
/// cut interfaces of both.
std::vector<int> TwoBalls(int n)
{
  std::vector<int> labels = MakeBallLabels(n, n / 3.2);
  const double c[3] = { n * 0.72, n * 0.55, n * 0.4 };
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        if ((i - c[0]) * (i - c[0]) + (j - c[1]) * (j - c[1]) + (k - c[2]) * (k - c[2]) <= n * n / 25.0)
          labels[(static_cast<std::size_t>(k) * n + j) * n + i] = 2;
  return labels;
}

bool SameGrid(vtkUnstructuredGrid* a, vtkUnstructuredGrid* b)
{
  if (a->GetNumberOfCells() != b->GetNumberOfCells() || a->GetNumberOfPoints() != b->GetNumberOfPoints())
    return false;
  for (vtkIdType p = 0; p < a->GetNumberOfPoints(); ++p)
  {
    double x[3], y[3];
    a->GetPoint(p, x);
    b->GetPoint(p, y);
    if (x[0] != y[0] || x[1] != y[1] || x[2] != y[2])
      return false;
  }
  vtkIdType na = 0, nb = 0;
  const vtkIdType *pa = nullptr, *pb = nullptr;
  for (vtkIdType c = 0; c < a->GetNumberOfCells(); ++c)
  {
    a->GetCells()->GetCellAtId(c, na, pa);
    b->GetCells()->GetCellAtId(c, nb, pb);
    if (na != nb || !std::equal(pa, pa + na, pb))
      return false;
  }
  return true;
}
} // namespace

TEST(vtkLabelMesher, MeshesAndDecimatesWithItsArraysAndFieldData)
{
  auto image = MakeVtkImage(TwoBalls(24), { 0.5, 0.5, 0.5 }, { 10, -4, 2 });
  image->SetDirectionMatrix(0, 1, 0, 1, 0, 0, 0, 0, 1); // a reflection
  vtkNew<vtkLabelMesher> mesher;
  EXPECT_EQ(mesher->GetNumberOfInputPorts(), 1);
  EXPECT_EQ(mesher->GetNumberOfOutputPorts(), 3);
  EXPECT_STREQ(mesher->GetInputPortInformation(0)->Get(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE()), "vtkImageData");
  mesher->SetInputData(image);
  mesher->SetImageToMeshDistance(1.5);
  mesher->SetMinimumAngle(12.0);
  mesher->SetBlockCells(3000);
  MessageRecorder errors(mesher, vtkCommand::ErrorEvent);
  mesher->Update();
  EXPECT_TRUE(errors.Messages.empty()) << errors.Messages.front();

  vtkUnstructuredGrid* out = mesher->GetOutput();
  ASSERT_GT(out->GetNumberOfCells(), 0);
  vtkNew<vtkCellTypes> types;
  out->GetCellTypes(types);
  ASSERT_EQ(types->GetNumberOfTypes(), 1);
  EXPECT_EQ(types->GetCellType(0), VTK_TETRA);
  double range[2];
  out->GetCellData()->GetScalars()->GetRange(range);
  EXPECT_EQ(range[0], 1.0) << "background dropped by default";
  EXPECT_EQ(range[1], 2.0);
  EXPECT_EQ(CountNonPositiveTetrahedra(out), 0);
  EXPECT_EQ(CountUnusedPoints(out), 0);
  EXPECT_EQ(CountUnusedPoints(mesher->GetInterfacesOutput()), 0);
  EXPECT_GT(mesher->GetInterfacesOutput()->GetNumberOfPolys(), 0);

  EXPECT_GE(FieldScalar(out, arrays::Blocks), 3.0) << "the image crosses block borders";
  EXPECT_LE(FieldScalar(out, arrays::LargestBlockCells), 3000.0 + 200.0) << "a block closes once it holds 3000 cells";
  EXPECT_GT(FieldScalar(out, arrays::AssembledCells), 0.0);
  EXPECT_GT(FieldScalar(out, arrays::BorderPasses), 0.0) << "the blocks so far are resolved between blocks";
  EXPECT_GE(FieldScalar(out, arrays::LargestAssembledCells), FieldScalar(out, arrays::AssembledCells));
  EXPECT_GT(FieldScalar(out, arrays::NumberOfLeaves), 0.0);
  EXPECT_GT(FieldScalar(out, arrays::InterfaceFaces), 0.0);
  EXPECT_GT(FieldScalar(out, arrays::EstimatedMemory), 0.0);
  EXPECT_EQ(FieldScalar(out, arrays::AngleBound), 12.0);
  EXPECT_EQ(FieldScalar(out, arrays::ImageToMeshDistance), 1.5);
  EXPECT_EQ(FieldScalar(out, arrays::MeshToImageDistance), 2.0);
  EXPECT_EQ(FieldScalar(out, arrays::VoxelSize), 0.5);
  EXPECT_EQ(FieldScalar(out, arrays::CellsAfter), out->GetNumberOfCells());
  EXPECT_LT(FieldScalar(out, arrays::CellsAfter) * 3, FieldScalar(out, arrays::CellsBefore));
  // The measured guarantees, by the independent checks.
  EXPECT_GE(FieldScalar(out, arrays::MinimumAngle), 12.0 - 1e-9);
  EXPECT_EQ(FieldScalar(out, arrays::InvertedCells), 0.0);
  EXPECT_EQ(FieldScalar(out, arrays::OverSharedFaces), 0.0);
  EXPECT_EQ(FieldScalar(out, arrays::HangingVertices), 0.0);
  EXPECT_EQ(FieldScalar(out, arrays::HausdorffBoundsCertified), 1.0);
  EXPECT_LE(FieldScalar(out, arrays::MeasuredImageToMeshDistance), 1.5 + 1e-9);
  EXPECT_LE(FieldScalar(out, arrays::MeasuredMeshToImageDistance), 2.0 + 1e-9);
  vtkDataArray* matches = out->GetFieldData()->GetArray(arrays::TopologyMatches);
  ASSERT_NE(matches, nullptr);
  for (vtkIdType t = 0; t < matches->GetNumberOfTuples(); ++t)
    EXPECT_EQ(matches->GetComponent(t, 0), 1.0) << "material " << t;
}

TEST(vtkLabelMesher, OneBlockIsTheMesherFollowedByTheDecimator)
{
  auto image = MakeVtkImage(TwoBalls(20), { 0.7, 0.7, 0.7 }, { 1, 2, 3 });
  vtkNew<vtkLabelMesher> streamed;
  streamed->SetInputData(image);
  streamed->SetBlockCells(0);
  streamed->MeasureOutputOff();
  streamed->Update();
  vtkNew<vtkLabelOctreeMesher> mesher;
  mesher->SetInputData(image);
  mesher->IncludeBackgroundOn();
  mesher->MeasureOutputOff();
  vtkNew<vtkMeshDecimator> decimator;
  decimator->SetInputConnection(0, mesher->GetOutputPort(0));
  decimator->SetInputDataObject(1, image);
  decimator->MeasureOutputOff();
  decimator->Update();
  EXPECT_EQ(FieldScalar(streamed->GetOutput(), arrays::Blocks), 1.0);
  EXPECT_TRUE(SameGrid(streamed->GetOutput(), decimator->GetOutput()));
  EXPECT_EQ(FieldScalar(streamed->GetOutput(), arrays::CellsBefore), FieldScalar(decimator->GetOutput(), arrays::CellsBefore));
}

TEST(vtkLabelMesher, TwoDimensionalImageGivesTrianglesInItsPlane)
{
  auto image = MakeVtkImage2D(MakeDiscSliceXZ(40, 14.0), 40, 40);
  vtkNew<vtkLabelMesher> mesher;
  mesher->SetInputData(image);
  mesher->SetMinimumAngle(30.0);
  mesher->SetBlockCells(200);
  mesher->Update();
  vtkUnstructuredGrid* out = mesher->GetOutput();
  ASSERT_GT(out->GetNumberOfCells(), 0);
  EXPECT_EQ(out->GetCellType(0), VTK_TRIANGLE);
  EXPECT_GE(FieldScalar(out, arrays::Blocks), 2.0);
  EXPECT_GE(FieldScalar(out, arrays::MinimumAngle), 30.0 - 1e-9);
  EXPECT_EQ(FieldScalar(out, arrays::HausdorffBoundsCertified), 1.0);
}

TEST(vtkLabelMesher, BadInputIsOneErrorAndAnEmptyOutput)
{
  struct Case
  {
    const char* Name;
    std::function<void(vtkLabelMesher*)> Spoil;
    const char* Expected;
  };
  const std::vector<Case> cases = {
    { "angle above the proven bound", [](vtkLabelMesher* m) { m->SetMinimumAngle(35.0); }, "minimum angle" },
    { "memory limit", [](vtkLabelMesher* m) { m->SetMemoryLimit(1.0); }, "memory limit of 1 MiB" },
    { "no foreground", [](vtkLabelMesher* m) { m->SetInputData(MakeVtkImage(std::vector<int>(8 * 8 * 8, 0))); },
      "no foreground" },
  };
  for (const Case& c : cases)
  {
    vtkNew<vtkLabelMesher> mesher;
    mesher->SetInputData(MakeVtkImage(MakeBallLabels(12, 4.0)));
    c.Spoil(mesher);
    MessageRecorder errors(mesher, vtkCommand::ErrorEvent);
    mesher->Update();
    EXPECT_EQ(mesher->GetOutput()->GetNumberOfCells(), 0) << c.Name;
    ASSERT_EQ(errors.Messages.size(), 1u) << c.Name;
    EXPECT_NE(errors.Messages[0].find(c.Expected), std::string::npos) << c.Name << ": " << errors.Messages[0];
  }
}

TEST(vtkLabelMesher, AbortStopsTheRunWithAnEmptyOutputAndAWarning)
{
  vtkNew<vtkLabelMesher> mesher;
  mesher->SetInputData(MakeVtkImage(TwoBalls(24)));
  mesher->SetBlockCells(3000);
  AbortAtStage abort(mesher, "decimation");
  MessageRecorder warnings(mesher, vtkCommand::WarningEvent);
  mesher->Update();
  EXPECT_TRUE(abort.Reached);
  EXPECT_EQ(mesher->GetOutput()->GetNumberOfCells(), 0);
  ASSERT_EQ(warnings.Messages.size(), 1u);
  EXPECT_NE(warnings.Messages[0].find("aborted"), std::string::npos);
}

TEST(vtkLabelMesher, DecimateOffIsTheMesherExactly)
{
  auto image = MakeVtkImage(TwoBalls(20), { 0.7, 0.7, 0.7 }, { 1, 2, 3 });
  vtkNew<vtkLabelMesher> composite;
  composite->SetInputData(image);
  composite->DecimateOff();
  composite->SetImageToMeshDistance(1.0);
  composite->Update();
  vtkNew<vtkLabelOctreeMesher> mesher;
  mesher->SetInputData(image);
  mesher->SetImageToMeshDistance(1.0);
  mesher->Update();
  ASSERT_GT(composite->GetOutput()->GetNumberOfCells(), 0);
  EXPECT_TRUE(SameGrid(composite->GetOutput(), mesher->GetOutput()));
  EXPECT_EQ(composite->GetInterfacesOutput()->GetNumberOfCells(), mesher->GetInterfacesOutput()->GetNumberOfCells());
  EXPECT_EQ(composite->GetCurvedOutput()->GetNumberOfCells(), 0);
  // The mesher's field data, with no decimation's.
  EXPECT_TRUE(std::isnan(FieldScalar(composite->GetOutput(), arrays::Merges)));
  EXPECT_EQ(FieldScalar(composite->GetOutput(), arrays::MinimumAngle), FieldScalar(mesher->GetOutput(), arrays::MinimumAngle));
  EXPECT_GE(FieldScalar(composite->GetOutput(), arrays::MinimumAngle), vtkLabelMesher::GetProvenAngleBound(3) - 1e-9);
}

/// Runs `composite` (configured by the caller) on `image` and vtkLabelMesher then vtkBezierCurver
/// (configured by `configureCurver`) on the same image, and expects port 2 to be the curver's
/// output and port 0 the linear mesh. Returns the composite's curved output.
template <typename ConfigureCurver>
vtkUnstructuredGrid* ExpectCompositeIsMesherThenCurver(
  vtkImageData* image, vtkLabelMesher* composite, ConfigureCurver configureCurver)
{
  composite->SetInputData(image);
  MessageRecorder errors(composite, vtkCommand::ErrorEvent);
  composite->Update();
  EXPECT_TRUE(errors.Messages.empty()) << errors.Messages.front();
  vtkNew<vtkLabelMesher> linear;
  linear->SetInputData(image);
  vtkNew<vtkBezierCurver> curver;
  curver->SetInputConnection(0, linear->GetOutputPort(0));
  curver->SetInputDataObject(1, image);
  configureCurver(curver.GetPointer());
  curver->Update();
  vtkUnstructuredGrid* curved = composite->GetCurvedOutput();
  EXPECT_GT(curved->GetNumberOfCells(), 0);
  EXPECT_TRUE(SameGrid(curved, curver->GetOutput()));
  EXPECT_TRUE(SameGrid(composite->GetOutput(), linear->GetOutput())) << "port 0 stays the linear mesh";
  EXPECT_EQ(FieldScalar(curved, arrays::InvalidCells), 0.0);
  return curved;
}

TEST(vtkLabelMesher, CurveIsTheCurverOnTheLinearMesh)
{
  auto image = MakeVtkImage2D(MakeDiscSliceXZ(40, 14.0), 40, 40);
  vtkNew<vtkLabelMesher> composite;
  composite->CurveOn();
  composite->SetSmoothness(2);
  vtkUnstructuredGrid* curved =
    ExpectCompositeIsMesherThenCurver(image, composite, [](vtkBezierCurver* curver) { curver->SetSmoothness(2); });
  ASSERT_GT(curved->GetNumberOfCells(), 0);
  EXPECT_EQ(curved->GetCellType(0), VTK_BEZIER_TRIANGLE);
  EXPECT_EQ(FieldScalar(curved, arrays::Smoothness), 2.0);
}

TEST(vtkLabelMesher, CurveOnAThreeDimensionalImageIsOneError)
{
  vtkNew<vtkLabelMesher> mesher;
  mesher->SetInputData(MakeVtkImage(MakeBallLabels(12, 4.0)));
  mesher->CurveOn();
  MessageRecorder errors(mesher, vtkCommand::ErrorEvent);
  mesher->Update();
  ASSERT_EQ(errors.Messages.size(), 1u);
  EXPECT_NE(errors.Messages[0].find("2D image"), std::string::npos) << errors.Messages[0];
  EXPECT_EQ(mesher->GetOutput()->GetNumberOfCells(), 0);
  EXPECT_EQ(mesher->GetCurvedOutput()->GetNumberOfCells(), 0);
}

TEST(vtkLabelMesher, ProgressRunsOnceFromZeroToOneOverEveryStage)
{
  for (const bool decimate : { true, false })
  {
    auto image = MakeVtkImage2D(MakeDiscSliceXZ(40, 14.0), 40, 40);
    vtkNew<vtkLabelMesher> mesher;
    mesher->SetInputData(image);
    mesher->SetDecimate(decimate);
    mesher->CurveOn();
    struct Seen
    {
      std::vector<double> Fractions;
      std::vector<std::string> Stages;
    } seen;
    vtkNew<vtkCallbackCommand> record;
    record->SetClientData(&seen);
    record->SetCallback([](vtkObject* caller, unsigned long, void* client, void* data) {
      auto* s = static_cast<Seen*>(client);
      s->Fractions.push_back(*static_cast<double*>(data));
      const char* text = static_cast<vtkAlgorithm*>(caller)->GetProgressText();
      s->Stages.emplace_back(text ? text : "");
    });
    mesher->AddObserver(vtkCommand::ProgressEvent, record);
    mesher->Update();
    ASSERT_FALSE(seen.Fractions.empty());
    for (std::size_t i = 1; i < seen.Fractions.size(); ++i)
    {
      ASSERT_GE(seen.Fractions[i], seen.Fractions[i - 1]) << "step " << i << " (" << seen.Stages[i] << ")";
    }
    EXPECT_EQ(seen.Fractions.back(), 1.0);
    // The curver's stages come last, within the curving's share, after the mesher's.
    std::size_t firstCurve = 0;
    while (firstCurve < seen.Stages.size() && seen.Stages[firstCurve].rfind("Smoothing boundaries", 0) != 0)
    {
      ++firstCurve;
    }
    ASSERT_LT(firstCurve, seen.Stages.size()) << "the curver reported through the composite";
    EXPECT_GE(seen.Fractions[firstCurve], 0.5) << "decimate " << decimate; // meshing weighs as much or more
    EXPECT_LT(seen.Fractions[firstCurve], 1.0) << "decimate " << decimate;
  }
}

TEST(vtkLabelMesher, AbortInEveryStageEmptiesEveryOutput)
{
  struct Case
  {
    bool Decimate;
    const char* Stage;
  };
  // The mesher alone (its octree stage), and the curver (after a complete linear mesh).
  for (const Case& c : { Case{ false, "fill" }, Case{ true, "Smoothing boundaries" } })
  {
    vtkNew<vtkLabelMesher> mesher;
    mesher->SetInputData(MakeVtkImage2D(MakeDiscSliceXZ(40, 14.0), 40, 40));
    mesher->SetDecimate(c.Decimate);
    mesher->CurveOn();
    AbortAtStage abort(mesher, c.Stage);
    MessageRecorder warnings(mesher, vtkCommand::WarningEvent);
    MessageRecorder errors(mesher, vtkCommand::ErrorEvent);
    mesher->Update();
    EXPECT_TRUE(abort.Reached) << c.Stage;
    EXPECT_TRUE(errors.Messages.empty()) << c.Stage << ": " << errors.Messages.front();
    EXPECT_EQ(mesher->GetOutput()->GetNumberOfCells(), 0) << c.Stage;
    EXPECT_EQ(mesher->GetInterfacesOutput()->GetNumberOfCells(), 0) << c.Stage;
    EXPECT_EQ(mesher->GetCurvedOutput()->GetNumberOfCells(), 0) << c.Stage;
    ASSERT_FALSE(warnings.Messages.empty()) << c.Stage;
    EXPECT_NE(warnings.Messages[0].find("aborted"), std::string::npos) << warnings.Messages[0];
  }
}

TEST(vtkLabelMesher, MinimumAngleIsClampedToTheProvenBounds)
{
  vtkNew<vtkLabelMesher> mesher;
  const double largest = std::max(vtkLabelMesher::GetProvenAngleBound(2), vtkLabelMesher::GetProvenAngleBound(3));
  mesher->SetMinimumAngle(largest + 10.0);
  EXPECT_EQ(mesher->GetMinimumAngle(), largest);
  mesher->SetMinimumAngle(-1.0);
  EXPECT_EQ(mesher->GetMinimumAngle(), 0.0);
  EXPECT_STREQ(vtkLabelMesher::GetMaterialArrayName(), arrays::Material);
  EXPECT_STREQ(vtkLabelMesher::GetMaterialNameArrayName(), arrays::MaterialName);
}

TEST(vtkLabelMesher, CurveOffAgainEmptiesTheCurvedPort)
{
  vtkNew<vtkLabelMesher> mesher;
  mesher->SetInputData(MakeVtkImage2D(MakeDiscSliceXZ(40, 14.0), 40, 40));
  mesher->CurveOn();
  mesher->Update();
  ASSERT_GT(mesher->GetCurvedOutput()->GetNumberOfCells(), 0);
  mesher->CurveOff();
  mesher->Update();
  EXPECT_GT(mesher->GetOutput()->GetNumberOfCells(), 0);
  EXPECT_EQ(mesher->GetCurvedOutput()->GetNumberOfCells(), 0) << "no curves left from the run before";
}

TEST(vtkLabelMesher, AnErrorBeforeCurvingEmptiesEveryPort)
{
  vtkNew<vtkLabelMesher> mesher;
  mesher->SetInputData(MakeVtkImage2D(MakeDiscSliceXZ(40, 14.0), 40, 40));
  mesher->CurveOn();
  mesher->SetMemoryLimit(1.0);
  MessageRecorder errors(mesher, vtkCommand::ErrorEvent);
  mesher->Update();
  ASSERT_EQ(errors.Messages.size(), 1u);
  EXPECT_NE(errors.Messages[0].find("memory limit"), std::string::npos) << errors.Messages[0];
  EXPECT_EQ(mesher->GetOutput()->GetNumberOfCells(), 0);
  EXPECT_EQ(mesher->GetInterfacesOutput()->GetNumberOfCells(), 0);
  EXPECT_EQ(mesher->GetCurvedOutput()->GetNumberOfCells(), 0);
}

TEST(vtkLabelMesher, TheCurverFitsTheLabelsTheMeshWasMadeFrom)
{
  // The labels are a second point array; the active scalars are something else (all one label):
  // the curver must read the array the filter was told to, as the mesher does.
  auto image = MakeVtkImage2D(MakeDiscSliceXZ(40, 14.0), 40, 40);
  vtkNew<vtkIntArray> labels;
  labels->DeepCopy(image->GetPointData()->GetScalars());
  labels->SetName("Labels");
  vtkNew<vtkIntArray> other;
  other->SetName("Other");
  other->SetNumberOfValues(labels->GetNumberOfTuples());
  other->Fill(3);
  image->GetPointData()->SetScalars(other); // replaces the labels as the scalars
  image->GetPointData()->AddArray(labels);
  vtkNew<vtkLabelMesher> composite;
  composite->SetInputData(image);
  composite->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Labels");
  composite->CurveOn();
  MessageRecorder errors(composite, vtkCommand::ErrorEvent);
  composite->Update();
  EXPECT_TRUE(errors.Messages.empty()) << errors.Messages.front();

  vtkNew<vtkLabelMesher> linear;
  linear->SetInputData(image);
  linear->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Labels");
  vtkNew<vtkBezierCurver> curver;
  curver->SetInputConnection(0, linear->GetOutputPort(0));
  curver->SetInputDataObject(1, image);
  curver->SetInputArrayToProcess(0, 1, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Labels");
  curver->Update();
  ASSERT_GT(composite->GetCurvedOutput()->GetNumberOfCells(), 0);
  EXPECT_TRUE(SameGrid(composite->GetCurvedOutput(), curver->GetOutput()));
  EXPECT_EQ(FieldScalar(composite->GetCurvedOutput(), arrays::MisclassifiedPixelsCurved),
    FieldScalar(curver->GetOutput(), arrays::MisclassifiedPixelsCurved));
}

TEST(vtkLabelMesher, OrderTwoAddsCertifiedQuadraticTetrahedraOnPortTwo)
{
  vtkNew<vtkLabelMesher> mesher;
  mesher->SetInputData(MakeVtkImage(TwoBalls(20)));
  mesher->SetOrder(2);
  std::vector<double> fractions;
  vtkNew<vtkCallbackCommand> record;
  record->SetClientData(&fractions);
  record->SetCallback([](vtkObject*, unsigned long, void* client, void* data) {
    static_cast<std::vector<double>*>(client)->push_back(*static_cast<double*>(data));
  });
  mesher->AddObserver(vtkCommand::ProgressEvent, record);
  mesher->Update();
  ASSERT_FALSE(fractions.empty());
  EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end())) << "progress went back";
  EXPECT_EQ(fractions.back(), 1.0);
  vtkUnstructuredGrid* linear = mesher->GetOutput();
  vtkUnstructuredGrid* quadratic = mesher->GetCurvedOutput();
  ASSERT_GT(linear->GetNumberOfCells(), 0);
  ASSERT_EQ(quadratic->GetNumberOfCells(), linear->GetNumberOfCells()); // the same cells, made quadratic
  for (vtkIdType c = 0; c < quadratic->GetNumberOfCells(); ++c)
    ASSERT_EQ(quadratic->GetCellType(c), VTK_QUADRATIC_TETRA);
  vtkFieldData* fd = quadratic->GetFieldData();
  const double bound = fd->GetArray(arrays::MinimumScaledJacobianBound)->GetTuple1(0);
  EXPECT_EQ(bound, 0.1);
  EXPECT_GE(fd->GetArray(arrays::CertifiedMinimumScaledJacobian)->GetTuple1(0), bound);
  EXPECT_GE(fd->GetArray(arrays::SampledMinimumScaledJacobian)->GetTuple1(0), bound);
  EXPECT_GT(fd->GetArray(arrays::CurvedEdges)->GetTuple1(0), 0.0);
  EXPECT_LT(fd->GetArray(arrays::MisclassifiedVoxelsQuadratic)->GetTuple1(0),
    fd->GetArray(arrays::MisclassifiedVoxelsLinear)->GetTuple1(0));
  vtkDataArray* scaled = quadratic->GetCellData()->GetArray(arrays::ScaledJacobian);
  ASSERT_NE(scaled, nullptr);
  for (vtkIdType c = 0; c < scaled->GetNumberOfTuples(); ++c)
    ASSERT_GE(scaled->GetTuple1(c), bound) << "cell " << c;
  // The corners keep the decimator's angle (MinimumAngle, 15 degrees by default).
  EXPECT_EQ(fd->GetArray(arrays::CornerAngleBound)->GetTuple1(0), mesher->GetMinimumAngle());
  EXPECT_GE(fd->GetArray(arrays::MeasuredMinimumCornerAngle)->GetTuple1(0), mesher->GetMinimumAngle() - 1e-6);
  vtkDataArray* corners = quadratic->GetCellData()->GetArray(arrays::CornerAngle);
  ASSERT_NE(corners, nullptr);
  for (vtkIdType c = 0; c < corners->GetNumberOfTuples(); ++c)
    ASSERT_GE(corners->GetTuple1(c), mesher->GetMinimumAngle() - 1e-9) << "cell " << c;
}

TEST(vtkLabelMesher, OrderTwoWithoutDecimationOrWithCurveIsOneError)
{
  for (const bool curve : { true, false })
  {
    vtkNew<vtkLabelMesher> mesher;
    mesher->SetInputData(curve ? MakeVtkImage2D(MakeDiscSliceXZ(40, 14.0), 40, 40)
                               : MakeVtkImage(MakeBallLabels(12, 4.0)));
    mesher->SetDecimate(curve);
    mesher->SetCurve(curve);
    mesher->SetOrder(2);
    MessageRecorder errors(mesher, vtkCommand::ErrorEvent);
    mesher->Update();
    ASSERT_EQ(errors.Messages.size(), 1u);
    EXPECT_NE(errors.Messages[0].find("Order 2"), std::string::npos) << errors.Messages[0];
    EXPECT_EQ(mesher->GetOutput()->GetNumberOfCells(), 0);
    EXPECT_EQ(mesher->GetCurvedOutput()->GetNumberOfCells(), 0);
  }
}

/// A 2D image's Order 2 is the curver's Order 2 on the linear mesh: quadratic triangles on the
/// linear mesh's vertices and one mid-node per edge.
TEST(vtkLabelMesher, OrderTwoOnATwoDimensionalImageGivesQuadraticTriangles)
{
  auto image = MakeVtkImage2D(MakeDiscSliceXZ(40, 14.0), 40, 40);
  vtkNew<vtkLabelMesher> composite;
  composite->SetOrder(2);
  vtkUnstructuredGrid* curved =
    ExpectCompositeIsMesherThenCurver(image, composite, [](vtkBezierCurver* curver) { curver->SetOrder(2); });
  ASSERT_GT(curved->GetNumberOfCells(), 0);
  EXPECT_EQ(curved->GetCellType(0), VTK_QUADRATIC_TRIANGLE);
  EXPECT_EQ(FieldScalar(curved, arrays::Order), 2.0);
  // Nodes: the linear mesh's vertices, then one per edge (no ear is split: the corner bound is on).
  vtkUnstructuredGrid* mesh = composite->GetOutput();
  std::set<std::pair<vtkIdType, vtkIdType>> edges;
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    const vtkIdType* ids = nullptr;
    vtkIdType n = 0;
    mesh->GetCellPoints(c, n, ids);
    for (vtkIdType k = 0; k < n; ++k)
      edges.insert({ std::min(ids[k], ids[(k + 1) % n]), std::max(ids[k], ids[(k + 1) % n]) });
  }
  EXPECT_EQ(curved->GetNumberOfPoints(), mesh->GetNumberOfPoints() + static_cast<vtkIdType>(edges.size()));
  EXPECT_GT(FieldScalar(curved, arrays::MisclassifiedPixelsLinear), FieldScalar(curved, arrays::MisclassifiedPixelsCurved));
}

TEST(vtkLabelMesher, AbortWhileMakingQuadraticCellsEmptiesEveryOutput)
{
  vtkNew<vtkLabelMesher> mesher;
  mesher->SetInputData(MakeVtkImage(TwoBalls(20)));
  mesher->SetOrder(2);
  AbortAtStage abort(mesher, "quadratic certify");
  MessageRecorder warnings(mesher, vtkCommand::WarningEvent);
  mesher->Update();
  EXPECT_TRUE(abort.Reached);
  EXPECT_EQ(mesher->GetOutput()->GetNumberOfCells(), 0);
  EXPECT_EQ(mesher->GetInterfacesOutput()->GetNumberOfCells(), 0);
  EXPECT_EQ(mesher->GetCurvedOutput()->GetNumberOfCells(), 0);
  ASSERT_FALSE(warnings.Messages.empty());
  EXPECT_NE(warnings.Messages[0].find("aborted"), std::string::npos) << warnings.Messages[0];
}
