// SPDX-License-Identifier: GPL-2.0-or-later
// vtkLabelImageReader: what VTK's own NRRD reader gets wrong (gzip NRRD) read voxel for voxel with
// spacing and origin; a 3D Slicer segmentation's names and colours in the field data; every bad
// input refused with one line and an empty output; a colour table naming the labels.
#include "vtkLabelImageReader.h"

#include "FilterTestSupport.h"
#include "ImageReader.h"
#include "ScratchFolder.h"

#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkPointData.h"
#include "vtkStringArray.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <tuple>
#include <vector>

namespace
{
using labelmesher::testing::MessageRecorder;

using ReaderTest = labelmesher::testing::ScratchFolder;

std::string Gzip(const std::string& bytes)
{
  z_stream z{};
  EXPECT_EQ(deflateInit2(&z, Z_BEST_SPEED, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY), Z_OK); // 16: gzip wrapper
  std::string out(deflateBound(&z, bytes.size()) + 32, '\0');
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data()));
  z.avail_in = static_cast<uInt>(bytes.size());
  z.next_out = reinterpret_cast<Bytef*>(out.data());
  z.avail_out = static_cast<uInt>(out.size());
  EXPECT_EQ(deflate(&z, Z_FINISH), Z_STREAM_END);
  out.resize(z.total_out);
  deflateEnd(&z);
  return out;
}

void WriteFile(const std::string& path, const std::string& bytes)
{
  std::ofstream f(path, std::ios::binary);
  f << bytes;
  ASSERT_TRUE(f.good());
}

/// 7 x 5 x 4 voxels, label (3i + 5j + 7k) mod 6, as unsigned char.
std::vector<unsigned char> Pattern()
{
  std::vector<unsigned char> labels;
  for (int k = 0; k < 4; ++k)
    for (int j = 0; j < 5; ++j)
      for (int i = 0; i < 7; ++i)
        labels.push_back(static_cast<unsigned char>((3 * i + 5 * j + 7 * k) % 6));
  return labels;
}

std::string NrrdHeader(const std::string& type, const std::string& encoding, const std::string& extra = "")
{
  return "NRRD0004\ntype: " + type + "\ndimension: 3\nspace: left-posterior-superior\nsizes: 7 5 4\n"
         "space directions: (0.5,0,0) (0,0.25,0) (0,0,2)\nkinds: domain domain domain\nencoding: " + encoding +
    "\nspace origin: (1,2,3)\n" + extra + "\n";
}

vtkSmartPointer<vtkImageData> Read(vtkLabelImageReader* reader, const std::string& path)
{
  reader->SetFileName(path.c_str());
  reader->Update();
  return reader->GetOutput();
}

TEST_F(ReaderTest, GzipNrrdVoxelForVoxelWithSpacingAndOrigin)
{
  const std::vector<unsigned char> labels = Pattern();
  const std::string path = this->Path("pattern.nrrd");
  WriteFile(path, NrrdHeader("uchar", "gzip") + Gzip(std::string(labels.begin(), labels.end())));
  vtkNew<vtkLabelImageReader> reader;
  MessageRecorder errors(reader, vtkCommand::ErrorEvent);
  vtkImageData* image = Read(reader, path);
  ASSERT_TRUE(errors.Messages.empty()) << errors.Messages[0];
  int dims[3];
  image->GetDimensions(dims);
  EXPECT_EQ(dims[0], 7);
  EXPECT_EQ(dims[1], 5);
  EXPECT_EQ(dims[2], 4);
  // NRRD's LPS space becomes VTK's frame as ITK reads it: spacing positive, origin as written
  // up to the LPS sign convention ITK keeps (it does not flip to RAS).
  EXPECT_DOUBLE_EQ(image->GetSpacing()[0], 0.5);
  EXPECT_DOUBLE_EQ(image->GetSpacing()[1], 0.25);
  EXPECT_DOUBLE_EQ(image->GetSpacing()[2], 2.0);
  EXPECT_DOUBLE_EQ(image->GetOrigin()[0], 1.0);
  EXPECT_DOUBLE_EQ(image->GetOrigin()[1], 2.0);
  EXPECT_DOUBLE_EQ(image->GetOrigin()[2], 3.0);
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  ASSERT_NE(scalars, nullptr);
  EXPECT_STREQ(scalars->GetName(), "Labels");
  ASSERT_EQ(scalars->GetNumberOfTuples(), static_cast<vtkIdType>(labels.size()));
  for (vtkIdType v = 0; v < scalars->GetNumberOfTuples(); ++v)
  {
    ASSERT_EQ(scalars->GetComponent(v, 0), labels[static_cast<std::size_t>(v)]) << "voxel " << v;
  }
  EXPECT_STREQ(reader->GetErrorText(), "");
  EXPECT_EQ(reader->GetNumberOfNotes(), 0);
}

