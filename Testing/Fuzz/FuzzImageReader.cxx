// SPDX-License-Identifier: GPL-2.0-or-later
// Fuzz target (LLVMFuzzerTestOneInput; built for AFL++ with FileDriver.cxx as main()): the CLI's
// label-image reader (ReadLabeledImage, Filters/IO/ImageReader.h) on arbitrary bytes, saved under a name
// ending in LABELMESHER_FUZZ_EXTENSION (.nrrd, .nhdr, .nii, .mha, .vti, .png, .seg.nrrd: one target
// each). With LABELMESHER_FUZZ_DETACHED (the .nhdr target) the bytes are a detached header and its
// data file: up to and including the first blank line they are input.nhdr, the rest input.raw, which
// the seeds' headers name in their "data file:" line (a mutated header may name any other file).
// Every input must give a checked image or an InputError; any other exception, a crash, a
// hang or a sanitizer report is a finding, and so is an image the checks should have refused (not
// one integer component named Labels, or fewer values than voxels).
#include "ImageReader.h"
#include "VTKMessages.h"

#include "itkObject.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkPointData.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <unistd.h>

namespace
{
std::string& InputPath()
{
  static std::string path;
  return path;
}

// The detached header's data file, next to it.
std::string& DataPath()
{
  static std::string path;
  return path;
}

[[noreturn]] void Finding(const std::string& what)
{
  std::fprintf(stderr, "fuzz finding: %s\n", what.c_str());
  std::abort();
}

void Write(const std::string& path, const std::uint8_t* data, std::size_t size)
{
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  if (!out)
    Finding("cannot write " + path);
}

// How many of the bytes are the file the reader is given: all of them, or for a detached header
// those up to and including the first blank line (all of them when there is none).
std::size_t HeaderSize(const std::uint8_t* data, std::size_t size)
{
#ifdef LABELMESHER_FUZZ_DETACHED
  for (std::size_t i = 0; i + 1 < size; ++i)
    if (data[i] == '\n' && data[i + 1] == '\n')
      return i + 2;
#else
  (void)data;
#endif
  return size;
}
} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
  labelmesher::SilenceVTKOutputWindow();
  itk::Object::GlobalWarningDisplayOff();
  char folder[] = "/tmp/labelmesher-fuzz-XXXXXX";
  if (!mkdtemp(folder))
    Finding("cannot create a temporary folder");
  InputPath() = std::string(folder) + "/input" LABELMESHER_FUZZ_EXTENSION;
  DataPath() = std::string(folder) + "/input.raw";
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  const std::size_t headerSize = HeaderSize(data, size);
  Write(InputPath(), data, headerSize);
#ifdef LABELMESHER_FUZZ_DETACHED
  Write(DataPath(), data + headerSize, size - headerSize);
#endif
  try
  {
    const labelmesher::io::LabeledImage read = labelmesher::io::ReadLabeledImage(InputPath());
    vtkImageData* image = read.Image;
    vtkDataArray* labels = image ? image->GetPointData()->GetScalars() : nullptr;
    if (!labels || std::string(labels->GetName() ? labels->GetName() : "") != "Labels")
      Finding("an image without a Labels array got through");
    if (labels->GetNumberOfComponents() != 1 || labels->GetNumberOfTuples() != image->GetNumberOfPoints())
      Finding("an image with other than one value per voxel got through");
    if (labels->GetDataType() == VTK_FLOAT || labels->GetDataType() == VTK_DOUBLE)
      Finding("a floating-point label array got through");
  }
  catch (const labelmesher::io::InputError&)
  {
    // refused with a message: what malformed input must get
  }
  return 0;
}
