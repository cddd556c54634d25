// SPDX-License-Identifier: GPL-2.0-or-later
#include "NiftiCheck.h"

#include "ImageReader.h"

#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <vector>

namespace labelmesher
{
namespace io
{
namespace
{
/// The header's bytes, gzip-inflated when compressed (gzread reads plain files as they are).
std::vector<unsigned char> ReadHeader(const std::string& path, std::size_t size)
{
  std::vector<unsigned char> header(size);
  gzFile file = gzopen(path.c_str(), "rb");
  if (!file)
  {
    return {};
  }
  const int read = gzread(file, header.data(), static_cast<unsigned>(size));
  gzclose(file);
  header.resize(read > 0 ? static_cast<std::size_t>(read) : 0);
  return header;
}

class Fields
{
public:
  Fields(const std::vector<unsigned char>& bytes, bool swap)
    : Bytes(bytes)
    , Swap(swap)
  {
  }

  template <typename T>
  T Get(std::size_t offset) const
  {
    unsigned char raw[sizeof(T)];
    std::memcpy(raw, this->Bytes.data() + offset, sizeof(T));
    if (this->Swap)
    {
      std::reverse(raw, raw + sizeof(T));
    }
    T value;
    std::memcpy(&value, raw, sizeof(T));
    return value;
  }

private:
  const std::vector<unsigned char>& Bytes;
  bool Swap;
};

/// Offsets of the geometry fields (NIfTI-1: nifti1.h, 348 bytes, float; NIfTI-2: nifti2.h,
/// 540 bytes, double).
struct Layout
{
  std::size_t Size, PixDim, QFormCode, SFormCode, Quatern, SRow;
  bool Doubles, WideCodes;
};
constexpr Layout kNifti1{ 348, 76, 252, 254, 256, 280, false, false };
constexpr Layout kNifti2{ 540, 104, 344, 348, 352, 400, true, true };
} // namespace

void CheckNiftiGeometry(const std::string& path)
{
  const std::vector<unsigned char> bytes = ReadHeader(path, kNifti2.Size);
  if (bytes.size() < 4)
  {
    return;
  }
  std::int32_t size;
  std::memcpy(&size, bytes.data(), 4);
  std::int32_t swapped = size;
  std::reverse(reinterpret_cast<unsigned char*>(&swapped), reinterpret_cast<unsigned char*>(&swapped) + 4);
  const Layout* layout = nullptr;
  bool swap = false;
  for (const Layout* candidate : { &kNifti1, &kNifti2 })
  {
    if (size == static_cast<std::int32_t>(candidate->Size) || swapped == static_cast<std::int32_t>(candidate->Size))
    {
      layout = candidate;
      swap = size != static_cast<std::int32_t>(candidate->Size);
    }
  }
  // niftilib reads a file with a NIfTI magic ("n+V"/"niV", V any digit 1-9, at byte 344 or 4)
  // whatever its sizeof_hdr, and such a header escaped the checks below (a hang, and ITK's abort
  // on a geometry read from the wrong offsets: both found by fuzzing); the standard fixes
  // sizeof_hdr, so a damaged one is refused.
  auto magic = [&](std::size_t at) -> char {
    const bool found = bytes.size() >= at + 4 && bytes[at] == 'n' && (bytes[at + 1] == '+' || bytes[at + 1] == 'i') &&
      bytes[at + 2] >= '1' && bytes[at + 2] <= '9' && bytes[at + 3] == '\0';
    return found ? static_cast<char>(bytes[at + 2]) : '\0';
  };
  if (!layout && (magic(344) || magic(4)))
  {
    throw InputError("'" + path + "' is not a valid NIfTI file (its header's sizeof_hdr is " + std::to_string(size) +
      ", expected " + (magic(344) ? "348" : "540") + ")");
  }
  if (!layout || bytes.size() < layout->Size)
  {
    return; // not a NIfTI header ITK would read; ITK says why
  }
  const Fields fields(bytes, swap);
  auto real = [&](std::size_t offset, int index) {
    return layout->Doubles ? fields.Get<double>(offset + 8 * static_cast<std::size_t>(index))
                           : static_cast<double>(fields.Get<float>(offset + 4 * static_cast<std::size_t>(index)));
  };
  auto code = [&](std::size_t offset) {
    return layout->WideCodes ? fields.Get<std::int32_t>(offset) : fields.Get<std::int16_t>(offset);
  };
  // ITK takes the transform's SVD in single precision, which never ends on entries near
  // FLT_MAX (found by fuzzing too): a millimetre geometry is far inside this bound.
  constexpr double kLargestGeometry = 1e9;
  auto require = [&](double value, const std::string& field) {
    if (!std::isfinite(value))
    {
      throw InputError("'" + path + "' is not a valid NIfTI file (its header's " + field + " is not finite)");
    }
    if (std::abs(value) > kLargestGeometry)
    {
      std::ostringstream text;
      text << "'" << path << "' is not a valid NIfTI file (its header's " << field << " is " << value
           << ", beyond +-1e9)";
      throw InputError(text.str());
    }
  };
  for (int d = 1; d <= 3; ++d)
  {
    require(real(layout->PixDim, d), "pixdim[" + std::to_string(d) + "]");
  }
  if (code(layout->QFormCode) > 0)
  {
    static const char* const names[] = { "quatern_b", "quatern_c", "quatern_d", "qoffset_x", "qoffset_y", "qoffset_z" };
    for (int q = 0; q < 6; ++q)
    {
      require(real(layout->Quatern, q), names[q]);
    }
    require(real(layout->PixDim, 0), "pixdim[0] (qfac)");
  }
  if (code(layout->SFormCode) > 0)
  {
    static const char* const rows[] = { "srow_x", "srow_y", "srow_z" };
    for (int e = 0; e < 12; ++e)
    {
      require(real(layout->SRow, e), std::string(rows[e / 4]) + "[" + std::to_string(e % 4) + "]");
    }
  }
}

} // namespace io
} // namespace labelmesher