/// The reader's output for `extent` alone (a process reading its slab: VTK's UPDATE_EXTENT).
vtkImageData* ReadExtent(vtkLabelImageReader* reader, const int extent[6])
{
  reader->UpdateExtent(extent);
  return reader->GetOutput();
}

TEST_F(ReaderTest, AnExtentIsTheWholeImagesVoxelsThere)
{
  const std::vector<unsigned char> labels = Pattern();
  const std::string raw(labels.begin(), labels.end());
  std::string mha = "ObjectType = Image\nNDims = 3\nDimSize = 7 5 4\nElementType = MET_UCHAR\n"
                    "ElementSpacing = 0.5 0.25 2\nOffset = 1 2 3\nElementDataFile = LOCAL\n";
  const std::vector<std::pair<std::string, std::string>> files{
    { "raw.nrrd", NrrdHeader("uchar", "raw") + raw },
    { "gzip.nrrd", NrrdHeader("uchar", "gzip") + Gzip(raw) },
    { "raw.mha", mha + raw },
  };
  // Slabs along z (what a process of a distributed run asks for) and any box.
  const int extents[][6] = { { 0, 6, 0, 4, 2, 3 }, { 0, 6, 0, 4, 0, 0 }, { 1, 5, 2, 3, 1, 2 }, { 0, 6, 0, 4, 0, 3 } };
  for (const auto& [name, bytes] : files)
  {
    const std::string path = this->Path(name);
    WriteFile(path, bytes);
    for (const auto& extent : extents)
    {
      vtkNew<vtkLabelImageReader> reader;
      MessageRecorder errors(reader, vtkCommand::ErrorEvent);
      reader->SetFileName(path.c_str());
      vtkImageData* piece = ReadExtent(reader, extent);
      ASSERT_TRUE(errors.Messages.empty()) << name << ": " << errors.Messages[0];
      for (int e = 0; e < 6; ++e)
        ASSERT_EQ(piece->GetExtent()[e], extent[e]) << name;
      EXPECT_DOUBLE_EQ(piece->GetSpacing()[2], 2.0) << name;
      EXPECT_DOUBLE_EQ(piece->GetOrigin()[1], 2.0) << name;
      vtkDataArray* scalars = piece->GetPointData()->GetScalars();
      ASSERT_NE(scalars, nullptr) << name;
      EXPECT_STREQ(scalars->GetName(), "Labels");
      ASSERT_EQ(scalars->GetNumberOfTuples(), piece->GetNumberOfPoints()) << name;
      vtkIdType v = 0;
      for (int k = extent[4]; k <= extent[5]; ++k)
        for (int j = extent[2]; j <= extent[3]; ++j)
          for (int i = extent[0]; i <= extent[1]; ++i, ++v)
            ASSERT_EQ(scalars->GetComponent(v, 0), labels[static_cast<std::size_t>((k * 5 + j) * 7 + i)])
              << name << " voxel " << i << ' ' << j << ' ' << k;
    }
  }
}

