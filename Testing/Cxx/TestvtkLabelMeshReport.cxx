// SPDX-License-Identifier: GPL-2.0-or-later
// vtkLabelMeshReport: the one report of a vtkLabelMesher run (the CLI's JSON and summary, the
// viewer's, the Slicer module's) states what the outputs' field data record: the parameters, the
// material table, the decimation, the measured guarantees and, with a curved mesh, its validity and
// curves, or a quadratic mesh's part. Its verdict GetGuaranteesHold turns false when any one measured guarantee is broken (each
// spoiled in turn), and without measurements. (The CLI's JSON is compared with Python's in
// Testing/Python/test_labelmesher_io.py; the Slicer module reads it in Testing/Slicer.)
#include "vtkLabelMeshReport.h"

#include "FilterTestSupport.h"
#include "LabelMesherArrayNames.h"
#include "vtkLabelMesher.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkUnstructuredGrid.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <functional>
#include <string>
#include <vector>

namespace
{
namespace arrays = labelmesher::arrays;
using labelmesher::testing::MessageRecorder;

bool Contains(const std::string& text, const std::string& part)
{
  return text.find(part) != std::string::npos;
}

/// A ball of label 1 named "liver" (a material table on the image, as vtkLabelImageReader gives).
vtkSmartPointer<vtkImageData> NamedBall()
{
  auto image = labelmesher::testing::MakeVtkImage(labelmesher::testing::MakeBallLabels(14, 4.5), { 0.5, 0.5, 0.5 });
  labelmesher::testing::NameMaterial(image, 1, "liver", { 0.8, 0.3, 0.2 });
  return image;
}

/// The first tuple of field array `name` of `mesh` set to `value`.
void Spoil(vtkUnstructuredGrid* mesh, const char* name, double value)
{
  vtkDataArray* array = mesh->GetFieldData()->GetArray(name);
  ASSERT_NE(array, nullptr) << name;
  array->SetComponent(0, 0, value);
}
} // namespace

TEST(vtkLabelMeshReport, StatesWhatTheMeshRecords)
{
  vtkSmartPointer<vtkImageData> image = NamedBall();
  vtkNew<vtkLabelMesher> mesher;
  mesher->SetInputData(image);
  mesher->SetMinimumAngle(17.0);
  mesher->SetImageToMeshDistance(1.5);
  mesher->Update();
  vtkNew<vtkLabelMeshReport> report;
  report->SetImage(image);
  report->SetMesh(mesher->GetOutput());
  report->SetInputName("ball.nrrd");
  report->AddOutputName("ball.msh");
  report->AddTiming("read", 0.25, true);
  report->SetMemory(10.0, 30.0);

  const std::string json = report->GetMeshJSON();
  const std::string cells = std::to_string(mesher->GetOutput()->GetNumberOfCells());
  for (const std::string& part : { std::string("\"input\": \"ball.nrrd\""), std::string("\"outputs\": [\n    \"ball.msh\""),
         std::string("\"name\": \"liver\""), std::string("\"dimensions\": [\n      14,"),
         std::string("\"image_to_mesh\": 1.5"), std::string("\"mesh_to_image\": 2"),
         std::string("\"minimum_angle_bound_degrees\": 17"), std::string("\"angle_bound_degrees\": 17"),
         std::string("\"cells\": " + cells), std::string("\"bounds_certified\": true"),
         std::string("\"all_match\": true"), std::string("\"stage\": \"read\""), std::string("\"peak_mib\": 30") })
  {
    EXPECT_TRUE(Contains(json, part)) << part << "\n" << json;
  }
  EXPECT_EQ(report->GetJSON(), json) << "without a curved mesh, the mesh report";
  EXPECT_EQ(report->GetCurveJSON(), "");
  const std::string summary = report->GetSummary();
  EXPECT_TRUE(Contains(summary, "Input   ball.nrrd")) << summary;
  EXPECT_TRUE(Contains(summary, "liver")) << summary;
  EXPECT_TRUE(Contains(summary, "Both bounds certified")) << summary;
  EXPECT_TRUE(report->GetGuaranteesHold());
}

