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

struct vtkLabelMeshReport::Figures
{
  labelmesher::report::RunReport Linear;
  std::optional<labelmesher::report::CurveReport> Curved;
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
  Figures f;
  f.Linear = labelmesher::report::MakeReport(this->InputName, this->Image, this->Mesh);
  f.Linear.Outputs = this->OutputNames;
  f.Linear.Notes = this->Notes;
  f.Linear.StartMemory = this->StartMemory;
  f.Linear.PeakMemory = this->PeakMemory;
  auto& timings = f.Linear.Timings;
  timings.insert(timings.begin(), this->FirstTimings.begin(), this->FirstTimings.end());
  const bool curved = this->Curved && this->Curved->GetNumberOfCells() > 0;
  if (!curved)
  {
    timings.insert(timings.end(), this->LastTimings.begin(), this->LastTimings.end());
    return f;
  }
  // The curve report lists the caller's last stages (writing) after the curver's.
  f.Curved = labelmesher::report::MakeCurveReport(f.Linear, this->Curved);
  f.Curved->Timings.insert(f.Curved->Timings.end(), this->LastTimings.begin(), this->LastTimings.end());
  return f;
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
  const bool curved = this->Curved && this->Curved->GetNumberOfCells() > 0;
  return curved ? this->GetCurveJSON() : this->GetMeshJSON();
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
    if (!labelmesher::report::GuaranteesHold(f.Linear))
    {
      return false;
    }
    return !f.Curved || (f.Curved->Valid() && f.Curved->CurvesFaithful());
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