TEST_F(ReaderTest, AnExtentOfABigEndianOrDamagedNrrd)
{
  // Two-byte labels stored big-endian, raw and gzip: read slice by slice, swapped.
  const std::vector<unsigned char> pattern = Pattern();
  std::string bigEndian;
  for (unsigned char p : pattern)
  {
    const unsigned value = 300u + p;
    bigEndian += static_cast<char>(value >> 8);
    bigEndian += static_cast<char>(value & 0xff);
  }
  const int slab[6] = { 0, 6, 0, 4, 1, 2 };
  for (const std::string& encoding : { std::string("raw"), std::string("gzip") })
  {
    const std::string path = this->Path("big_" + encoding + ".nrrd");
    WriteFile(path, NrrdHeader("ushort", encoding, "endian: big\n") + (encoding == "raw" ? bigEndian : Gzip(bigEndian)));
    vtkNew<vtkLabelImageReader> reader;
    MessageRecorder errors(reader, vtkCommand::ErrorEvent);
    reader->SetFileName(path.c_str());
    vtkDataArray* scalars = ReadExtent(reader, slab)->GetPointData()->GetScalars();
    ASSERT_TRUE(errors.Messages.empty()) << errors.Messages[0];
    ASSERT_NE(scalars, nullptr);
    ASSERT_EQ(scalars->GetNumberOfTuples(), 7 * 5 * 2);
    for (vtkIdType v = 0; v < scalars->GetNumberOfTuples(); ++v)
      ASSERT_EQ(scalars->GetComponent(v, 0), 300.0 + pattern[static_cast<std::size_t>(v + 35)]) << encoding << " voxel " << v;
  }
  // An extent beyond the image is refused, whatever reads it (slices, or ITK).
  for (const std::string& name : { std::string("big_raw.nrrd"), std::string("big_gzip.nrrd") })
  {
    const int beyond[6] = { 0, 7, 0, 4, 0, 0 };
    EXPECT_THROW(labelmesher::io::ReadLabelImageExtent(this->Path(name), beyond), labelmesher::io::InputError) << name;
    const int negative[6] = { 0, 6, -1, 4, 0, 0 };
    EXPECT_THROW(labelmesher::io::ReadLabelImageExtent(this->Path(name), negative), labelmesher::io::InputError) << name;
  }
  // A gzip stream cut short, and one damaged: one line each, no voxels.
  const std::string compressed = Gzip(std::string(pattern.begin(), pattern.end()));
  std::string damaged = compressed;
  damaged[damaged.size() / 2] = static_cast<char>(damaged[damaged.size() / 2] ^ 0x5a);
  // Two gzip members, as concatenated files make them: read as one stream.
  {
    const std::string path = this->Path("members.nrrd");
    const std::string bytes(pattern.begin(), pattern.end());
    WriteFile(path, NrrdHeader("uchar", "gzip") + Gzip(bytes.substr(0, 50)) + Gzip(bytes.substr(50)));
    vtkNew<vtkLabelImageReader> reader;
    MessageRecorder errors(reader, vtkCommand::ErrorEvent);
    reader->SetFileName(path.c_str());
    const int last[6] = { 0, 6, 0, 4, 2, 3 };
    vtkDataArray* scalars = ReadExtent(reader, last)->GetPointData()->GetScalars();
    ASSERT_TRUE(errors.Messages.empty()) << errors.Messages[0];
    ASSERT_NE(scalars, nullptr);
    for (vtkIdType v = 0; v < scalars->GetNumberOfTuples(); ++v)
      ASSERT_EQ(scalars->GetComponent(v, 0), pattern[static_cast<std::size_t>(v + 70)]) << "voxel " << v;
  }
  for (const auto& [name, voxels, problem] : { std::tuple<std::string, std::string, std::string>{ "short.nrrd",
         compressed.substr(0, compressed.size() / 2), "end before the image does" },
         { "damaged.nrrd", damaged, "" } })
  {
    const std::string path = this->Path(name);
    WriteFile(path, NrrdHeader("uchar", "gzip") + voxels);
    vtkNew<vtkLabelImageReader> reader;
    MessageRecorder errors(reader, vtkCommand::ErrorEvent);
    reader->SetFileName(path.c_str());
    const int last[6] = { 0, 6, 0, 4, 3, 3 };
    EXPECT_EQ(ReadExtent(reader, last)->GetNumberOfPoints(), 0) << name;
    ASSERT_EQ(errors.Messages.size(), 1u) << name;
    const std::string text = reader->GetErrorText();
    EXPECT_EQ(text.find('\n'), std::string::npos) << text;
    EXPECT_NE(text.find(problem), std::string::npos) << text;
    EXPECT_NE(text.find(name), std::string::npos) << text;
  }
}

