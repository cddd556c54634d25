// SPDX-License-Identifier: GPL-2.0-or-later
// Reads label images (ITK formats, .vti, .png) into vtkImageData, checking every rule of the CLI's
// input; ReadLabeledImage hands .seg.nrrd files to SegmentationReader.cxx.
#include "ImageReader.h"

#include "ImageChecks.h"
#include "NrrdSlices.h"
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
#include "itkImageRegionConstIterator.h"
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
#include <type_traits>

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

/// What ReadWithITK reads of the image: its geometry alone, all its voxels, or those of an extent.
struct ReadRequest
{
  enum class Kind
  {
    Information,
    Whole,
    Extent
  };
  Kind What = Kind::Whole;
  int Extent[6] = { 0, -1, 0, -1, 0, -1 }; ///< Kind::Extent: within the image's, in VTK's order
};

/// The region requested of `image`: the whole of it, or the extent's (ITK may have buffered
/// more, and says so in its own requested region).
template <typename TImage>
typename TImage::RegionType RequestedRegion(TImage* image, const ReadRequest& request)
{
  if (request.What != ReadRequest::Kind::Extent)
  {
    return image->GetLargestPossibleRegion();
  }
  typename TImage::RegionType region;
  for (unsigned int a = 0; a < 3; ++a)
  {
    region.SetIndex(a, request.Extent[2 * a]);
    region.SetSize(a, static_cast<itk::SizeValueType>(request.Extent[2 * a + 1] - request.Extent[2 * a] + 1));
  }
  return region;
}

template <typename TPixel>
typename itk::Image<TPixel, 3>::Pointer ReadITK(const std::string& path, itk::ImageIOBase* io, const ReadRequest& request)
{
  using ImageType = itk::Image<TPixel, 3>;
  auto reader = itk::ImageFileReader<ImageType>::New();
  reader->SetFileName(path);
  reader->SetImageIO(io);
  if (request.What == ReadRequest::Kind::Information)
  {
    reader->UpdateOutputInformation();
  }
  else
  {
    if (request.What == ReadRequest::Kind::Extent)
    {
      // ITK reads just this region where the format lets it (raw MetaImage, NIfTI); NrrdIO
      // reads the whole file, and the copy below keeps only the region.
      reader->UpdateOutputInformation();
      const typename ImageType::RegionType region = RequestedRegion(reader->GetOutput(), request);
      if (!reader->GetOutput()->GetLargestPossibleRegion().IsInside(region))
      {
        throw InputError("cannot read an extent of '" + path + "' beyond the image");
      }
      reader->GetOutput()->SetRequestedRegion(region);
    }
    reader->Update();
  }
  typename ImageType::Pointer image = reader->GetOutput();
  image->DisconnectPipeline();
  return image;
}

/// The requested voxels of `image` into `out`, in VTK's order (x fastest). The whole image is
/// its buffer; an extent is copied out of what ITK buffered (all of it, for NrrdIO).
template <typename TPixel, typename TOut>
void CopyRequestedVoxels(itk::Image<TPixel, 3>* image, const ReadRequest& request, TOut* out)
{
  using ImageType = itk::Image<TPixel, 3>;
  if (request.What != ReadRequest::Kind::Extent)
  {
    std::copy(image->GetBufferPointer(), image->GetBufferPointer() + image->GetLargestPossibleRegion().GetNumberOfPixels(), out);
    return;
  }
  for (itk::ImageRegionConstIterator<ImageType> it(image, RequestedRegion(image, request)); !it.IsAtEnd(); ++it)
  {
    *out++ = it.Get();
  }
}

/// The image's geometry, and for an extent its extent.
template <typename TImage>
vtkSmartPointer<vtkImageData> PlacedGeometry(TImage* image, const std::string& path, const ReadRequest& request)
{
  auto output = GeometryFromITK(image, path);
  if (request.What == ReadRequest::Kind::Extent)
  {
    output->SetExtent(const_cast<int*>(request.Extent));
  }
  return output;
}

/// Integer pixels: copied as they are (the filter accepts every integer type).
template <typename TPixel>
vtkSmartPointer<vtkImageData> IntegerFromITK(const std::string& path, itk::ImageIOBase* io, const ReadRequest& request)
{
  auto image = ReadITK<TPixel>(path, io, request);
  auto output = PlacedGeometry(image.GetPointer(), path, request);
  vtkNew<vtkAOSDataArrayTemplate<TPixel>> labels;
  labels->SetName("Labels");
  if (request.What != ReadRequest::Kind::Information)
  {
    labels->SetNumberOfValues(static_cast<vtkIdType>(RequestedRegion(image.GetPointer(), request).GetNumberOfPixels()));
    CopyRequestedVoxels(image.GetPointer(), request, labels->GetPointer(0));
  }
  output->GetPointData()->SetScalars(labels);
  return output;
}

