// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_testing_FilterTestSupport_h
#define labelmesher_testing_FilterTestSupport_h

/**
 * @file FilterTestSupport.h
 * What the tests of the VTK filters (Testvtk*.cxx) share: small vtkImageData
 * label images, a recorder of error/warning events (so that a test can assert
 * "exactly one error naming the problem" instead of letting VTK print it), an
 * observer that aborts a filter when it reaches a given stage, and an
 * orientation count on an output grid. Header only: the core's test support
 * library does not link VTK.
 */

#include "MaterialTable.h"

#include "vtkAlgorithm.h"
#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDataObject.h"
#include "vtkDataSet.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkImageData.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace labelmesher
{
namespace testing
{

/// An n^3 (x fastest) label volume with a ball of label 1 and `radius` voxels
/// around the centre.
inline std::vector<int> MakeBallLabels(int n, double radius)
{
  std::vector<int> labels(static_cast<std::size_t>(n) * n * n, 0);
  const double c = (n - 1) / 2.0;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        if ((i - c) * (i - c) + (j - c) * (j - c) + (k - c) * (k - c) <= radius * radius)
          labels[(static_cast<std::size_t>(k) * n + j) * n + i] = 1;
  return labels;
}

/// An n x 1 x n slice (x fastest, then z) with a disc of label 1.
inline std::vector<int> MakeDiscSliceXZ(int n, double radius)
{
  std::vector<int> labels(static_cast<std::size_t>(n) * n, 0);
  const double c = (n - 1) / 2.0;
  for (int k = 0; k < n; ++k)
    for (int i = 0; i < n; ++i)
      if ((i - c) * (i - c) + (k - c) * (k - c) <= radius * radius)
        labels[static_cast<std::size_t>(k) * n + i] = 1;
  return labels;
}

/// int point scalars "Labels" of `image`, from `labels` (x fastest).
inline void SetLabels(vtkImageData* image, const std::vector<int>& labels)
{
  vtkNew<vtkIntArray> scalars;
  scalars->SetName("Labels");
  scalars->SetNumberOfValues(static_cast<vtkIdType>(labels.size()));
  for (std::size_t v = 0; v < labels.size(); ++v)
    scalars->SetValue(static_cast<vtkIdType>(v), labels[v]);
  image->GetPointData()->SetScalars(scalars);
}

/// A cube image of side cbrt(labels.size()) (or an n x 1 x n slice when the
/// size is a square, not a cube) with int point scalars "Labels".
inline vtkSmartPointer<vtkImageData> MakeVtkImage(const std::vector<int>& labels,
  std::array<double, 3> spacing = { 1, 1, 1 }, std::array<double, 3> origin = { 0, 0, 0 })
{
  const int cube = static_cast<int>(std::lround(std::cbrt(static_cast<double>(labels.size()))));
  const int square = static_cast<int>(std::lround(std::sqrt(static_cast<double>(labels.size()))));
  auto image = vtkSmartPointer<vtkImageData>::New();
  if (static_cast<std::size_t>(cube) * cube * cube == labels.size())
    image->SetDimensions(cube, cube, cube);
  else
    image->SetDimensions(square, 1, square);
  image->SetSpacing(spacing.data());
  image->SetOrigin(origin.data());
  SetLabels(image, labels);
  return image;
}

/// Names label `label` of `image` with `name` and colour `rgb` in the image's material table
/// (field data, as vtkLabelImageReader gives it), which the filters pass to their outputs.
inline void NameMaterial(vtkImageData* image, int label, const std::string& name, std::array<double, 3> rgb)
{
  labelmesher::MaterialTable table = labelmesher::ReadMaterialTable(image->GetFieldData());
  labelmesher::MaterialInfo info;
  info.Label = label;
  info.Name = name;
  info.Color = rgb;
  table.Set(info);
  labelmesher::StoreMaterialTable(image->GetFieldData(), table);
}

/// The same with an explicit single-slice size (x by y), for 2D cases in the x-y plane.
inline vtkSmartPointer<vtkImageData> MakeVtkImage2D(const std::vector<int>& labels, int nx, int ny)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(nx, ny, 1);
  SetLabels(image, labels);
  return image;
}

/// Records the messages of one event (ErrorEvent, WarningEvent) of an object.
class MessageRecorder
{
public:
  MessageRecorder(vtkObject* object, unsigned long event)
  {
    this->Command->SetClientData(this);
    this->Command->SetCallback([](vtkObject*, unsigned long, void* self, void* message) {
      static_cast<MessageRecorder*>(self)->Messages.emplace_back(message ? static_cast<const char*>(message) : "");
    });
    object->AddObserver(event, this->Command);
  }
  std::vector<std::string> Messages;

private:
  vtkNew<vtkCallbackCommand> Command;
};

/// Sets AbortExecute on `algorithm` the first time it reports progress with a
/// ProgressText that starts with `stage`.
class AbortAtStage
{
public:
  AbortAtStage(vtkAlgorithm* algorithm, std::string stage)
    : Stage(std::move(stage))
  {
    this->Command->SetClientData(this);
    this->Command->SetCallback([](vtkObject* caller, unsigned long, void* self, void*) {
      auto* me = static_cast<AbortAtStage*>(self);
      auto* running = static_cast<vtkAlgorithm*>(caller);
      const char* text = running->GetProgressText();
      if (text && std::string(text).rfind(me->Stage, 0) == 0)
      {
        me->Reached = true;
        running->SetAbortExecute(1);
      }
    });
    algorithm->AddObserver(vtkCommand::ProgressEvent, this->Command);
  }
  std::string Stage;
  bool Reached = false;

private:
  vtkNew<vtkCallbackCommand> Command;
};

/// The first value of field-data array `name`, or NaN when it is missing (so
/// that every comparison with it fails).
inline double FieldScalar(vtkDataObject* data, const char* name)
{
  vtkDataArray* array = data->GetFieldData()->GetArray(name);
  return array ? array->GetComponent(0, 0) : std::numeric_limits<double>::quiet_NaN();
}

/// Tetrahedra of `grid` with signed volume <= 0 (VTK's orientation).
inline int CountNonPositiveTetrahedra(vtkUnstructuredGrid* grid)
{
  int count = 0;
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
  {
    if (grid->GetCellType(c) != VTK_TETRA)
      continue;
    vtkIdType n;
    const vtkIdType* ids;
    grid->GetCellPoints(c, n, ids);
    double p[4][3];
    for (int v = 0; v < 4; ++v)
      grid->GetPoint(ids[v], p[v]);
    double u[3], w[3], x[3];
    for (int a = 0; a < 3; ++a)
    {
      u[a] = p[1][a] - p[0][a];
      w[a] = p[2][a] - p[0][a];
      x[a] = p[3][a] - p[0][a];
    }
    const double det = u[0] * (w[1] * x[2] - w[2] * x[1]) - u[1] * (w[0] * x[2] - w[2] * x[0]) +
      u[2] * (w[0] * x[1] - w[1] * x[0]);
    count += det <= 0.0;
  }
  return count;
}

/// Points of `data` that no cell uses (an output should have none).
inline vtkIdType CountUnusedPoints(vtkDataSet* data)
{
  std::vector<char> used(static_cast<std::size_t>(data->GetNumberOfPoints()), 0);
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < data->GetNumberOfCells(); ++c)
  {
    data->GetCellPoints(c, ids);
    for (vtkIdType i = 0; i < ids->GetNumberOfIds(); ++i)
      used[static_cast<std::size_t>(ids->GetId(i))] = 1;
  }
  return static_cast<vtkIdType>(std::count(used.begin(), used.end(), 0));
}

} // namespace testing
} // namespace labelmesher

#endif
