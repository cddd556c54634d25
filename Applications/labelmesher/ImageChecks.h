// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_cli_ImageChecks_h
#define labelmesher_cli_ImageChecks_h

/**
 * @file ImageChecks.h
 * The checks every input image goes through, whichever reader reads it
 * (ImageReader.cxx, SegmentationReader.cxx): the path is a regular file,
 * uncompressed data is as long as the header says, the geometry ITK reports is
 * finite with positive spacing, a NRRD header holds nothing NrrdIO cannot
 * report safely. Internal to the CLI; each throws InputError.
 */

#include "ImageReader.h"
#include "StringUtilities.h"

#include "itkImageIOBase.h"
#include "itkMacro.h"

#include "vtkImageData.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace labelmesher_cli
{
namespace detail
{

/// "(i, j, k)" of the flat point index `flat` in an image of `dims`.
inline std::string VoxelText(std::size_t flat, const int dims[3])
{
  const std::size_t nx = dims[0], ny = dims[1];
  std::ostringstream s;
  s << "(" << flat % nx << ", " << (flat / nx) % ny << ", " << flat / (nx * ny) << ")";
  return s.str();
}

/// The readers' own messages for a missing path are less clear than this.
inline void CheckInputFile(const std::string& path)
{
  std::error_code ec;
  if (!std::filesystem::exists(path, ec))
  {
    throw InputError("cannot read '" + path + "': no such file");
  }
  if (!std::filesystem::is_regular_file(path, ec))
  {
    throw InputError("cannot read '" + path + "': not a regular file");
  }
}

/// Debian's NrrdIO (ITK 5.2) formats each parse error, the header line quoted, into a fixed
/// 1,025-byte stack buffer (biff's vsprintf): a malformed field line of about a thousand
/// characters overruns it and aborts the program (found by fuzzing the .seg.nrrd reader). Field
/// lines ("name: value") are short in every real file; comments and key/value lines (":=", which
/// may be long, as Slicer's conversion parameters are) are never quoted, so only field lines are
/// limited. Files that do not start with the NRRD magic are left to their readers.
inline void CheckNrrdHeaderLines(const std::string& path)
{
  constexpr std::size_t kLongestFieldLine = 800;
  std::ifstream in(path, std::ios::binary);
  std::string line;
  if (!std::getline(in, line) || line.rfind("NRRD", 0) != 0)
  {
    return;
  }
  for (int number = 2; std::getline(in, line); ++number)
  {
    if (!line.empty() && line.back() == '\r')
    {
      line.pop_back();
    }
    if (line.empty())
    {
      return; // the end of the header
    }
    if (line[0] != '#' && line.find(":=") == std::string::npos && line.size() > kLongestFieldLine)
    {
      throw InputError("'" + path + "' is not a valid NRRD file (header line " + std::to_string(number) +
        " is a field of " + std::to_string(line.size()) + " characters; at most " +
        std::to_string(kLongestFieldLine) + " are read)");
    }
  }
}

/// The data file a detached header names, relative to the header's folder: a NRRD's
/// "data file: NAME" (.nhdr) or a MetaImage's "ElementDataFile = NAME" (.mhd). Empty for attached
/// data (none, LOCAL) and for the multi-file forms (LIST, a pattern with its range), which are
/// left to the readers.
inline std::filesystem::path DetachedDataFile(const std::string& path)
{
  constexpr int kMostHeaderLines = 1000; // past them it is data, not a header
  std::ifstream in(path, std::ios::binary);
  std::string line;
  for (int number = 0; number < kMostHeaderLines && std::getline(in, line); ++number)
  {
    if (!line.empty() && line.back() == '\r')
    {
      line.pop_back();
    }
    if (line.empty())
    {
      break; // a NRRD header's end
    }
    const std::string l = Lower(line);
    const bool nrrd = l.rfind("data file:", 0) == 0 || l.rfind("datafile:", 0) == 0;
    const bool meta = l.rfind("elementdatafile", 0) == 0 && l.find('=') != std::string::npos;
    if (!nrrd && !meta)
    {
      continue;
    }
    std::string name = line.substr(line.find(nrrd ? ':' : '=') + 1);
    name.erase(0, name.find_first_not_of(" \t"));
    name.erase(name.find_last_not_of(" \t") + 1);
    const std::string lowerName = Lower(name);
    if (name.empty() || lowerName == "local" || lowerName.rfind("list", 0) == 0 ||
      name.find_first_of(" \t") != std::string::npos)
    {
      return {};
    }
    const std::filesystem::path file(name);
    return file.is_absolute() ? file : std::filesystem::path(path).parent_path() / file;
  }
  return {};
}

/// A detached header's data file must be a regular file: NrrdIO's message for a missing one calls
/// the header invalid, and for a folder says only "fread got only 0 1-sized things"; a device such
/// as /dev/stdin would block the reader.
inline void CheckDetachedDataFile(const std::string& path)
{
  const std::string lower = Lower(path);
  if (!EndsWith(lower, ".nhdr") && !EndsWith(lower, ".nrrd") && !EndsWith(lower, ".mhd") &&
    !EndsWith(lower, ".mha"))
  {
    return;
  }
  const std::filesystem::path data = DetachedDataFile(path);
  if (data.empty())
  {
    return;
  }
  std::error_code ec;
  const std::filesystem::file_status status = std::filesystem::status(data, ec);
  const char* problem = !std::filesystem::exists(status) ? "does not exist"
    : std::filesystem::is_directory(status)              ? "is a folder"
    : !std::filesystem::is_regular_file(status)          ? "is not a regular file"
                                                         : nullptr;
  if (problem)
  {
    throw InputError("cannot read '" + path + "': its data file '" + data.string() + "' " + problem);
  }
}

/// MetaIO reads NDims values for each per-axis field (and NDims squared for TransformMatrix)
/// with no bound: an NDims of 3e25 makes it read forever (found by fuzzing the MetaImage
/// reader). Every NDims line of a .mha/.mhd header must give 1 to 8 axes.
inline void CheckMetaImageDimensions(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::string line;
  for (int number = 1; number <= 64 && std::getline(in, line); ++number)
  {
    const std::size_t equals = line.find('=');
    if (equals == std::string::npos)
    {
      continue;
    }
    std::string key = line.substr(0, equals);
    key.erase(std::remove_if(key.begin(), key.end(), [](unsigned char c) { return std::isspace(c); }), key.end());
    if (key != "NDims")
    {
      if (key == "ElementDataFile")
      {
        return; // the header's last field
      }
      continue;
    }
    std::istringstream value(line.substr(equals + 1));
    long long dims = 0;
    std::string rest;
    if (!(value >> dims) || (value >> rest) || dims < 1 || dims > 8)
    {
      throw InputError("'" + path + "' is not a valid MetaImage file (header line " + std::to_string(number) +
        ": NDims must be 1 to 8)");
    }
  }
}

inline void CheckSpacing(const double spacing[3], const std::string& path)
{
  for (int a = 0; a < 3; ++a)
  {
    if (!std::isfinite(spacing[a]) || spacing[a] <= 0.0)
    {
      std::ostringstream s;
      s << "'" << path << "' has spacing " << spacing[a] << " along axis " << a
        << ": expected a positive, finite value";
      throw InputError(s.str());
    }
  }
}

/// Uncompressed formats whose data length we can compare with the header
/// (ITK reads past the end of a truncated raw file without complaint).
inline void CheckNotTruncated(const std::string& path, itk::ImageIOBase* io)
{
  const std::string lower = Lower(path);
  const std::uintmax_t bytes = io->GetImageSizeInBytes();
  std::uintmax_t fileSize = std::filesystem::file_size(path);
  std::uintmax_t header = 0;
  if (EndsWith(lower, ".nii"))
  {
    header = 352; // NIfTI-1 header + extension flag; vox_offset is at least this
  }
  else if (EndsWith(lower, ".mha") || EndsWith(lower, ".mhd") || EndsWith(lower, ".nrrd") || EndsWith(lower, ".nhdr"))
  {
    // Uncompressed data only, attached or in one detached data file (the header is text, read it).
    std::ifstream in(path, std::ios::binary);
    std::string line;
    bool raw = false;
    bool compressed = false; // MetaImage: CompressedData = True (raw otherwise, whatever the order)
    bool detached = false;
    while (std::getline(in, line) && !line.empty() && line != "\r")
    {
      const std::string l = Lower(line);
      if (l.rfind("encoding:", 0) == 0)
      {
        raw = l.find("raw") != std::string::npos;
      }
      if (l.rfind("compresseddata ", 0) == 0 || l.rfind("compresseddata=", 0) == 0)
      {
        compressed = l.find("true") != std::string::npos;
      }
      if (l.rfind("elementdatafile", 0) == 0)
      {
        raw = EndsWith(lower, ".mha") || EndsWith(lower, ".mhd") ? !compressed : raw;
        if (l.find("local") == std::string::npos)
        {
          detached = true;
        }
        break; // MetaImage data follows this line
      }
      if (l.rfind("data file:", 0) == 0 || l.rfind("datafile:", 0) == 0)
      {
        detached = true; // and the encoding may follow
      }
    }
    if (!raw)
    {
      return;
    }
    if (detached)
    {
      // The data file alone holds the voxels (a byte or line skip only needs more).
      const std::filesystem::path data = DetachedDataFile(path);
      if (data.empty())
      {
        return; // several data files: the reader checks them
      }
      std::error_code ec;
      fileSize = std::filesystem::file_size(data, ec);
      if (ec)
      {
        throw InputError("cannot read '" + path + "': its data file '" + data.string() + "' cannot be read");
      }
      if (fileSize < bytes)
      {
        std::ostringstream s;
        s << "'" << path << "' is truncated: the header announces " << bytes << " bytes of voxel data, its data file '"
          << data.string() << "' holds " << fileSize;
        throw InputError(s.str());
      }
      return;
    }
    header = static_cast<std::uintmax_t>(std::max<std::streamoff>(0, in.tellg()));
  }
  else
  {
    return;
  }
  if (fileSize < header + bytes)
  {
    std::ostringstream s;
    s << "'" << path << "' is truncated: the header announces " << bytes
      << " bytes of voxel data, the file holds at most " << (fileSize > header ? fileSize - header : 0);
    throw InputError(s.str());
  }
}

/// An empty vtkImageData with the dimensions, spacing, origin and direction of
/// the ITK image `image` (itk::Image or itk::VectorImage, 3D).
template <typename TImage>
vtkSmartPointer<vtkImageData> GeometryFromITK(TImage* image, const std::string& path)
{
  const auto size = image->GetLargestPossibleRegion().GetSize();
  auto output = vtkSmartPointer<vtkImageData>::New();
  output->SetDimensions(static_cast<int>(size[0]), static_cast<int>(size[1]), static_cast<int>(size[2]));
  double spacing[3], origin[3], direction[9];
  for (int r = 0; r < 3; ++r)
  {
    spacing[r] = image->GetSpacing()[r];
    origin[r] = image->GetOrigin()[r];
    for (int c = 0; c < 3; ++c)
    {
      direction[3 * r + c] = image->GetDirection()[r][c];
      if (!std::isfinite(direction[3 * r + c]))
      {
        throw InputError("'" + path + "' has a non-finite direction matrix");
      }
    }
    if (!std::isfinite(origin[r]))
    {
      throw InputError("'" + path + "' has a non-finite origin");
    }
  }
  CheckSpacing(spacing, path);
  output->SetSpacing(spacing);
  output->SetOrigin(origin);
  output->SetDirectionMatrix(direction);
  return output;
}

/// An ITK exception as InputError: ITK's descriptions may span lines.
/// The spacing the file's header gives, checked before ITK builds an image
/// (ITK refuses a zero spacing with an exception naming an object address).
/// A negative one is fine here: ITK turns it into a flipped direction.
inline void CheckHeaderSpacing(itk::ImageIOBase* io, const std::string& path)
{
  double spacing[3] = { 1.0, 1.0, 1.0 };
  for (unsigned int d = 0; d < std::min(3u, io->GetNumberOfDimensions()); ++d)
  {
    spacing[d] = std::abs(io->GetSpacing(d));
  }
  CheckSpacing(spacing, path);
}

inline InputError ITKReadError(const std::string& path, const itk::ExceptionObject& e)
{
  std::string what = e.GetDescription();
  what.erase(std::remove(what.begin(), what.end(), '\n'), what.end());
  // ITK's "itk::ERROR: Class(0x55...): " prefix names an object, not the problem.
  const std::size_t prefix = what.find("): ");
  if ((what.rfind("ITK ERROR: ", 0) == 0 || what.rfind("itk::ERROR: ", 0) == 0) && prefix != std::string::npos)
  {
    what = what.substr(prefix + 3);
  }
  // NrrdIO chains its callers' complaints ("... [nrrd] nrrdLoad: trouble ... [nrrd] fn: reason");
  // the last link says what is wrong with the file.
  const std::size_t last = what.rfind("[nrrd] ");
  if (last != std::string::npos)
  {
    std::string reason = what.substr(last + 7);
    const std::size_t colon = reason.find(": ");
    reason = colon == std::string::npos ? reason : reason.substr(colon + 2);
    return InputError("cannot read '" + path + "': not a valid NRRD file (" + reason + ")");
  }
  return InputError("cannot read '" + path + "': " + what);
}

} // namespace detail
} // namespace labelmesher_cli

#endif
