// SPDX-License-Identifier: GPL-2.0-or-later
// A raw or gzip NRRD's voxels read as a stream of slices: seek past the slices before the box
// (raw), or inflate and drop them (gzip), then keep the box's rows of each of its slices.
#include "NrrdSlices.h"

#include "ImageReader.h"

#include <zlib.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <limits>
#include <vector>

namespace labelmesher
{
namespace io
{
namespace detail
{
namespace
{

/// The voxels' bytes in order, from where the header says they start.
class VoxelStream
{
public:
  VoxelStream(const std::string& path, const TextHeader& header)
    : Path(path)
    , Gzip(!header.RawData)
    , In(header.Detached ? header.DataFile : std::filesystem::path(path), std::ios::binary)
  {
    this->In.seekg(static_cast<std::streamoff>(header.Detached ? 0 : header.Length));
    if (!this->In)
    {
      throw InputError("cannot read '" + path + "': its voxels cannot be opened");
    }
    if (this->Gzip && inflateInit2(&this->Z, 16 + MAX_WBITS) != Z_OK) // 16: the gzip wrapper
    {
      throw InputError("cannot read '" + path + "': zlib cannot start inflating its voxels");
    }
  }
  ~VoxelStream()
  {
    if (this->Gzip)
    {
      inflateEnd(&this->Z);
    }
  }
  VoxelStream(const VoxelStream&) = delete;
  VoxelStream& operator=(const VoxelStream&) = delete;

  /// The next `bytes` bytes into `into`.
  void Read(char* into, std::size_t bytes)
  {
    if (!this->Gzip)
    {
      this->In.read(into, static_cast<std::streamsize>(bytes));
      if (static_cast<std::size_t>(this->In.gcount()) != bytes)
      {
        throw InputError("cannot read '" + this->Path + "': its voxels end before the image does");
      }
      return;
    }
    while (bytes > 0)
    {
      const std::size_t chunk = std::min<std::size_t>(bytes, std::numeric_limits<uInt>::max() / 2);
      this->Z.next_out = reinterpret_cast<Bytef*>(into);
      this->Z.avail_out = static_cast<uInt>(chunk);
      while (this->Z.avail_out > 0)
      {
        if (this->Z.avail_in == 0 && !this->Refill())
        {
          throw InputError("cannot read '" + this->Path + "': its gzip-compressed voxels end before the image does");
        }
        const int status = inflate(&this->Z, Z_NO_FLUSH);
        if (status == Z_STREAM_END && this->Z.avail_out > 0)
        {
          // A file of several gzip members (bgzip, concatenated files) goes on in the next one.
          if (!this->NextMember())
          {
            throw InputError("cannot read '" + this->Path + "': its gzip-compressed voxels end before the image does");
          }
          continue;
        }
        if (status != Z_OK && status != Z_STREAM_END && status != Z_BUF_ERROR)
        {
          throw InputError("cannot read '" + this->Path + "': its gzip-compressed voxels are damaged (" +
            (this->Z.msg ? this->Z.msg : "zlib error " + std::to_string(status)) + ")");
        }
      }
      into += chunk;
      bytes -= chunk;
    }
  }

  /// Once every voxel is read: a gzip stream is inflated to its end, so that its check sum is
  /// tested (surplus bytes are dropped, and a file that ends without the gzip trailer passes,
  /// as NrrdIO lets it).
  void Finish()
  {
    if (!this->Gzip)
    {
      return;
    }
    std::vector<char> dropped(std::size_t(1) << 16);
    for (;;)
    {
      if (this->Z.avail_in == 0 && !this->Refill())
      {
        return;
      }
      this->Z.next_out = reinterpret_cast<Bytef*>(dropped.data());
      this->Z.avail_out = static_cast<uInt>(dropped.size());
      const int status = inflate(&this->Z, Z_NO_FLUSH);
      if (status == Z_STREAM_END)
      {
        return;
      }
      if (status != Z_OK && status != Z_BUF_ERROR)
      {
        throw InputError("cannot read '" + this->Path + "': its gzip-compressed voxels are damaged (" +
          (this->Z.msg ? this->Z.msg : "zlib error " + std::to_string(status)) + ")");
      }
    }
  }

