// SPDX-License-Identifier: GPL-2.0-or-later
// Reads label images (ITK formats, .vti, .png) into vtkImageData, checking every rule of the CLI's
// input; ReadLabeledImage hands .seg.nrrd files to SegmentationReader.cxx.
#include "ImageReader.h"

#include "ImageChecks.h"
#include "NiftiCheck.h"
#include "PngCheck.h"
#include "SegmentationReader.h"
#include "StringUtilities.h"
#include "TextHeader.h"
#include "VtiCheck.h"
#include "VTKMessages.h"

#include "itkImage.h"
#include "itkImageFileReader.h"
#include "itkImageIOBase.h"
#include "itkImageIOFactory.h"
#include "itkMultiThreaderBase.h"

#include "vtkAOSDataArrayTemplate.h"
#include "vtkCommand.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPNGReader.h"
#include "vtkPointData.h"
#include "vtkType.h"
#include "vtkXMLImageDataReader.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <limits>
#include <sstream>

namespace labelmesher
{
namespace io
{
namespace
{

using detail::CheckNotTruncated;
using detail::CheckSpacing;
using detail::GeometryFromITK;
using detail::VoxelText;

// ---- ITK: NRRD, NIfTI, MetaImage ----------------------------------------------

/// MetaIO writes its complaints ("Incomplete file record definition", "Uncompress failed") to
/// std::cerr as it reads. They would break the CLI's one-line errors, and ITK's exception or our
/// own checks say what is wrong, so std::cerr goes nowhere while ITK reads.
class QuietStandardError
{
public:
  QuietStandardError()
    : Saved(std::cerr.rdbuf(this->Discarded.rdbuf()))
  {
  }
  ~QuietStandardError() { std::cerr.rdbuf(this->Saved); }
  QuietStandardError(const QuietStandardError&) = delete;
  QuietStandardError& operator=(const QuietStandardError&) = delete;

private:
  std::ostringstream Discarded;
  std::streambuf* Saved;
};

template <typename TPixel>
typename itk::Image<TPixel, 3>::Pointer ReadITK(const std::string& path, itk::ImageIOBase* io)
{
  using ImageType = itk::Image<TPixel, 3>;
  auto reader = itk::ImageFileReader<ImageType>::New();
  reader->SetFileName(path);
  reader->SetImageIO(io);
  reader->Update();
  typename ImageType::Pointer image = reader->GetOutput();
  image->DisconnectPipeline();
  return image;
}

/// Integer pixels: copied as they are (the filter accepts every integer type).
template <typename TPixel>
vtkSmartPointer<vtkImageData> IntegerFromITK(const std::string& path, itk::ImageIOBase* io)
{
  auto image = ReadITK<TPixel>(path, io);
  auto output = GeometryFromITK(image.GetPointer(), path);
  vtkNew<vtkAOSDataArrayTemplate<TPixel>> labels;
  labels->SetName("Labels");
  const std::size_t n = image->GetLargestPossibleRegion().GetNumberOfPixels();
  labels->SetNumberOfValues(static_cast<vtkIdType>(n));
  std::copy(image->GetBufferPointer(), image->GetBufferPointer() + n, labels->GetPointer(0));
  output->GetPointData()->SetScalars(labels);
  return output;
}

/// Floating-point labels: accepted only if every value is an integer that fits 32 bits (label
/// maps are often stored as float); converted to int.
template <typename TReal>
vtkSmartPointer<vtkIntArray> IntegerLabels(const TReal* values, std::size_t n, const int dims[3], const std::string& path)
{
  auto labels = vtkSmartPointer<vtkIntArray>::New();
  labels->SetName("Labels");
  labels->SetNumberOfValues(static_cast<vtkIdType>(n));
  for (std::size_t i = 0; i < n; ++i)
  {
    const double v = static_cast<double>(values[i]);
    std::string problem;
    if (!std::isfinite(v))
    {
      problem = std::isnan(v) ? "NaN" : "an infinite value";
    }
    else if (v != std::floor(v))
    {
      std::ostringstream s;
      s << "the non-integer value " << v;
      problem = s.str();
    }
    else if (v < std::numeric_limits<std::int32_t>::min() || v > std::numeric_limits<std::int32_t>::max())
    {
      std::ostringstream s;
      s << "the value " << v << ", which does not fit a 32-bit label";
      problem = s.str();
    }
    if (!problem.empty())
    {
      throw InputError("'" + path + "' is not a label image: voxel " + VoxelText(i, dims) +
        " holds " + problem);
    }
    labels->SetValue(static_cast<vtkIdType>(i), static_cast<int>(v));
  }
  return labels;
}

template <typename TPixel>
vtkSmartPointer<vtkImageData> RealFromITK(const std::string& path, itk::ImageIOBase* io)
{
  auto image = ReadITK<TPixel>(path, io);
  auto output = GeometryFromITK(image.GetPointer(), path);
  int dims[3];
  output->GetDimensions(dims);
  output->GetPointData()->SetScalars(IntegerLabels(image->GetBufferPointer(),
    image->GetLargestPossibleRegion().GetNumberOfPixels(), dims, path));
  return output;
}

/// ITK's default threader is a pool whose threads start with the first ITK object, and a thread
/// that cannot start (no address space left: `ulimit -v`) ends the process in std::terminate.
/// Reading needs no threads: the platform threader starts none until a filter runs in parallel.
void AvoidITKThreadPool()
{
  static const bool once = [] {
    itk::MultiThreaderBase::SetGlobalDefaultThreader(itk::MultiThreaderBase::ThreaderEnum::Platform);
    return true;
  }();
  (void)once;
}

vtkSmartPointer<vtkImageData> ReadWithITK(const std::string& path)
{
  AvoidITKThreadPool();
  const detail::TextHeader header = detail::ReadTextHeader(path); // before NrrdIO or MetaIO parses it
  const QuietStandardError quiet;
  detail::CheckDetachedDataFile(path, header);
  const std::string lowerPath = Lower(path);
  if (EndsWith(lowerPath, ".nii") || EndsWith(lowerPath, ".nii.gz"))
  {
    CheckNiftiGeometry(path); // before ITK turns the transform into a VNL matrix
  }
  itk::ImageIOBase::Pointer io =
    itk::ImageIOFactory::CreateImageIO(path.c_str(), itk::ImageIOFactory::IOFileModeEnum::ReadMode);
  if (!io)
  {
    // A known extension whose reader refuses the content: say which format the file fails to be.
    const char* format = EndsWith(lowerPath, ".nrrd") || EndsWith(lowerPath, ".nhdr") ? "NRRD"
      : EndsWith(lowerPath, ".nii") || EndsWith(lowerPath, ".nii.gz")                 ? "NIfTI"
      : EndsWith(lowerPath, ".mha") || EndsWith(lowerPath, ".mhd")                    ? "MetaImage"
                                                                                      : nullptr;
    if (format)
    {
      throw InputError("cannot read '" + path + "': not a valid " + format + " file (its header cannot be read)");
    }
    throw InputError("'" + path + "' is not an image format labelmesher reads (.nrrd, .nhdr, .nii, "
                                  ".nii.gz, .mha, .mhd, .vti, .png)");
  }
  io->SetFileName(path);
  io->ReadImageInformation();
  detail::CheckHeaderSpacing(io, path);
  if (io->GetNumberOfComponents() != 1)
  {
    throw InputError("'" + path + "' has " + std::to_string(io->GetNumberOfComponents()) +
      " components per voxel: expected a single-channel label image");
  }
  for (unsigned int d = 3; d < io->GetNumberOfDimensions(); ++d)
  {
    if (io->GetDimensions(d) > 1)
    {
      throw InputError("'" + path + "' has " + std::to_string(io->GetNumberOfDimensions()) +
        " dimensions: expected a 2D or 3D label image");
    }
  }
  detail::CheckMetaImageReadAlike(path, io, header); // before the checks that rely on `header`
  CheckNotTruncated(path, io, header);
  detail::CheckCompressedVoxels(path, io, header);

  using C = itk::IOComponentEnum;
  switch (io->GetComponentType())
  {
    case C::UCHAR: return IntegerFromITK<unsigned char>(path, io);
    case C::CHAR: return IntegerFromITK<signed char>(path, io);
    case C::USHORT: return IntegerFromITK<unsigned short>(path, io);
    case C::SHORT: return IntegerFromITK<short>(path, io);
    case C::UINT: return IntegerFromITK<unsigned int>(path, io);
    case C::INT: return IntegerFromITK<int>(path, io);
    case C::ULONG: return IntegerFromITK<unsigned long>(path, io);
    case C::LONG: return IntegerFromITK<long>(path, io);
    case C::ULONGLONG: return IntegerFromITK<unsigned long long>(path, io);
    case C::LONGLONG: return IntegerFromITK<long long>(path, io);
    case C::FLOAT: return RealFromITK<float>(path, io);
    case C::DOUBLE: return RealFromITK<double>(path, io);
    default:
      throw InputError("'" + path + "' has an unsupported pixel type " +
        itk::ImageIOBase::GetComponentTypeAsString(io->GetComponentType()));
  }
}

// ---- VTK: VTI and PNG ------------------------------------------------------------

template <typename TReader>
vtkSmartPointer<vtkImageData> ReadWithVTK(const std::string& path)
{
  vtkNew<TReader> reader;
  VTKMessages errors(reader, vtkCommand::ErrorEvent);
  VTKMessages executiveErrors(reader->GetExecutive(), vtkCommand::ErrorEvent);
  reader->SetFileName(path.c_str());
  reader->Update();
  const std::string& message = errors.First().empty() ? executiveErrors.First() : errors.First();
  vtkImageData* image = reader->GetOutput();
  if (!message.empty() || !image || image->GetNumberOfPoints() == 0)
  {
    throw InputError("cannot read '" + path + "'" + (message.empty() ? "" : ": " + message));
  }
  auto output = vtkSmartPointer<vtkImageData>::New();
  output->ShallowCopy(image);
  CheckSpacing(output->GetSpacing(), path);
  return output;
}

bool IsIntegerType(int type)
{
  switch (type)
  {
    case VTK_CHAR: case VTK_SIGNED_CHAR: case VTK_UNSIGNED_CHAR: case VTK_SHORT: case VTK_UNSIGNED_SHORT:
    case VTK_INT: case VTK_UNSIGNED_INT: case VTK_LONG: case VTK_UNSIGNED_LONG: case VTK_LONG_LONG:
    case VTK_UNSIGNED_LONG_LONG: case VTK_ID_TYPE:
      return true;
    default:
      return false; // floating point, VTK_BIT, ...
  }
}

/// A VTI's labels: its point scalars, else its only point array; one integer component per point
/// (integral floats converted, as for the ITK formats), named Labels.
void CheckVTILabels(vtkImageData* image, const std::string& path)
{
  vtkPointData* points = image->GetPointData();
  vtkDataArray* labels = points->GetScalars();
  if (!labels && points->GetNumberOfArrays() == 1)
  {
    labels = points->GetArray(0);
  }
  if (!labels)
  {
    throw InputError("'" + path + "' has " + (points->GetNumberOfArrays() == 0 ? std::string("no point data array")
      : std::to_string(points->GetNumberOfArrays()) + " point data arrays and none marked as Scalars") +
      ": expected one integer array of labels");
  }
  if (labels->GetNumberOfComponents() != 1)
  {
    throw InputError("'" + path + "' has " + std::to_string(labels->GetNumberOfComponents()) +
      " components per voxel: expected a single-channel label image");
  }
  if (labels->GetNumberOfTuples() != image->GetNumberOfPoints())
  {
    throw InputError("'" + path + "' holds " + std::to_string(labels->GetNumberOfTuples()) + " labels for " +
      std::to_string(image->GetNumberOfPoints()) + " voxels");
  }
  int dims[3];
  image->GetDimensions(dims);
  const std::size_t n = static_cast<std::size_t>(labels->GetNumberOfTuples());
  vtkSmartPointer<vtkDataArray> checked = labels;
  if (auto* floats = vtkFloatArray::SafeDownCast(labels))
  {
    checked = IntegerLabels(floats->GetPointer(0), n, dims, path);
  }
  else if (auto* doubles = vtkDoubleArray::SafeDownCast(labels))
  {
    checked = IntegerLabels(doubles->GetPointer(0), n, dims, path);
  }
  else if (!IsIntegerType(labels->GetDataType()))
  {
    throw InputError("'" + path + "' has labels of type " + std::string(labels->GetDataTypeAsString()) +
      ": expected integers");
  }
  checked->SetName("Labels");
  points->SetScalars(checked);
}

} // namespace

vtkSmartPointer<vtkImageData> ReadLabelImage(const std::string& path)
{
  detail::CheckInputFile(path);
  const std::string lower = Lower(path);
  try
  {
    if (EndsWith(lower, ".vti"))
    {
      CheckVtiCompressionHeaders(path);
      vtkSmartPointer<vtkImageData> image = ReadWithVTK<vtkXMLImageDataReader>(path);
      CheckVTILabels(image, path);
      return image;
    }
    if (EndsWith(lower, ".png"))
    {
      CheckPngStructure(path);
      vtkSmartPointer<vtkImageData> image = ReadWithVTK<vtkPNGReader>(path);
      const int components = image->GetNumberOfScalarComponents();
      if (components != 1)
      {
        const char* kind = components == 2 ? "grey+alpha" : components == 3 ? "RGB" : "RGBA";
        throw InputError("'" + path + "' is an " + std::string(kind) + " PNG (" +
          std::to_string(components) + " channels): expected a single-channel label PNG");
      }
      image->GetPointData()->GetScalars()->SetName("Labels");
      return image;
    }
    return ReadWithITK(path);
  }
  catch (const itk::ExceptionObject& e)
  {
    throw detail::ITKReadError(path, e);
  }
}

LabeledImage ReadLabeledImage(const std::string& path)
{
  AvoidITKThreadPool(); // a 3D Slicer segmentation is read through ITK too
  if (IsSegmentationFile(path))
  {
    return ReadSegmentation(path);
  }
  LabeledImage result;
  result.Image = ReadLabelImage(path);
  return result;
}

} // namespace io
} // namespace labelmesher
