// SPDX-License-Identifier: GPL-2.0-or-later
// Reads 3D label images with ITK for tests and benchmarks.
#include "LabelImageFile.h"

#include "itkImage.h"
#include "itkImageFileReader.h"

#include <algorithm>
#include <filesystem>
#include <stdexcept>

namespace labelmesher
{
namespace testing
{

LabelImageFile ReadLabelImageFile(const std::string& path)
{
  using ImageType = itk::Image<int, 3>;
  auto reader = itk::ImageFileReader<ImageType>::New();
  reader->SetFileName(path);
  try
  {
    reader->Update();
  }
  catch (const itk::ExceptionObject& e)
  {
    throw std::runtime_error("cannot read '" + path + "': " + e.GetDescription());
  }
  const ImageType* image = reader->GetOutput();
  const auto size = image->GetLargestPossibleRegion().GetSize();
  LabelImageFile result;
  result.Image = LabelImage(int(size[0]), int(size[1]), int(size[2]));
  for (int a = 0; a < 3; ++a)
    result.Spacing[a] = image->GetSpacing()[a];
  // ITK's buffer is x fastest, like LabelImage.
  const int* buffer = image->GetBufferPointer();
  const std::size_t n = result.Image.NumberOfVoxels();
  for (std::size_t v = 0; v < n; ++v)
  {
    if (buffer[v] < 0)
      throw std::runtime_error("'" + path + "' has negative labels");
    result.Image.Labels[v] = buffer[v];
  }
  return result;
}

std::vector<std::string> ListNrrdFiles(const std::string& directory)
{
  std::vector<std::string> files;
  std::error_code error;
  if (!std::filesystem::is_directory(directory, error))
    return files;
  for (const auto& entry : std::filesystem::directory_iterator(directory, error))
    if (entry.is_regular_file() && entry.path().extension() == ".nrrd")
      files.push_back(entry.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

} // namespace testing
} // namespace labelmesher