TEST_F(ReaderTest, TheValuesBeyondAnExtentAreNeitherKeptNorChecked)
{
  // Floats, with a non-integer label in slice 3: the header reads, the slices before it too; the
  // whole image is refused, naming the voxel where it lies.
  std::vector<float> values(7 * 5 * 4, 1.0f);
  values[(3 * 5 + 2) * 7 + 4] = 0.5f;
  const std::string path = this->Path("half.nrrd");
  WriteFile(path, NrrdHeader("float", "raw", "endian: little\n") +
      std::string(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(float)));
  vtkNew<vtkLabelImageReader> reader;
  MessageRecorder errors(reader, vtkCommand::ErrorEvent);
  reader->SetFileName(path.c_str());
  reader->UpdateInformation();
  EXPECT_TRUE(errors.Messages.empty()) << errors.Messages[0];
  const int before[6] = { 0, 6, 0, 4, 0, 2 };
  EXPECT_EQ(ReadExtent(reader, before)->GetNumberOfPoints(), 7 * 5 * 3);
  EXPECT_TRUE(errors.Messages.empty()) << errors.Messages[0];
  reader->UpdateWholeExtent();
  ASSERT_EQ(errors.Messages.size(), 1u);
  EXPECT_NE(errors.Messages[0].find("voxel (4, 2, 3) holds the non-integer value 0.5"), std::string::npos)
    << errors.Messages[0];
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 0);
  const int within[6] = { 0, 6, 0, 4, 3, 3 };
  ReadExtent(reader, within);
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 0) << "a failed whole read is not retried with these settings";
}

TEST_F(ReaderTest, BadInputsAreOneLineAndAnEmptyOutput)
{
  const std::vector<unsigned char> labels = Pattern();
  std::string halves;
  for (unsigned char l : labels)
  {
    const float value = l + 0.5f;
    halves.append(reinterpret_cast<const char*>(&value), sizeof value);
  }
  WriteFile(this->Path("halves.nrrd"), NrrdHeader("float", "raw", "endian: little\n") + halves);
  WriteFile(this->Path("short.nrrd"), NrrdHeader("uchar", "raw") + std::string(labels.begin(), labels.end() - 9));
  WriteFile(this->Path("notes.txt"), "no image here");
  const std::pair<std::string, std::string> cases[] = {
    { this->Path("missing.nrrd"), "no such file" },
    { this->Path("halves.nrrd"), "non-integer value 0.5" },
    { this->Path("short.nrrd"), "bytes" },
    { this->Path("notes.txt"), "not an image format" },
    { this->Folder.string(), "not a regular file" },
  };
  for (const auto& [path, fragment] : cases)
  {
    vtkNew<vtkLabelImageReader> reader;
    MessageRecorder errors(reader, vtkCommand::ErrorEvent);
    vtkImageData* image = Read(reader, path);
    const std::string text = reader->GetErrorText();
    EXPECT_NE(text.find(fragment), std::string::npos) << path << ": " << text;
    EXPECT_EQ(text.find('\n'), std::string::npos) << text;
    ASSERT_EQ(errors.Messages.size(), 1u) << path;
    EXPECT_NE(errors.Messages[0].find(text), std::string::npos);
    EXPECT_EQ(image->GetNumberOfPoints(), 0) << path;
  }
}

