// SPDX-License-Identifier: GPL-2.0-or-later
// PNG structure check (PNG specification, 2nd edition: sections 5 chunks, 11.2.2 IHDR, 8.2 Adam7).
#include "PngCheck.h"

#include "ImageReader.h"

#include <zlib.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <vector>

namespace labelmesher
{
namespace io
{
namespace
{

std::uint32_t BigEndian(const unsigned char* p)
{
  return (std::uint32_t{ p[0] } << 24) | (std::uint32_t{ p[1] } << 16) | (std::uint32_t{ p[2] } << 8) | p[3];
}

/// Bits per pixel of a valid (colour type, bit depth), 0 when invalid.
unsigned BitsPerPixel(unsigned colourType, unsigned depth)
{
  auto valid = [&](std::initializer_list<unsigned> depths) {
    for (unsigned d : depths)
    {
      if (d == depth)
      {
        return true;
      }
    }
    return false;
  };
  switch (colourType)
  {
    case 0: return valid({ 1, 2, 4, 8, 16 }) ? depth : 0;     // grey
    case 2: return valid({ 8, 16 }) ? 3 * depth : 0;          // RGB
    case 3: return valid({ 1, 2, 4, 8 }) ? depth : 0;         // palette
    case 4: return valid({ 8, 16 }) ? 2 * depth : 0;          // grey + alpha
    case 6: return valid({ 8, 16 }) ? 4 * depth : 0;          // RGBA
    default: return 0;
  }
}

struct Pass
{
  std::uint64_t Width, Height;
};

/// The sub-images of the data stream: one, or Adam7's seven.
std::vector<Pass> Passes(std::uint64_t width, std::uint64_t height, bool interlaced)
{
  if (!interlaced)
  {
    return { { width, height } };
  }
  const int x0[7] = { 0, 4, 0, 2, 0, 1, 0 }, dx[7] = { 8, 8, 4, 4, 2, 2, 1 };
  const int y0[7] = { 0, 0, 4, 0, 2, 0, 1 }, dy[7] = { 8, 8, 8, 4, 4, 2, 2 };
  std::vector<Pass> passes;
  for (int p = 0; p < 7; ++p)
  {
    const std::uint64_t w = width > static_cast<std::uint64_t>(x0[p]) ? (width - x0[p] + dx[p] - 1) / dx[p] : 0;
    const std::uint64_t h = height > static_cast<std::uint64_t>(y0[p]) ? (height - y0[p] + dy[p] - 1) / dy[p] : 0;
    passes.push_back({ w, h });
  }
  return passes;
}

} // namespace

void CheckPngStructure(const std::string& path)
{
  auto fail = [&](const std::string& problem) {
    throw InputError("'" + path + "' is not a valid PNG: " + problem);
  };
  std::ifstream in(path, std::ios::binary);
  std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in.eof() && in.fail())
  {
    throw InputError("cannot read '" + path + "'");
  }
  static const unsigned char signature[8] = { 0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n' };
  if (bytes.size() < 8 || std::memcmp(bytes.data(), signature, 8) != 0)
  {
    fail("no PNG signature");
  }
  std::size_t at = 8;
  std::uint64_t width = 0, height = 0;
  unsigned bits = 0;
  bool interlaced = false, sawHeader = false, sawEnd = false;
  std::vector<unsigned char> compressed;
  for (int index = 0; at < bytes.size() && !sawEnd; ++index)
  {
    if (bytes.size() - at < 12)
    {
      fail("the file ends inside chunk " + std::to_string(index));
    }
    const std::uint32_t length = BigEndian(&bytes[at]);
    const std::string type(reinterpret_cast<const char*>(&bytes[at + 4]), 4);
    if (length > 0x7fffffffu || bytes.size() - at - 12 < length)
    {
      fail("chunk " + std::to_string(index) + " is longer than the file");
    }
    for (char c : type)
    {
      if (!((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z')))
      {
        fail("chunk " + std::to_string(index) + " has an invalid type");
      }
    }
    const unsigned char* data = &bytes[at + 8];
    const auto crc = static_cast<std::uint32_t>(crc32(crc32(0L, Z_NULL, 0), &bytes[at + 4], length + 4));
    if (crc != BigEndian(data + length))
    {
      fail("chunk '" + type + "' has a wrong CRC (the file is damaged)");
    }
    if (index == 0 && type != "IHDR")
    {
      fail("the first chunk is not IHDR");
    }
    if (type == "IHDR")
    {
      if (sawHeader || length != 13)
      {
        fail("bad IHDR chunk");
      }
      sawHeader = true;
      width = BigEndian(data);
      height = BigEndian(data + 4);
      bits = BitsPerPixel(data[9], data[8]);
      if (width == 0 || height == 0 || width > 0x7fffffffu || height > 0x7fffffffu)
      {
        fail("image size " + std::to_string(width) + " x " + std::to_string(height));
      }
      if (bits == 0 || data[10] != 0 || data[11] != 0 || data[12] > 1)
      {
        fail("invalid colour type, bit depth, compression, filter or interlace method in IHDR");
      }
      interlaced = data[12] == 1;
    }
    else if (type == "IDAT")
    {
      compressed.insert(compressed.end(), data, data + length);
    }
    else if (type == "IEND")
    {
      sawEnd = true;
    }
    else if (!(type[0] & 0x20) && type != "PLTE")
    {
      fail("unknown critical chunk '" + type + "'");
    }
    at += 12 + length;
  }
  if (!sawEnd)
  {
    fail("no IEND chunk (the file is truncated)");
  }

  // Inflate and check every row: one filter byte (0..4) and ceil(w * bits / 8) bytes.
  std::uint64_t expected = 0;
  const std::vector<Pass> passes = Passes(width, height, interlaced);
  for (const Pass& p : passes)
  {
    if (p.Width > 0 && p.Height > 0)
    {
      expected += p.Height * (1 + (p.Width * bits + 7) / 8);
    }
  }
  if (expected > (std::uint64_t{ 1 } << 34))
  {
    fail("image too large");
  }
  std::vector<unsigned char> raw(static_cast<std::size_t>(expected) + 1);
  z_stream z{};
  if (inflateInit(&z) != Z_OK)
  {
    fail("zlib could not start");
  }
  z.next_in = compressed.data();
  z.avail_in = static_cast<uInt>(compressed.size());
  z.next_out = raw.data();
  z.avail_out = static_cast<uInt>(raw.size());
  const int status = inflate(&z, Z_FINISH);
  const std::uint64_t produced = z.total_out;
  inflateEnd(&z);
  if (status != Z_STREAM_END)
  {
    fail(produced > expected ? "more image data than the header announces" : "the image data is damaged or incomplete");
  }
  if (produced != expected)
  {
    fail("the image data holds " + std::to_string(produced) + " bytes, the header announces " + std::to_string(expected));
  }
  std::size_t row = 0;
  for (const Pass& p : passes)
  {
    if (p.Width == 0 || p.Height == 0)
    {
      continue;
    }
    const std::size_t stride = static_cast<std::size_t>(1 + (p.Width * bits + 7) / 8);
    for (std::uint64_t y = 0; y < p.Height; ++y, row += stride)
    {
      if (raw[row] > 4)
      {
        fail("invalid row filter " + std::to_string(raw[row]));
      }
    }
  }
}

} // namespace io
} // namespace labelmesher