TEST(vtkLabelMeshReport, AnyBrokenGuaranteeFailsTheVerdict)
{
  vtkSmartPointer<vtkImageData> image = NamedBall();
  vtkNew<vtkLabelMesher> mesher;
  mesher->SetInputData(image);
  mesher->Update();
  struct Case
  {
    const char* Name;
    std::function<void(vtkUnstructuredGrid*)> Break;
  };
  const std::vector<Case> cases = {
    { "angle below the bound", [](vtkUnstructuredGrid* m) { Spoil(m, arrays::MinimumAngle, 14.9); } },
    { "an inverted cell", [](vtkUnstructuredGrid* m) { Spoil(m, arrays::InvertedCells, 1.0); } },
    { "bounds not certified", [](vtkUnstructuredGrid* m) { Spoil(m, arrays::HausdorffBoundsCertified, 0.0); } },
    { "a topology mismatch", [](vtkUnstructuredGrid* m) { Spoil(m, arrays::TopologyMatches, 0.0); } },
    { "not measured", [](vtkUnstructuredGrid* m) { m->GetFieldData()->RemoveArray(arrays::MinimumAngle); } },
  };
  for (const Case& c : cases)
  {
    vtkNew<vtkUnstructuredGrid> mesh;
    mesh->DeepCopy(mesher->GetOutput());
    vtkNew<vtkLabelMeshReport> report;
    report->SetImage(image);
    report->SetMesh(mesh);
    ASSERT_TRUE(report->GetGuaranteesHold()) << c.Name << ": the unspoiled mesh";
    c.Break(mesh);
    EXPECT_FALSE(report->GetGuaranteesHold()) << c.Name;
  }
}

TEST(vtkLabelMeshReport, ACurvedMeshGivesTheCurveReport)
{
  auto image = labelmesher::testing::MakeVtkImage2D(labelmesher::testing::MakeDiscSliceXZ(40, 14.0), 40, 40);
  vtkNew<vtkLabelMesher> mesher;
  mesher->SetInputData(image);
  mesher->CurveOn();
  mesher->Update();
  vtkNew<vtkUnstructuredGrid> curved;
  curved->DeepCopy(mesher->GetCurvedOutput());
  vtkNew<vtkLabelMeshReport> report;
  report->SetImage(image);
  report->SetMesh(mesher->GetOutput());
  report->SetCurvedMesh(curved);
  const std::string json = report->GetJSON();
  EXPECT_EQ(json, report->GetCurveJSON());
  for (const char* part : { "\"command\": \"curve\"", "\"smoothness\": 1", "\"linear_mesh\"", "\"within_bounds\": true",
         "\"valid\": true", "\"cell_type\": \"bezier_triangle_degree_3\"" })
  {
    EXPECT_TRUE(Contains(json, part)) << part << "\n" << json;
  }
  EXPECT_TRUE(Contains(report->GetMeshJSON(), "\"cell_type\": \"triangle\""));
  EXPECT_TRUE(Contains(report->GetSummary(), "every cell proven valid"));
  EXPECT_TRUE(report->GetGuaranteesHold());
  Spoil(curved, arrays::InvalidCells, 1.0);
  EXPECT_FALSE(report->GetGuaranteesHold()) << "a curved cell not proven valid";
  Spoil(curved, arrays::InvalidCells, 0.0);
  Spoil(curved, arrays::InterfaceCrossings, 2.0);
  EXPECT_FALSE(report->GetGuaranteesHold()) << "crossing curves";
  Spoil(curved, arrays::InterfaceCrossings, 0.0);
  ASSERT_TRUE(report->GetGuaranteesHold());
  vtkDataArray* scaled = curved->GetCellData()->GetArray(arrays::ScaledJacobian);
  ASSERT_NE(scaled, nullptr);
  const double kept = scaled->GetComponent(0, 0);
  scaled->SetComponent(0, 0, 0.05);
  EXPECT_FALSE(report->GetGuaranteesHold()) << "a cell below the scaled Jacobian bound (0.1)";
  EXPECT_TRUE(Contains(report->GetSummary(), "Scaled Jacobian: every cell NOT at least 0.100"));
  scaled->SetComponent(0, 0, kept);
  ASSERT_TRUE(report->GetGuaranteesHold());
  curved->GetFieldData()->RemoveArray(arrays::InvalidCells);
  EXPECT_FALSE(report->GetGuaranteesHold()) << "validity not recorded is not validity";
}