/// Floating-point labels: accepted only if every value is an integer that fits 32 bits (label
/// maps are often stored as float); converted to int. `extent`: where the values lie.
template <typename TReal>
vtkSmartPointer<vtkIntArray> IntegerLabels(const TReal* values, std::size_t n, const int extent[6], const std::string& path)
{
  const int dims[3] = { extent[1] - extent[0] + 1, extent[3] - extent[2] + 1, extent[5] - extent[4] + 1 };
  const int start[3] = { extent[0], extent[2], extent[4] };
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
      throw InputError("'" + path + "' is not a label image: voxel " + VoxelText(i, dims, start) +
        " holds " + problem);
    }
    labels->SetValue(static_cast<vtkIdType>(i), static_cast<int>(v));
  }
  return labels;
}

template <typename TPixel>
vtkSmartPointer<vtkImageData> RealFromITK(const std::string& path, itk::ImageIOBase* io, const ReadRequest& request)
{
  auto image = ReadITK<TPixel>(path, io, request);
  auto output = PlacedGeometry(image.GetPointer(), path, request);
  if (request.What == ReadRequest::Kind::Information)
  {
    vtkNew<vtkIntArray> labels;
    labels->SetName("Labels");
    output->GetPointData()->SetScalars(labels);
    return output;
  }
  std::vector<TPixel> voxels(RequestedRegion(image.GetPointer(), request).GetNumberOfPixels());
  CopyRequestedVoxels(image.GetPointer(), request, voxels.data());
  image = nullptr; // the whole file's voxels, where ITK read them all
  output->GetPointData()->SetScalars(IntegerLabels(voxels.data(), voxels.size(), output->GetExtent(), path));
  return output;
}

