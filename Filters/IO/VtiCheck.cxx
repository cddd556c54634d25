// SPDX-License-Identifier: GPL-2.0-or-later
// Compression headers of a VTK XML image ("VTK File Formats", XML formats: compressed data is
// [#blocks][#u-size][#p-size][#c-size-1]...[#c-size-n], in words of header_type).
#include "VtiCheck.h"

#include "ImageReader.h"

#include "vtkBase64Utilities.h"
#include "vtkNew.h"
#include "vtkXMLDataElement.h"
#include "vtkXMLDataParser.h"

#include <cctype>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace labelmesher
{
namespace io
{
namespace
{

/// How the arrays' bytes are laid out, from the VTKFile and AppendedData elements.
struct Layout
{
  std::size_t HeaderWord = 4; ///< header_type UInt32 (the default) or UInt64
  bool BigEndian = false;
  bool AppendedBase64 = true;
  std::streamoff AppendedStart = -1;
  std::uintmax_t FileBytes = 0;
};

struct CompressionHeader
{
  std::uint64_t Blocks = 0, BlockBytes = 0, LastBlockBytes = 0;
};

/// The first three words at `position`, base64 or raw; false when the file ends before them.
bool ReadHeaderWords(std::istream& in, std::streamoff position, bool base64, const Layout& layout,
  CompressionHeader& header)
{
  in.clear();
  in.seekg(position);
  unsigned char words[3 * 8] = {};
  const std::size_t bytes = 3 * layout.HeaderWord;
  if (base64)
  {
    // Inline data may start after blanks; a header's 3 words are 16 or 32 base64 characters.
    std::string text;
    for (int c = in.get(); c != EOF && text.size() < bytes / 3 * 4; c = in.get())
    {
      if (!std::isspace(c))
      {
        text.push_back(static_cast<char>(c));
      }
    }
    if (text.size() < bytes / 3 * 4 ||
      vtkBase64Utilities::DecodeSafely(reinterpret_cast<const unsigned char*>(text.data()), text.size(), words,
        sizeof(words)) < bytes)
    {
      return false;
    }
  }
  else if (!in.read(reinterpret_cast<char*>(words), static_cast<std::streamsize>(bytes)))
  {
    return false;
  }
  std::uint64_t value[3] = {};
  for (int w = 0; w < 3; ++w)
  {
    for (std::size_t b = 0; b < layout.HeaderWord; ++b)
    {
      const std::size_t significance = layout.BigEndian ? layout.HeaderWord - 1 - b : b;
      value[w] |= std::uint64_t{ words[w * layout.HeaderWord + b] } << (8 * significance);
    }
  }
  header = { value[0], value[1], value[2] };
  return true;
}

/// Points or cells of a piece's Extent (vtkStructuredData's counts); 0 when it has none.
std::uint64_t TuplesOfExtent(vtkXMLDataElement* piece, bool cells)
{
  long long extent[6] = {};
  if (!piece || piece->GetVectorAttribute("Extent", 6, extent) != 6)
  {
    return 0;
  }
  std::uint64_t tuples = 1;
  for (int axis = 0; axis < 3; ++axis)
  {
    const long long points = extent[2 * axis + 1] - extent[2 * axis] + 1;
    if (points <= 0 || points > (1LL << 31))
    {
      return 0;
    }
    tuples *= static_cast<std::uint64_t>(cells && points > 1 ? points - 1 : points);
  }
  return tuples;
}

/// An array's tuples: its NumberOfTuples in field data, its piece's points or cells otherwise;
/// 0 when not known.
std::uint64_t TuplesOf(vtkXMLDataElement* array, vtkXMLDataElement* piece, const std::string& kind)
{
  if (kind == "FieldData")
  {
    long long count = 0;
    return array->GetScalarAttribute("NumberOfTuples", count) && count > 0 ? static_cast<std::uint64_t>(count) : 0;
  }
  return kind == "PointData" || kind == "CellData" ? TuplesOfExtent(piece, kind == "CellData") : 0;
}

class HeaderChecker
{
public:
  HeaderChecker(const std::string& path, std::istream& in, const Layout& layout, vtkXMLDataParser* parser)
    : Path(path), In(in), Format(layout), Parser(parser)
  {
  }

  /// Walks `element`'s subtree; `piece` is the Piece it lies in, `kind` its data element's name.
  void Check(vtkXMLDataElement* element, vtkXMLDataElement* piece, const std::string& kind)
  {
    const std::string name = element->GetName() ? element->GetName() : "";
    if (name == "DataArray")
    {
      this->CheckArray(element, piece, kind);
      return;
    }
    for (int i = 0; i < element->GetNumberOfNestedElements(); ++i)
    {
      this->Check(element->GetNestedElement(i), name == "Piece" ? element : piece,
        name == "PointData" || name == "CellData" || name == "FieldData" ? name : kind);
    }
  }

private:
  [[noreturn]] void Refuse(vtkXMLDataElement* array, const std::string& problem) const
  {
    const char* arrayName = array->GetAttribute("Name");
    throw InputError("'" + this->Path + "' is not a valid VTI file (the compressed array '" +
      (arrayName ? arrayName : "") + "' " + problem + ")");
  }

  void CheckArray(vtkXMLDataElement* array, vtkXMLDataElement* piece, const std::string& kind)
  {
    const char* format = array->GetAttribute("format");
    const bool appended = format && std::strcmp(format, "appended") == 0;
    if (!format || (!appended && std::strcmp(format, "binary") != 0))
    {
      return; // ascii: not compressed
    }
    std::streamoff position = 0;
    if (!appended)
    {
      // As vtkXMLDataParser finds inline data: past the start tag's '>' (blanks are skipped below).
      this->In.clear();
      this->In.seekg(array->GetXMLByteIndex());
      for (int c = this->In.get(); c != EOF && c != '>'; c = this->In.get())
      {
      }
      position = this->In.tellg();
    }
    else
    {
      long long offset = 0;
      if (this->Format.AppendedStart < 0 || !array->GetScalarAttribute("offset", offset) || offset < 0)
      {
        return; // VTK's reader refuses it
      }
      position = this->Format.AppendedStart + static_cast<std::streamoff>(offset);
    }
    CompressionHeader header;
    if (!ReadHeaderWords(this->In, position, !appended || this->Format.AppendedBase64, this->Format, header))
    {
      this->Refuse(array, "ends before its compression header");
    }
    if (header.Blocks > this->Format.FileBytes / this->Format.HeaderWord)
    {
      std::ostringstream s;
      s << "announces " << header.Blocks << " blocks, more than the file of " << this->Format.FileBytes
        << " bytes can list";
      this->Refuse(array, s.str());
    }
    int wordType = 0;
    int components = 1;
    array->GetScalarAttribute("NumberOfComponents", components);
    const std::uint64_t tuples = TuplesOf(array, piece, kind);
    if (!array->GetWordTypeAttribute("type", wordType) || components < 1 || tuples == 0)
    {
      return; // the block count alone is checked; VTK's reader judges the rest
    }
    const std::size_t wordBytes = this->Parser->GetWordTypeSize(wordType);
    if (wordType == VTK_BIT || wordType == VTK_STRING || wordBytes == 0)
    {
      return;
    }
    // The bytes the blocks hold: every block full but the last, which is LastBlockBytes when not 0.
    using Wide = unsigned __int128;
    const Wide announced = header.Blocks == 0 ? 0
      : Wide{ header.Blocks - 1 } * header.BlockBytes + (header.LastBlockBytes ? header.LastBlockBytes : header.BlockBytes);
    const Wide needed = Wide{ tuples } * static_cast<unsigned>(components) * wordBytes;
    if (announced != needed)
    {
      std::ostringstream s;
      s << "announces " << static_cast<long double>(announced) << " bytes in " << header.Blocks
        << " blocks; its " << tuples << " tuples of " << components << " components of " << wordBytes << " bytes are "
        << static_cast<long double>(needed);
      this->Refuse(array, s.str());
    }
  }

  const std::string& Path;
  std::istream& In;
  const Layout& Format;
  vtkXMLDataParser* Parser;
};

} // namespace

void CheckVtiCompressionHeaders(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  vtkNew<vtkXMLDataParser> parser;
  parser->SetStream(&in);
  if (!in || !parser->Parse())
  {
    return; // VTK's reader says why
  }
  vtkXMLDataElement* root = parser->GetRootElement();
  const char* compressor = root ? root->GetAttribute("compressor") : nullptr;
  if (!compressor || !*compressor)
  {
    return;
  }
  Layout layout;
  const char* headerType = root->GetAttribute("header_type");
  layout.HeaderWord = headerType && std::strcmp(headerType, "UInt64") == 0 ? 8 : 4;
  const char* byteOrder = root->GetAttribute("byte_order");
  layout.BigEndian = byteOrder && std::strcmp(byteOrder, "BigEndian") == 0;
  if (vtkXMLDataElement* appended = root->FindNestedElementWithName("AppendedData"))
  {
    const char* encoding = appended->GetAttribute("encoding");
    layout.AppendedBase64 = !encoding || std::strcmp(encoding, "raw") != 0;
    layout.AppendedStart = parser->GetAppendedDataPosition();
  }
  std::error_code ec;
  layout.FileBytes = std::filesystem::file_size(path, ec);
  if (ec)
  {
    return; // the reader reports it
  }
  HeaderChecker(path, in, layout, parser).Check(root, nullptr, "");
}

} // namespace io
} // namespace labelmesher