TEST_F(ReaderTest, SegmentationNamesAndColoursInFieldData)
{
  vtkNew<vtkLabelImageReader> reader;
  MessageRecorder errors(reader, vtkCommand::ErrorEvent);
  vtkImageData* image =
    Read(reader, std::string(LABELMESHER_SOURCE_DIR) + "/Testing/Fuzz/Corpus/segmentation/one_layer.seg.nrrd");
  ASSERT_TRUE(errors.Messages.empty()) << errors.Messages[0];
  vtkFieldData* fd = image->GetFieldData();
  auto* labels = vtkDataArray::SafeDownCast(fd->GetAbstractArray("MaterialLabel"));
  auto* names = vtkStringArray::SafeDownCast(fd->GetAbstractArray("MaterialName"));
  auto* colours = vtkDoubleArray::SafeDownCast(fd->GetAbstractArray("MaterialColor"));
  ASSERT_TRUE(labels && names && colours);
  ASSERT_EQ(names->GetNumberOfValues(), 2);
  EXPECT_EQ(names->GetValue(0), "head");
  EXPECT_EQ(names->GetValue(1), "marker");
  EXPECT_EQ(labels->GetComponent(0, 0), 1);
  EXPECT_DOUBLE_EQ(colours->GetComponent(0, 0), 0.9);
  EXPECT_DOUBLE_EQ(colours->GetComponent(1, 2), 0.8);
}

TEST_F(ReaderTest, ColourTableNamesTheLabels)
{
  const std::vector<unsigned char> labels = Pattern();
  const std::string path = this->Path("pattern.nrrd");
  WriteFile(path, NrrdHeader("uchar", "raw") + std::string(labels.begin(), labels.end()));
  WriteFile(this->Path("names.txt"), "# ITK-SNAP\n    3   255    0    0        1  1  1    \"Liver tissue\"\n");
  vtkNew<vtkLabelImageReader> reader;
  reader->SetLabelTableFileName(this->Path("names.txt").c_str());
  vtkImageData* image = Read(reader, path);
  auto* names = vtkStringArray::SafeDownCast(image->GetFieldData()->GetAbstractArray("MaterialName"));
  ASSERT_NE(names, nullptr) << reader->GetErrorText();
  ASSERT_EQ(names->GetNumberOfValues(), 1);
  EXPECT_EQ(names->GetValue(0), "Liver tissue");
  EXPECT_EQ(image->GetFieldData()->GetArray("MaterialLabel")->GetComponent(0, 0), 3);

  // A bad table is the read's error, in one line naming the file.
  WriteFile(this->Path("bad.txt"), "3 255 0\n");
  reader->SetLabelTableFileName(this->Path("bad.txt").c_str());
  MessageRecorder errors(reader, vtkCommand::ErrorEvent);
  image = Read(reader, path);
  EXPECT_EQ(errors.Messages.size(), 1u);
  EXPECT_NE(std::string(reader->GetErrorText()).find("bad.txt"), std::string::npos) << reader->GetErrorText();
  EXPECT_EQ(image->GetNumberOfPoints(), 0);
}

TEST_F(ReaderTest, ReadsOncePerSettingAndAgainAfterModified)
{
  const std::vector<unsigned char> labels = Pattern();
  const std::string path = this->Path("pattern.nrrd");
  vtkNew<vtkLabelImageReader> reader;
  MessageRecorder errors(reader, vtkCommand::ErrorEvent);
  Read(reader, path); // missing: one error
  reader->Update();   // nothing changed: neither read nor said again
  EXPECT_EQ(errors.Messages.size(), 1u);
  WriteFile(path, NrrdHeader("uchar", "raw") + std::string(labels.begin(), labels.end()));
  reader->Modified(); // what ParaView's Reload does: read again
  reader->Update();
  EXPECT_EQ(errors.Messages.size(), 1u) << errors.Messages.back();
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), static_cast<vtkIdType>(labels.size()));
  EXPECT_STREQ(reader->GetErrorText(), "");
}

TEST(vtkLabelImageReader, CanReadFileByExtension)
{
  for (const char* name : { "a.nrrd", "a.NHDR", "a.seg.nrrd", "a.nii", "a.nii.gz", "a.mha", "a.mhd", "a.vti", "a.png" })
  {
    EXPECT_EQ(vtkLabelImageReader::CanReadFile(name), 1) << name;
  }
  for (const char* name : { "a.vtu", "a.gz", "nrrd", "" })
  {
    EXPECT_EQ(vtkLabelImageReader::CanReadFile(name), 0) << name;
  }
  EXPECT_EQ(vtkLabelImageReader::CanReadFile(nullptr), 0);
}

} // namespace