/// An extent of a raw or gzip NRRD read slice by slice (NrrdSlices.h), ITK giving the geometry:
/// integer pixels as they are, real ones checked and converted as RealFromITK does.
template <typename TPixel>
vtkSmartPointer<vtkImageData> NrrdBoxBySlices(
  const std::string& path, itk::ImageIOBase* io, const detail::TextHeader& header, const ReadRequest& request)
{
  if (io->GetComponentSize() != sizeof(TPixel))
  {
    throw InputError("'" + path + "' has voxels of " + std::to_string(io->GetComponentSize()) + " bytes for its type");
  }
  ReadRequest information;
  information.What = ReadRequest::Kind::Information;
  auto image = ReadITK<TPixel>(path, io, information);
  auto output = PlacedGeometry(image.GetPointer(), path, request);
  const auto size = image->GetLargestPossibleRegion().GetSize();
  const int dims[3] = { static_cast<int>(size[0]), static_cast<int>(size[1]), static_cast<int>(size[2]) };
  const bool bigEndian = io->GetByteOrder() == itk::IOByteOrderEnum::BigEndian;
  const auto voxels = static_cast<std::size_t>(output->GetNumberOfPoints());
  if constexpr (std::is_integral_v<TPixel>)
  {
    vtkNew<vtkAOSDataArrayTemplate<TPixel>> labels;
    labels->SetName("Labels");
    labels->SetNumberOfValues(static_cast<vtkIdType>(voxels));
    detail::ReadNrrdBox(path, header, dims, sizeof(TPixel), bigEndian, request.Extent,
      reinterpret_cast<char*>(labels->GetPointer(0)));
    output->GetPointData()->SetScalars(labels);
  }
  else
  {
    std::vector<TPixel> values(voxels);
    detail::ReadNrrdBox(
      path, header, dims, sizeof(TPixel), bigEndian, request.Extent, reinterpret_cast<char*>(values.data()));
    output->GetPointData()->SetScalars(IntegerLabels(values.data(), voxels, output->GetExtent(), path));
  }
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

/// NrrdBoxBySlices for the file's pixel type.
vtkSmartPointer<vtkImageData> NrrdExtentBySlices(
  const std::string& path, itk::ImageIOBase* io, const detail::TextHeader& header, const ReadRequest& request)
{
  using C = itk::IOComponentEnum;
  switch (io->GetComponentType())
  {
    case C::UCHAR: return NrrdBoxBySlices<unsigned char>(path, io, header, request);
    case C::CHAR: return NrrdBoxBySlices<signed char>(path, io, header, request);
    case C::USHORT: return NrrdBoxBySlices<unsigned short>(path, io, header, request);
    case C::SHORT: return NrrdBoxBySlices<short>(path, io, header, request);
    case C::UINT: return NrrdBoxBySlices<unsigned int>(path, io, header, request);
    case C::INT: return NrrdBoxBySlices<int>(path, io, header, request);
    case C::ULONG: return NrrdBoxBySlices<unsigned long>(path, io, header, request);
    case C::LONG: return NrrdBoxBySlices<long>(path, io, header, request);
    case C::ULONGLONG: return NrrdBoxBySlices<unsigned long long>(path, io, header, request);
    case C::LONGLONG: return NrrdBoxBySlices<long long>(path, io, header, request);
    case C::FLOAT: return NrrdBoxBySlices<float>(path, io, header, request);
    case C::DOUBLE: return NrrdBoxBySlices<double>(path, io, header, request);
    default:
      throw InputError("'" + path + "' has an unsupported pixel type " +
        itk::ImageIOBase::GetComponentTypeAsString(io->GetComponentType()));
  }
}

vtkSmartPointer<vtkImageData> ReadWithITK(const std::string& path, const ReadRequest& request)
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

  if (request.What == ReadRequest::Kind::Extent && detail::ReadsNrrdBySlices(header))
  {
    return NrrdExtentBySlices(path, io, header, request);
  }
  using C = itk::IOComponentEnum;
  switch (io->GetComponentType())
  {
    case C::UCHAR: return IntegerFromITK<unsigned char>(path, io, request);
    case C::CHAR: return IntegerFromITK<signed char>(path, io, request);
    case C::USHORT: return IntegerFromITK<unsigned short>(path, io, request);
    case C::SHORT: return IntegerFromITK<short>(path, io, request);
    case C::UINT: return IntegerFromITK<unsigned int>(path, io, request);
    case C::INT: return IntegerFromITK<int>(path, io, request);
    case C::ULONG: return IntegerFromITK<unsigned long>(path, io, request);
    case C::LONG: return IntegerFromITK<long>(path, io, request);
    case C::ULONGLONG: return IntegerFromITK<unsigned long long>(path, io, request);
    case C::LONGLONG: return IntegerFromITK<long long>(path, io, request);
    case C::FLOAT: return RealFromITK<float>(path, io, request);
    case C::DOUBLE: return RealFromITK<double>(path, io, request);
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
  const std::size_t n = static_cast<std::size_t>(labels->GetNumberOfTuples());
  vtkSmartPointer<vtkDataArray> checked = labels;
  if (auto* floats = vtkFloatArray::SafeDownCast(labels))
  {
    checked = IntegerLabels(floats->GetPointer(0), n, image->GetExtent(), path);
  }
  else if (auto* doubles = vtkDoubleArray::SafeDownCast(labels))
  {
    checked = IntegerLabels(doubles->GetPointer(0), n, image->GetExtent(), path);
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
    return ReadWithITK(path, ReadRequest{});
  }
  catch (const itk::ExceptionObject& e)
  {
    throw detail::ITKReadError(path, e);
  }
}

bool ReadsByExtent(const std::string& path)
{
  const std::string lower = Lower(path);
  return !IsSegmentationFile(path) && !EndsWith(lower, ".vti") && !EndsWith(lower, ".png");
}

namespace
{
/// A file read by extent, through ReadWithITK (NrrdSlices for raw and gzip NRRD extents).
vtkSmartPointer<vtkImageData> ReadByExtent(const std::string& path, const ReadRequest& request)
{
  if (!ReadsByExtent(path))
  {
    throw std::invalid_argument("'" + path + "' is read whole, not by extent");
  }
  detail::CheckInputFile(path);
  try
  {
    return ReadWithITK(path, request);
  }
  catch (const itk::ExceptionObject& e)
  {
    throw detail::ITKReadError(path, e);
  }
}
} // namespace

vtkSmartPointer<vtkImageData> ReadLabelImageInformation(const std::string& path)
{
  ReadRequest request;
  request.What = ReadRequest::Kind::Information;
  return ReadByExtent(path, request);
}

vtkSmartPointer<vtkImageData> ReadLabelImageExtent(const std::string& path, const int extent[6])
{
  ReadRequest request;
  request.What = ReadRequest::Kind::Extent;
  std::copy(extent, extent + 6, request.Extent);
  return ReadByExtent(path, request);
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
