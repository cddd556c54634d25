// SPDX-License-Identifier: GPL-2.0-or-later
// vtkLabelMeshReport: the wrapped face of RunReport and CurveReport.
#include "vtkLabelMeshReport.h"

#include "Report/CurveReport.h"
#include "Report/RunReport.h"

#include "vtkImageData.h"
#include "vtkObjectFactory.h"
#include "vtkUnstructuredGrid.h"

#include <functional>
#include <optional>
#include <sstream>
#include <stdexcept>

vtkStandardNewMacro(vtkLabelMeshReport);

struct vtkLabelMeshReport::Figures : labelmesher::report::RunReports
{
};

//------------------------------------------------------------------------------
vtkLabelMeshReport::vtkLabelMeshReport() = default;
vtkLabelMeshReport::~vtkLabelMeshReport() = default;

//------------------------------------------------------------------------------
void vtkLabelMeshReport::SetImage(vtkImageData* image)
{
  this->Image = image;
  this->Modified();
}

void vtkLabelMeshReport::SetMesh(vtkUnstructuredGrid* mesh)
{
  this->Mesh = mesh;
  this->Modified();
}

void vtkLabelMeshReport::SetCurvedMesh(vtkUnstructuredGrid* curved)
{
  this->Curved = curved;
  this->Modified();
}

void vtkLabelMeshReport::AddOutputName(const char* name)
{
  this->OutputNames.emplace_back(name ? name : "");
  this->Modified();
}

void vtkLabelMeshReport::AddNote(const char* note)
{
  this->Notes.emplace_back(note ? note : "");
  this->Modified();
}

void vtkLabelMeshReport::AddTiming(const char* stage, double seconds, bool first)
{
  (first ? this->FirstTimings : this->LastTimings).emplace_back(stage ? stage : "", seconds);
  this->Modified();
}

void vtkLabelMeshReport::SetMemory(double startMiB, double peakMiB)
{
  this->StartMemory = startMiB;
  this->PeakMemory = peakMiB;
  this->Modified();
}

//------------------------------------------------------------------------------
vtkLabelMeshReport::Figures vtkLabelMeshReport::Gather()
{
  if (!this->Image || !this->Mesh)
  {
    throw std::invalid_argument("the report needs the image (SetImage) and the mesh (SetMesh)");
  }
  labelmesher::report::RunContext context;
  context.Input = this->InputName;
  context.Outputs = this->OutputNames;
  context.Notes = this->Notes;
  context.TimingsBefore = this->FirstTimings;
  context.TimingsAfter = this->LastTimings;
  context.StartMemory = this->StartMemory;
  context.PeakMemory = this->PeakMemory;
  return { labelmesher::report::MakeRunReports(context, this->Image, this->Mesh, this->Curved) };
}

//------------------------------------------------------------------------------
std::string vtkLabelMeshReport::Text(const std::function<void(const Figures&, std::ostream&)>& write)
{
  try
  {
    std::ostringstream out;
    write(this->Gather(), out);
    return out.str();
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro(<< "No report: " << e.what() << ".");
    return {};
  }
}

std::string vtkLabelMeshReport::GetMeshJSON()
{
  return this->Text([](const Figures& f, std::ostream& out) { labelmesher::report::WriteJson(f.Linear, out); });
}

std::string vtkLabelMeshReport::GetCurveJSON()
{
  return this->Text([](const Figures& f, std::ostream& out) {
    if (f.Curved)
    {
      labelmesher::report::WriteCurveJson(*f.Curved, out);
    }
  });
}

std::string vtkLabelMeshReport::GetJSON()
{
  // A quadratic mesh is part of the mesh report (its "quadratic" object); only Bezier curves
  // make a curve report.
  return this->Text([](const Figures& f, std::ostream& out) {
    if (f.Curved)
    {
      labelmesher::report::WriteCurveJson(*f.Curved, out);
    }
    else
    {
      labelmesher::report::WriteJson(f.Linear, out);
    }
  });
}

std::string vtkLabelMeshReport::GetSummary()
{
  return this->Text([](const Figures& f, std::ostream& out) {
    if (f.Curved)
    {
      labelmesher::report::PrintCurveSummary(*f.Curved, out);
    }
    else
    {
      labelmesher::report::PrintSummary(f.Linear, out);
    }
  });
}

//------------------------------------------------------------------------------
bool vtkLabelMeshReport::GetGuaranteesHold()
{
  try
  {
    const Figures f = this->Gather();
    if (!labelmesher::report::GuaranteesHold(f.Linear) || !labelmesher::report::QuadraticHolds(f.Linear))
    {
      return false;
    }
    return !f.Curved || (f.Curved->Valid() && f.Curved->CurvesFaithful() && f.Curved->ScaledJacobianHolds() &&
      f.Curved->CornerAnglesHold());
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro(<< "No report: " << e.what() << ".");
    return false;
  }
}

//------------------------------------------------------------------------------
void vtkLabelMeshReport::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "InputName: " << this->InputName << "\n";
  os << indent << "Image: " << this->Image.GetPointer() << "\n";
  os << indent << "Mesh: " << this->Mesh.GetPointer() << "\n";
  os << indent << "CurvedMesh: " << this->Curved.GetPointer() << "\n";
  os << indent << "Outputs: " << this->OutputNames.size() << ", notes: " << this->Notes.size() << "\n";
}
