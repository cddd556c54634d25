// SPDX-License-Identifier: GPL-2.0-or-later
// MeshFileWriter (MeshFiles.h), the CLI's writers, as a vtkWriter.
#include "vtkLabelMeshWriter.h"

#include "MaterialTable.h"
#include "MeshFiles.h"
#include "SafeFile.h"

#include "LabelMesherArrayNames.h"

#include "vtkAlgorithmOutput.h"
#include "vtkCellData.h"
#include "vtkErrorCode.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkUnstructuredGrid.h"

#include <cerrno>
#include <exception>
#include <new>

vtkStandardNewMacro(vtkLabelMeshWriter);

vtkLabelMeshWriter::vtkLabelMeshWriter()
{
  this->SetNumberOfInputPorts(2);
}

vtkLabelMeshWriter::~vtkLabelMeshWriter()
{
  this->SetFileName(nullptr);
}

int vtkLabelMeshWriter::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 0)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkUnstructuredGrid");
    return 1;
  }
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

void vtkLabelMeshWriter::SetInterfacesData(vtkPolyData* interfaces)
{
  this->SetInputData(1, interfaces);
}

void vtkLabelMeshWriter::SetInterfacesConnection(vtkAlgorithmOutput* output)
{
  this->SetInputConnection(1, output);
}

std::string vtkLabelMeshWriter::GetKnownExtensions()
{
  return labelmesher::io::KnownExtensions();
}

void vtkLabelMeshWriter::WriteData()
{
  this->ErrorText.clear();
  auto* mesh = vtkUnstructuredGrid::SafeDownCast(this->GetInputDataObject(0, 0));
  auto* interfaces =
    this->GetNumberOfInputConnections(1) > 0 ? vtkPolyData::SafeDownCast(this->GetInputDataObject(1, 0)) : nullptr;
  try
  {
    if (!this->FileName || !*this->FileName)
    {
      throw labelmesher::io::WriteError("no file name given");
    }
    if (!mesh)
    {
      throw labelmesher::io::WriteError(std::string("cannot write '") + this->FileName + "': no mesh on input port 0");
    }
    // An upstream filter that failed leaves an empty output: no file is better than an empty one.
    if (mesh->GetNumberOfCells() == 0)
    {
      throw labelmesher::io::WriteError(std::string("cannot write '") + this->FileName + "': the mesh has no cells");
    }
    if (!mesh->GetCellData()->GetArray(labelmesher::arrays::Material))
    {
      throw labelmesher::io::WriteError(
        std::string("cannot write '") + this->FileName + "': the mesh has no cell array Material");
    }
    labelmesher::io::WriteOptions options;
    options.GmshVersion22 = this->GmshVersion22;
    options.StlPerInterface = this->StlPerInterface;
    const labelmesher::MaterialTable table = labelmesher::ReadMaterialTable(mesh->GetFieldData());
    labelmesher::io::MeshFileWriter(mesh, interfaces, table, options).Write(this->FileName);
    return;
  }
  catch (const std::bad_alloc&)
  {
    this->ErrorText = std::string("not enough memory to write '") + (this->FileName ? this->FileName : "") + "'";
  }
  catch (const std::exception& e)
  {
    this->ErrorText = e.what();
  }
  this->SetErrorCode(vtkErrorCode::CannotOpenFileError);
  vtkErrorMacro(<< this->ErrorText);
}

void vtkLabelMeshWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "GmshVersion22: " << this->GmshVersion22 << "\n";
  os << indent << "StlPerInterface: " << this->StlPerInterface << "\n";
}
