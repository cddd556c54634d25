// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_io_TextHeader_h
#define labelmesher_io_TextHeader_h

/**
 * @file TextHeader.h
 * One reading of a NRRD (.nrrd, .nhdr) or MetaImage (.mha, .mhd) text header, before ITK
 * parses it: refuses the header lines that Debian's NrrdIO and MetaIO cannot take safely, and
 * keeps what the later checks need (where the voxels are, whether they are raw). Internal to
 * the readers (ImageReader.cxx, SegmentationReader.cxx); throws InputError.
 */

#include "itkImageIOBase.h"

#include <cstdint>
#include <filesystem>
#include <string>

namespace labelmesher
{
namespace io
{
namespace detail
{

struct TextHeader
{
  enum class Format
  {
    Other, ///< neither: no NRRD magic and not named .mha/.mhd
    Nrrd,
    MetaImage
  };
  Format Kind = Format::Other;
  bool RawData = false;    ///< the voxels are stored as uncompressed binary
  bool Compressed = false; ///< MetaImage: zlib-compressed voxels (CompressedData = True)
  bool Gzip = false;       ///< NRRD: gzip-compressed voxels (encoding gzip or gz)
  bool Skips = false;      ///< NRRD: a byte skip or line skip before the voxels
  std::uintmax_t CompressedBytes = 0; ///< MetaImage: CompressedDataSize, 0 when not given
  bool Detached = false; ///< the voxels are in another file than the header
  /// That file, relative to the header's folder resolved; empty when the voxels are attached or
  /// spread over several files (LIST, a name pattern with its range), which the readers check.
  std::filesystem::path DataFile;
  std::uintmax_t Length = 0; ///< bytes up to the attached voxels
};

/// Reads the header of `path` once. Throws InputError for a NRRD field line longer than NrrdIO's
/// error buffer, a MetaImage line that is not "Name = Value", a MetaImage NDims outside 1 to 8 or
/// MetaImage voxels stored as text; a file of another format gives Kind Other.
TextHeader ReadTextHeader(const std::string& path);

/// A detached header's data file must be a regular file: NrrdIO's message for a missing one calls
/// the header invalid, and for a folder says only "fread got only 0 1-sized things"; a device such
/// as /dev/stdin would block the reader.
void CheckDetachedDataFile(const std::string& path, const TextHeader& header);

/// Uncompressed voxels must be as long as the header says (ITK reads past the end of a truncated
/// raw file without complaint): NRRD and MetaImage from `header`, NIfTI from its fixed header.
void CheckNotTruncated(const std::string& path, itk::ImageIOBase* io, const TextHeader& header);

/// Compressed MetaImage voxels must be one zlib (or gzip) stream, CompressedDataSize bytes long,
/// that inflates to the bytes the header announces. ITK 5.2's MetaIO loops forever on a stream
/// that asks for a preset dictionary and leaks on a broken one (both found by fuzzing the
/// MetaImage reader); without a CompressedDataSize it returns uninitialised memory as voxels.
void CheckCompressedVoxels(const std::string& path, itk::ImageIOBase* io, const TextHeader& header);

/// MetaIO must have read the fields the checks above take from `header` as ReadTextHeader did
/// (CompressedData, CompressedDataSize, BinaryData, ElementDataFile): where a garbled header makes
/// the two readings differ, those checks would vouch for voxels MetaIO reads otherwise (a fuzzed
/// header made it read compressed voxels of unknown size). Compressed voxels with a HeaderSize are
/// refused, since they do not start where CheckCompressedVoxels inflates them.
void CheckMetaImageReadAlike(const std::string& path, itk::ImageIOBase* io, const TextHeader& header);

} // namespace detail
} // namespace io
} // namespace labelmesher

#endif
