// SPDX-License-Identifier: GPL-2.0-or-later
// Reads label images for tests and benchmarks through LabelMesher::IO's checked reader, the one
// the CLI, the viewer, Python and ParaView use.
#include "LabelImageFile.h"

#include "ImageReader.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkPointData.h"

#include <algorithm>
#include <filesystem>
#include <stdexcept>

namespace labelmesher
{
namespace testing
{

LabelImageFile ReadLabelImageFile(const std::string& path)
{
  vtkSmartPointer<vtkImageData> image;
  try
  {
    image = io::ReadLabelImage(path);
  }
  catch (const io::InputError& e)
  {
    throw std::runtime_error(e.what());
  }
  int dims[3];
  image->GetDimensions(dims);
  LabelImageFile result;
  result.Image = LabelImage(dims[0], dims[1], dims[2]);
  std::copy_n(image->GetSpacing(), 3, result.Spacing.begin());
  // VTK's point order is x fastest, like LabelImage's.
  vtkDataArray* labels = image->GetPointData()->GetScalars();
  const std::size_t n = result.Image.NumberOfVoxels();
  for (std::size_t v = 0; v < n; ++v)
  {
    const double label = labels->GetComponent(static_cast<vtkIdType>(v), 0);
    if (label < 0)
      throw std::runtime_error("'" + path + "' has negative labels");
    result.Image.SetLabel(v, static_cast<std::int32_t>(label));
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