  /// Passes over the next `bytes` bytes: a seek when raw; inflated and dropped when compressed.
  void Skip(std::size_t bytes)
  {
    if (!this->Gzip)
    {
      this->In.seekg(static_cast<std::streamoff>(bytes), std::ios::cur);
      return; // a file too short shows at the next Read
    }
    std::vector<char> dropped(std::min<std::size_t>(bytes, std::size_t(1) << 20));
    while (bytes > 0)
    {
      const std::size_t chunk = std::min(bytes, dropped.size());
      this->Read(dropped.data(), chunk);
      bytes -= chunk;
    }
  }

private:
  /// More compressed bytes from the file; false at its end.
  bool Refill()
  {
    this->In.read(this->Compressed.data(), static_cast<std::streamsize>(this->Compressed.size()));
    this->Z.next_in = reinterpret_cast<Bytef*>(this->Compressed.data());
    this->Z.avail_in = static_cast<uInt>(this->In.gcount());
    return this->Z.avail_in > 0;
  }

  /// After a gzip member's end: the next member, if the file has more; false otherwise.
  bool NextMember()
  {
    if (this->Z.avail_in == 0 && !this->Refill())
    {
      return false;
    }
    return inflateReset(&this->Z) == Z_OK;
  }

  std::string Path;
  bool Gzip;
  std::ifstream In;
  z_stream Z{};
  std::vector<char> Compressed = std::vector<char>(std::size_t(1) << 18);
};

} // namespace

bool ReadsNrrdBySlices(const TextHeader& header)
{
  return header.Kind == TextHeader::Format::Nrrd && (header.RawData || header.Gzip) && !header.Skips &&
    !(header.Detached && header.DataFile.empty());
}

void ReadNrrdBox(const std::string& path, const TextHeader& header, const int dims[3], std::size_t voxelBytes,
  bool bigEndian, const int extent[6], char* out)
{
  for (int a = 0; a < 3; ++a)
  {
    if (extent[2 * a] < 0 || extent[2 * a + 1] >= dims[a] || extent[2 * a] > extent[2 * a + 1])
    {
      throw InputError("cannot read an extent of '" + path + "' beyond the image");
    }
  }
  const std::size_t nx = static_cast<std::size_t>(dims[0]), ny = static_cast<std::size_t>(dims[1]);
  const std::size_t sliceBytes = nx * ny * voxelBytes;
  const std::size_t rowBytes = static_cast<std::size_t>(extent[1] - extent[0] + 1) * voxelBytes;
  char* const first = out;
  VoxelStream voxels(path, header);
  voxels.Skip(static_cast<std::size_t>(extent[4]) * sliceBytes);
  std::vector<char> slice(sliceBytes);
  for (int k = extent[4]; k <= extent[5]; ++k)
  {
    voxels.Read(slice.data(), sliceBytes);
    for (int j = extent[2]; j <= extent[3]; ++j)
    {
      std::memcpy(out, slice.data() + (static_cast<std::size_t>(j) * nx + static_cast<std::size_t>(extent[0])) * voxelBytes,
        rowBytes);
      out += rowBytes;
    }
  }
  if (extent[5] == dims[2] - 1)
  {
    voxels.Finish(); // every voxel read: the stream's end and check sum too
  }
  if (bigEndian && voxelBytes > 1) // this machine is little-endian (x86-64, arm64 as Debian runs them)
  {
    for (char* v = first; v < out; v += voxelBytes)
    {
      std::reverse(v, v + voxelBytes);
    }
  }
}

} // namespace detail
} // namespace io
} // namespace labelmesher
