// SPDX-License-Identifier: GPL-2.0-or-later
// The CLI's checked label-image readers (ImageReader.h, SegmentationReader.h, ColorTableReader.h)
// as a VTK source. NRRD, NIfTI and MetaImage: RequestInformation reads the header alone and
// RequestData the extent asked for, held only as the output. The other formats: read whole in
// RequestInformation and held until a setting changes.
#include "vtkLabelImageReader.h"

#include "ColorTableReader.h"
#include "ImageReader.h"
#include "MaterialTable.h"
#include "StringUtilities.h"

#include "vtkDataObject.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMatrix3x3.h"
#include "vtkObjectFactory.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <exception>
#include <new>

vtkStandardNewMacro(vtkLabelImageReader);

vtkLabelImageReader::vtkLabelImageReader()
{
  this->SetNumberOfInputPorts(0);
}

vtkLabelImageReader::~vtkLabelImageReader()
{
  this->SetFileName(nullptr);
  this->SetLabelTableFileName(nullptr);
}

int vtkLabelImageReader::CanReadFile(const char* fileName)
{
  if (!fileName)
  {
    return 0;
  }
  const std::string lower = labelmesher::io::Lower(fileName);
  for (const char* suffix : { ".nrrd", ".nhdr", ".nii", ".nii.gz", ".mha", ".mhd", ".vti", ".png" })
  {
    if (labelmesher::io::EndsWith(lower, suffix))
    {
      return 1;
    }
  }
  return 0;
}

const char* vtkLabelImageReader::GetNote(int i)
{
  return i >= 0 && i < this->GetNumberOfNotes() ? this->Notes[static_cast<std::size_t>(i)].c_str() : nullptr;
}

bool vtkLabelImageReader::ReadIfChanged()
{
  if (this->ImageTime == this->GetMTime())
  {
    return this->Image != nullptr; // read (or failed, and said so) with these settings already
  }
  this->Image = nullptr;
  this->Notes.clear();
  this->ErrorText.clear();
  try
  {
    if (!this->FileName || !*this->FileName)
    {
      throw labelmesher::io::InputError("no file name given");
    }
    labelmesher::io::LabeledImage read;
    this->HoldsVoxels = !labelmesher::io::ReadsByExtent(this->FileName);
    if (this->HoldsVoxels)
    {
      read = labelmesher::io::ReadLabeledImage(this->FileName);
    }
    else
    {
      read.Image = labelmesher::io::ReadLabelImageInformation(this->FileName);
    }
    labelmesher::MaterialTable table = read.Materials;
    if (this->LabelTableFileName && *this->LabelTableFileName)
    {
      const labelmesher::MaterialTable names = labelmesher::io::ReadColorTable(this->LabelTableFileName);
      for (const labelmesher::MaterialInfo& entry : names.Entries())
      {
        table.Set(entry);
      }
    }
    if (!table.Empty())
    {
      labelmesher::StoreMaterialTable(read.Image->GetFieldData(), table);
    }
    this->Image = read.Image;
    this->Notes = read.Notes;
  }
  catch (const std::bad_alloc&)
  {
    this->ErrorText = std::string("not enough memory to read '") + (this->FileName ? this->FileName : "") + "'";
  }
  catch (const std::exception& e)
  {
    this->ErrorText = e.what();
  }
  this->ImageTime = this->GetMTime();
  if (!this->Image)
  {
    vtkErrorMacro(<< this->ErrorText);
    return false;
  }
  return true;
}

int vtkLabelImageReader::RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  if (!this->ReadIfChanged())
  {
    // An empty extent, and success: the error was reported once, in one line; failing the
    // request would add the executive's own multi-line record of it.
    const int empty[6] = { 0, -1, 0, -1, 0, -1 };
    outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), empty, 6);
    return 1;
  }
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), this->Image->GetExtent(), 6);
  // Any sub-extent: under MPI (pvbatch, pvserver) every process gets the one it asks for (a
  // slab of the image, or the whole of it for Label Mesher); a source that cannot produce
  // sub-extents gives every process but the first an empty image.
  outInfo->Set(vtkAlgorithm::CAN_PRODUCE_SUB_EXTENT(), 1);
  outInfo->Set(vtkDataObject::SPACING(), this->Image->GetSpacing(), 3);
  outInfo->Set(vtkDataObject::ORIGIN(), this->Image->GetOrigin(), 3);
  outInfo->Set(vtkDataObject::DIRECTION(), this->Image->GetDirectionMatrix()->GetData(), 9);
  vtkDataObject::SetPointDataActiveScalarInfo(
    outInfo, this->Image->GetScalarType(), this->Image->GetNumberOfScalarComponents());
  return 1;
}

int vtkLabelImageReader::RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkImageData* output = vtkImageData::GetData(outputVector);
  if (!this->ReadIfChanged())
  {
    output->Initialize();
    return 1;
  }
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  int extent[6];
  this->Image->GetExtent(extent);
  if (outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT()))
  {
    outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), extent);
  }
  const bool empty = extent[0] > extent[1] || extent[2] > extent[3] || extent[4] > extent[5];
  const int* whole = this->Image->GetExtent();
  const bool wholeExtent = std::equal(extent, extent + 6, whole);
  if (!this->HoldsVoxels && !empty)
  {
    // Read what was asked for, and hold it only as the output: a process of a distributed run
    // releases its slab's piece once converted, and the executive asks again only when the
    // request or a setting changes.
    this->ErrorText.clear();
    try
    {
      vtkSmartPointer<vtkImageData> read = labelmesher::io::ReadLabelImageExtent(this->FileName, extent);
      read->GetFieldData()->ShallowCopy(this->Image->GetFieldData());
      output->ShallowCopy(read);
      return 1;
    }
    catch (const std::bad_alloc&)
    {
      this->ErrorText = std::string("not enough memory to read '") + this->FileName + "'";
    }
    catch (const std::exception& e)
    {
      this->ErrorText = e.what();
    }
    if (wholeExtent)
    {
      this->Image = nullptr; // failed with these settings: neither read nor said again
    }
    vtkErrorMacro(<< this->ErrorText);
    output->Initialize();
    return 1;
  }
  if (empty && !this->HoldsVoxels)
  {
    output->Initialize();
    output->GetFieldData()->ShallowCopy(this->Image->GetFieldData());
    return 1;
  }
  output->ShallowCopy(this->Image);
  output->Crop(extent); // no-op for the whole extent
  return 1;
}

void vtkLabelImageReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "LabelTableFileName: " << (this->LabelTableFileName ? this->LabelTableFileName : "(none)") << "\n";
  os << indent << "ErrorText: " << this->ErrorText << "\n";
}