TEST(vtkLabelMeshReport, AQuadraticMeshIsPartOfTheMeshReport)
{
  vtkSmartPointer<vtkImageData> image = NamedBall();
  vtkNew<vtkLabelMesher> mesher;
  mesher->SetInputData(image);
  mesher->SetOrder(2);
  mesher->Update();
  vtkNew<vtkUnstructuredGrid> quadratic;
  quadratic->DeepCopy(mesher->GetOutput(2));
  ASSERT_GT(quadratic->GetNumberOfCells(), 0);
  vtkNew<vtkLabelMeshReport> report;
  report->SetImage(image);
  report->SetMesh(mesher->GetOutput());
  report->SetCurvedMesh(quadratic);
  const std::string json = report->GetJSON();
  EXPECT_EQ(json, report->GetMeshJSON()) << "a quadratic mesh has no curve report";
  EXPECT_EQ(report->GetCurveJSON(), "");
  for (const std::string& part : { std::string("\"quadratic\": {"),
         std::string("\"cells\": " + std::to_string(quadratic->GetNumberOfCells())),
         std::string("\"scaled_jacobian_bound\": 0.1"), std::string("\"guarantees_hold\": true") })
  {
    EXPECT_TRUE(Contains(json, part)) << part << "\n" << json;
  }
  EXPECT_TRUE(Contains(report->GetSummary(), "quadratic")) << report->GetSummary();
  EXPECT_TRUE(report->GetGuaranteesHold());
  // Each measured quadratic guarantee, broken in turn, fails the verdict.
  const double sampled = quadratic->GetFieldData()->GetArray(arrays::SampledMinimumScaledJacobian)->GetComponent(0, 0);
  const double certified = quadratic->GetFieldData()->GetArray(arrays::CertifiedMinimumScaledJacobian)->GetComponent(0, 0);
  const double distance = quadratic->GetFieldData()->GetArray(arrays::MeasuredImageToMeshDistance)->GetComponent(0, 0);
  const double back = quadratic->GetFieldData()->GetArray(arrays::MeasuredMeshToImageDistance)->GetComponent(0, 0);
  const double corner = quadratic->GetFieldData()->GetArray(arrays::CertifiedMinimumCornerAngle)->GetComponent(0, 0);
  const double measuredCorner = quadratic->GetFieldData()->GetArray(arrays::MeasuredMinimumCornerAngle)->GetComponent(0, 0);
  EXPECT_EQ(quadratic->GetFieldData()->GetArray(arrays::CornerAngleBound)->GetComponent(0, 0), 15.0);
  EXPECT_TRUE(Contains(json, "\"corner_angle_bound_degrees\": 15")) << json;
  for (const auto& c : { std::make_pair(arrays::CertifiedMinimumScaledJacobian, 0.05),
         std::make_pair(arrays::SampledMinimumScaledJacobian, 0.05), std::make_pair(arrays::MeasuredImageToMeshDistance, 2.5),
         std::make_pair(arrays::MeasuredMeshToImageDistance, 2.5), std::make_pair(arrays::CertifiedMinimumCornerAngle, 14.9),
         std::make_pair(arrays::MeasuredMinimumCornerAngle, 14.9), std::make_pair(arrays::CornerAngleBound, 10.0) })
  {
    Spoil(quadratic, c.first, c.second);
    EXPECT_FALSE(report->GetGuaranteesHold()) << c.first;
    Spoil(quadratic, arrays::CertifiedMinimumScaledJacobian, certified);
    Spoil(quadratic, arrays::SampledMinimumScaledJacobian, sampled);
    Spoil(quadratic, arrays::MeasuredImageToMeshDistance, distance);
    Spoil(quadratic, arrays::MeasuredMeshToImageDistance, back);
    Spoil(quadratic, arrays::CertifiedMinimumCornerAngle, corner);
    Spoil(quadratic, arrays::MeasuredMinimumCornerAngle, measuredCorner);
    Spoil(quadratic, arrays::CornerAngleBound, 15.0);
    ASSERT_TRUE(report->GetGuaranteesHold()) << c.first << " restored";
  }
}

TEST(vtkLabelMeshReport, WithoutAMeshItSaysSoOnce)
{
  vtkNew<vtkLabelMeshReport> report;
  MessageRecorder errors(report, vtkCommand::ErrorEvent);
  EXPECT_EQ(report->GetMeshJSON(), "");
  EXPECT_FALSE(report->GetGuaranteesHold());
  ASSERT_EQ(errors.Messages.size(), 2u);
  EXPECT_TRUE(Contains(errors.Messages[0], "needs the image")) << errors.Messages[0];
}

TEST(vtkLabelMeshReport, WithoutDecimationTheBoundIsTheProvenOne)
{
  vtkSmartPointer<vtkImageData> image = NamedBall();
  vtkNew<vtkLabelMesher> mesher;
  mesher->SetInputData(image);
  mesher->DecimateOff();
  mesher->Update();
  vtkNew<vtkLabelMeshReport> report;
  report->SetImage(image);
  report->SetMesh(mesher->GetOutput());
  const std::string json = report->GetMeshJSON();
  EXPECT_TRUE(Contains(json, "\"decimation\": null")) << json;
  char bound[64];
  std::snprintf(bound, sizeof(bound), "\"angle_bound_degrees\": %g", vtkLabelMesher::GetProvenAngleBound(3));
  EXPECT_TRUE(Contains(json, bound)) << bound << "\n" << json;
  EXPECT_TRUE(report->GetGuaranteesHold());
}
