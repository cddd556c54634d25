// SPDX-License-Identifier: GPL-2.0-or-later
#include "TextHeader.h"

#include "ImageReader.h"
#include "StringUtilities.h"

#include "itkMetaImageIO.h"
#include "metaImage.h"

#include <zlib.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <sstream>
#include <vector>

namespace labelmesher
{
namespace io
{
namespace detail
{
namespace
{

/// One line of the header without its line ending (headers written on Windows end in "\r\n").
bool NextLine(std::istream& in, std::string& line)
{
  if (!std::getline(in, line))
  {
    return false;
  }
  if (!line.empty() && line.back() == '\r')
  {
    line.pop_back();
  }
  return true;
}

/// MetaIO keeps the CompressedDataSize it read protected, with no getter; a derived class may name
/// the member.
struct MetaImageFields : MetaImage
{
  static std::streamoff CompressedDataSize(const MetaImage& image)
  {
    return image.*(&MetaImageFields::m_CompressedDataSize);
  }
};

/// The data file a header names, relative to the header's folder; empty for the multi-file forms
/// (LIST, a pattern with its range) and for LOCAL.
std::filesystem::path DataFileNamed(const std::string& name, const std::string& headerPath)
{
  const std::string lower = Lower(name);
  if (name.empty() || lower == "local" || lower.rfind("list", 0) == 0 || name.find_first_of(" \t") != std::string::npos)
  {
    return {};
  }
  const std::filesystem::path file(name);
  return file.is_absolute() ? file : std::filesystem::path(headerPath).parent_path() / file;
}

/// A data file's name as the header gives it, refused when it holds control characters (a NUL
/// ends it early for the C readers, and the message would print them).
std::string DataFileName(const std::string& name, const std::string& path, const char* format)
{
  if (std::any_of(name.begin(), name.end(), [](unsigned char c) { return c < 0x20 || c == 0x7f; }))
  {
    throw InputError("'" + path + "' is not a valid " + format + " file (its data file name holds control characters)");
  }
  return name;
}

/// NRRD's "field: value" lines after the magic, up to the blank line that ends the header.
///
/// Debian's NrrdIO (ITK 5.2) formats each parse error, the header line quoted, into a fixed
/// 1,025-byte stack buffer (biff's vsprintf): a malformed field line of about a thousand
/// characters overruns it and aborts the program (found by fuzzing the .seg.nrrd reader). Field
/// lines are short in every real file; comments and key/value lines (":=", which may be long, as
/// Slicer's conversion parameters are) are never quoted, so only field lines are limited.
void ReadNrrdFields(std::istream& in, const std::string& path, TextHeader& header)
{
  constexpr std::size_t kLongestFieldLine = 800;
  std::string line;
  for (int number = 2; NextLine(in, line); ++number)
  {
    if (line.empty())
    {
      header.Length = static_cast<std::uintmax_t>(std::max<std::streamoff>(0, in.tellg()));
      return;
    }
    if (line[0] == '#' || line.find(":=") != std::string::npos)
    {
      continue;
    }
    if (line.size() > kLongestFieldLine)
    {
      throw InputError("'" + path + "' is not a valid NRRD file (header line " + std::to_string(number) +
        " is a field of " + std::to_string(line.size()) + " characters; at most " +
        std::to_string(kLongestFieldLine) + " are read)");
    }
    const std::string lower = Lower(line);
    if (lower.rfind("encoding:", 0) == 0)
    {
      const std::string encoding = Trim(lower.substr(lower.find(':') + 1));
      header.RawData = lower.find("raw") != std::string::npos;
      header.Gzip = encoding == "gzip" || encoding == "gz";
    }
    else if (lower.rfind("byte skip:", 0) == 0 || lower.rfind("byteskip:", 0) == 0 ||
      lower.rfind("line skip:", 0) == 0 || lower.rfind("lineskip:", 0) == 0)
    {
      header.Skips = true;
    }
    else if (lower.rfind("data file:", 0) == 0 || lower.rfind("datafile:", 0) == 0)
    {
      header.Detached = true; // the voxels are never in the header's file, whatever the name
      header.DataFile = DataFileNamed(DataFileName(Trim(line.substr(line.find(':') + 1)), path, "NRRD"), path);
    }
  }
}

/// MetaImage's "Key = Value" lines, up to ElementDataFile, which is the last.
///
/// MetaIO reads NDims values for each per-axis field (and NDims squared for TransformMatrix) with
/// no bound: an NDims of 3e25 makes it read forever (found by fuzzing the MetaImage reader).
/// Voxels stored as text (a BinaryData that MetaIO does not read as true) are refused: ITK 5.2
/// frees memory it does not own when it reads them into a 1D or 2D image (found the same way).
/// So are voxels spread over several data files.
void ReadMetaImageFields(std::istream& in, const std::string& path, TextHeader& header)
{
  constexpr int kMostHeaderLines = 1000; // past them it is data, not a header
  bool binary = true;                    // ITK reads binary voxels when BinaryData is absent
  std::string line;
  for (int number = 1; number <= kMostHeaderLines && NextLine(in, line); ++number)
  {
    // MetaIO's own reading of a field: the name ends at '=' or ':' and, being a C string, at a
    // NUL; the value follows the separators. Spaces and case are ignored here, to match more.
    const std::size_t separator = line.find_first_of("=:");
    if (separator == std::string::npos)
    {
      // MetaIO looks for the value of a line without a separator lines further on, so a garbled
      // line makes it read fields we never see (a fuzzed one hid `CompressedData = False`).
      if (std::all_of(line.begin(), line.end(), [](unsigned char c) { return std::isspace(c); }))
      {
        continue;
      }
      throw InputError("'" + path + "' is not a valid MetaImage file (header line " + std::to_string(number) +
        " is not 'Name = Value')");
    }
    std::string key = Lower(line.substr(0, std::min(separator, line.find('\0'))));
    key.erase(std::remove_if(key.begin(), key.end(), [](unsigned char c) { return std::isspace(c); }), key.end());
    const std::size_t start = line.find_first_not_of("=: \t", separator);
    std::string value = start == std::string::npos ? std::string() : line.substr(start);
    if (key != "elementdatafile")
    {
      value = value.substr(0, value.find('\0')); // a data file name keeps its NULs, to be refused
    }
    value = Trim(value);
    // MetaIO's booleans: true when the value starts with T, t or 1.
    const bool yes = !value.empty() && (value[0] == 'T' || value[0] == 't' || value[0] == '1');
    if (key == "ndims")
    {
      std::istringstream field(value);
      long long dims = 0;
      std::string extra;
      if (!(field >> dims) || (field >> extra) || dims < 1 || dims > 8)
      {
        throw InputError("'" + path + "' is not a valid MetaImage file (header line " + std::to_string(number) +
          ": NDims must be 1 to 8)");
      }
    }
    else if (key == "compresseddata")
    {
      header.Compressed = yes;
    }
    else if (key == "compresseddatasize")
    {
      std::istringstream field(value);
      long long bytes = 0; // signed: ">> unsigned" would read "-5" as a huge size
      header.CompressedBytes = field >> bytes && bytes > 0 ? static_cast<std::uintmax_t>(bytes) : 0;
    }
    else if (key == "binarydata")
    {
      binary = yes;
    }
    else if (key == "elementdatafile")
    {
      if (!binary)
      {
        throw InputError("'" + path + "' stores its voxels as text (BinaryData is not True), which "
          "labelmesher does not read: write them as binary");
      }
      header.RawData = !header.Compressed;
      header.Detached = Lower(value) != "local";
      header.DataFile = DataFileNamed(DataFileName(value, path, "MetaImage"), path);
      if (value.empty())
      {
        throw InputError("'" + path + "' is not a valid MetaImage file (ElementDataFile names no file)");
      }
      // LIST or a file-name pattern: MetaIO parses the pattern's numbers unchecked (a fuzzed one
      // made it allocate without bound), and real label images come in one file.
      if (header.Detached && header.DataFile.empty())
      {
        throw InputError("'" + path + "' spreads its voxels over several data files (ElementDataFile LIST or a "
          "pattern), which labelmesher does not read: write them to one file");
      }
      header.Length = static_cast<std::uintmax_t>(std::max<std::streamoff>(0, in.tellg()));
      return;
    }
  }
}

} // namespace

TextHeader ReadTextHeader(const std::string& path)
{
  TextHeader header;
  std::ifstream in(path, std::ios::binary);
  char magic[4] = {};
  std::string first;
  // The magic alone first: a binary file's "first line" may be all of it.
  if (in.read(magic, 4) && std::string(magic, 4) == "NRRD" && NextLine(in, first))
  {
    header.Kind = TextHeader::Format::Nrrd;
    ReadNrrdFields(in, path, header);
  }
  // MetaImage has no magic: its readers go by the name. A .mha that starts like a NRRD is checked
  // as both, since which reader ITK's factory tries first is not ours to rely on.
  const std::string lower = Lower(path);
  if (EndsWith(lower, ".mha") || EndsWith(lower, ".mhd"))
  {
    header = TextHeader();
    header.Kind = TextHeader::Format::MetaImage;
    in.clear();
    in.seekg(0);
    ReadMetaImageFields(in, path, header);
  }
  return header;
}

void CheckDetachedDataFile(const std::string& path, const TextHeader& header)
{
  if (!header.Detached || header.DataFile.empty())
  {
    return;
  }
  std::error_code ec;
  const std::filesystem::file_status status = std::filesystem::status(header.DataFile, ec);
  const char* problem = !std::filesystem::exists(status) ? "does not exist"
    : std::filesystem::is_directory(status)              ? "is a folder"
    : !std::filesystem::is_regular_file(status)          ? "is not a regular file"
                                                         : nullptr;
  if (problem)
  {
    throw InputError("cannot read '" + path + "': its data file '" + header.DataFile.string() + "' " + problem);
  }
}

void CheckNotTruncated(const std::string& path, itk::ImageIOBase* io, const TextHeader& header)
{
  std::uintmax_t start = 0; // where the voxels begin in the file that holds them
  std::filesystem::path holder = path;
  if (EndsWith(Lower(path), ".nii"))
  {
    start = 352; // NIfTI-1 header + extension flag; vox_offset is at least this
  }
  else if (header.Kind != TextHeader::Format::Other && header.RawData)
  {
    if (header.Detached && header.DataFile.empty())
    {
      return; // several data files: the reader checks them
    }
    // A detached data file alone holds the voxels (a byte or line skip only needs more).
    holder = header.Detached ? header.DataFile : std::filesystem::path(path);
    start = header.Detached ? 0 : header.Length;
  }
  else
  {
    return; // compressed, or a format whose length the reader checks
  }
  const std::uintmax_t bytes = io->GetImageSizeInBytes();
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(holder, ec);
  if (ec)
  {
    throw InputError(header.Detached ? "cannot read '" + path + "': its data file '" + holder.string() + "' cannot be read"
                                     : "cannot read '" + path + "': " + ec.message());
  }
  if (size < start + bytes)
  {
    std::ostringstream s;
    s << "'" << path << "' is truncated: the header announces " << bytes << " bytes of voxel data, ";
    if (header.Detached)
    {
      s << "its data file '" << holder.string() << "' holds " << size;
    }
    else
    {
      s << "the file holds at most " << (size > start ? size - start : 0);
    }
    throw InputError(s.str());
  }
}

void CheckCompressedVoxels(const std::string& path, itk::ImageIOBase* io, const TextHeader& header)
{
  if (header.Kind != TextHeader::Format::MetaImage || !header.Compressed || (header.Detached && header.DataFile.empty()))
  {
    return;
  }
  // Without the size MetaIO inflates nothing and hands on the uninitialised buffer as voxels.
  if (header.CompressedBytes == 0)
  {
    throw InputError("'" + path + "' is not a valid MetaImage file (CompressedData = True needs a positive "
      "CompressedDataSize)");
  }
  const std::filesystem::path holder = header.Detached ? header.DataFile : std::filesystem::path(path);
  const std::uintmax_t start = header.Detached ? 0 : header.Length;
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(holder, ec);
  std::ifstream in(holder, std::ios::binary);
  in.seekg(static_cast<std::streamoff>(start));
  if (ec || !in)
  {
    throw InputError("cannot read '" + path + "': its compressed voxel data cannot be read");
  }
  if (header.CompressedBytes > size - start)
  {
    std::ostringstream s;
    s << "'" << path << "' is truncated: its CompressedDataSize is " << header.CompressedBytes << " bytes, the "
      << (header.Detached ? "data file" : "file") << " holds " << size - start;
    throw InputError(s.str());
  }
  // Inflate as MetaIO does (zlib or gzip headers), into a small buffer: only the count is kept.
  z_stream stream{};
  if (inflateInit2(&stream, 15 + 32) != Z_OK)
  {
    throw InputError("cannot read '" + path + "': zlib cannot start (out of memory)");
  }
  const std::uintmax_t wanted = io->GetImageSizeInBytes();
  std::uintmax_t left = header.CompressedBytes;
  std::vector<unsigned char> input(1 << 16), output(1 << 16);
  std::uintmax_t produced = 0;
  int status = Z_OK;
  while (status == Z_OK && produced < wanted)
  {
    if (stream.avail_in == 0)
    {
      in.read(reinterpret_cast<char*>(input.data()),
        static_cast<std::streamsize>(std::min<std::uintmax_t>(input.size(), left)));
      const std::streamsize got = in.gcount();
      if (got <= 0)
      {
        break; // the data ends before its stream does
      }
      left -= static_cast<std::uintmax_t>(got);
      stream.next_in = input.data();
      stream.avail_in = static_cast<uInt>(got);
    }
    stream.next_out = output.data();
    stream.avail_out = static_cast<uInt>(output.size());
    status = inflate(&stream, Z_NO_FLUSH);
    produced += output.size() - stream.avail_out;
  }
  const std::string message = stream.msg ? stream.msg : "";
  inflateEnd(&stream);
  if (produced >= wanted)
  {
    return;
  }
  std::ostringstream s;
  if (status == Z_NEED_DICT)
  {
    s << "'" << path << "' is not a valid MetaImage file (its compressed voxel data asks for a preset zlib dictionary)";
  }
  else if (status < 0 && status != Z_BUF_ERROR)
  {
    s << "'" << path << "' is not a valid MetaImage file (its compressed voxel data is not a zlib stream"
      << (message.empty() ? "" : ": " + message) << ")";
  }
  else
  {
    s << "'" << path << "' is truncated: the header announces " << wanted << " bytes of voxel data, its compressed data"
      << (status == Z_STREAM_END ? " inflates to " : " ends after ") << produced;
  }
  throw InputError(s.str());
}

void CheckMetaImageReadAlike(const std::string& path, itk::ImageIOBase* io, const TextHeader& header)
{
  auto* metaIO = dynamic_cast<itk::MetaImageIO*>(io);
  if (header.Kind != TextHeader::Format::MetaImage || !metaIO)
  {
    return;
  }
  const MetaImage& image = *metaIO->GetMetaImagePointer();
  const std::streamoff bytes = MetaImageFields::CompressedDataSize(image);
  // ReadTextHeader keeps a size that is not positive as 0 (CheckCompressedVoxels refuses it).
  const bool sizeAlike = (bytes > 0 ? static_cast<std::uintmax_t>(bytes) : 0) == header.CompressedBytes;
  const std::string dataFile = Trim(image.ElementDataFileName());
  const bool dataFileAlike = Lower(dataFile) == "local" ? !header.Detached
                                                         : header.Detached && !header.DataFile.empty() &&
      DataFileNamed(dataFile, path) == header.DataFile;
  const char* differing = image.CompressedData() != header.Compressed ? "CompressedData"
    : header.Compressed && !sizeAlike                                 ? "CompressedDataSize"
    : !image.BinaryData()                                             ? "BinaryData"
    : !dataFileAlike                                                  ? "ElementDataFile"
                                                                      : nullptr;
  if (differing)
  {
    throw InputError("'" + path + "' is not a valid MetaImage file (its header is garbled: MetaIO does not read its " +
      differing + " as written)");
  }
  if (header.Compressed && image.HeaderSize() != 0)
  {
    throw InputError("'" + path + "' has compressed voxels after a HeaderSize, which labelmesher does not read: "
      "write them without HeaderSize");
  }
}

} // namespace detail
} // namespace io
} // namespace labelmesher
