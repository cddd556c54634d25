// SPDX-License-Identifier: GPL-2.0-or-later
// Reads 3D Slicer segmentations (.seg.nrrd): the segment metadata of the NRRD header into a
// MaterialTable, the layers merged into one label image.
#include "SegmentationReader.h"

#include "ImageChecks.h"
#include "StringUtilities.h"
#include "TextHeader.h"

#include "itkImageFileReader.h"
#include "itkMetaDataObject.h"
#include "itkNrrdImageIO.h"
#include "itkVectorImage.h"

#include "vtkImageData.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <type_traits>
#include <utility>
#include <vector>

namespace labelmesher
{
namespace io
{
namespace
{

using detail::VoxelText;

constexpr std::int64_t MaxLabel = std::numeric_limits<std::int32_t>::max();

struct Segment
{
  int Index = 0;        ///< the i of Segment<i>_
  std::string Name;     ///< Segment<i>_Name, else _ID (as Slicer does), else empty
  std::array<double, 3> Color{ -1, -1, -1 };
  std::int64_t LabelValue = 1; ///< Slicer's default when the key is missing
  int Layer = 0;
  std::int32_t Merged = 0; ///< its label in the merged image

  std::string Title() const
  {
    return this->Name.empty() ? "Segment" + std::to_string(this->Index) : this->Name;
  }
};

std::string Key(int index, const char* field)
{
  return "Segment" + std::to_string(index) + "_" + field;
}

bool Lookup(const itk::MetaDataDictionary& dictionary, const std::string& key, std::string& value)
{
  return dictionary.HasKey(key) && itk::ExposeMetaData<std::string>(dictionary, key, value);
}

/// The whole of `text` (blanks around allowed) as an integer in [low, high].
bool ParseInteger(const std::string& text, std::int64_t low, std::int64_t high, std::int64_t& value)
{
  const std::string t = Trim(text);
  if (t.empty())
  {
    return false;
  }
  char* end = nullptr;
  errno = 0;
  const long long v = std::strtoll(t.c_str(), &end, 10);
  if (errno != 0 || *end != '\0' || v < low || v > high)
  {
    return false;
  }
  value = v;
  return true;
}

/// "r g b", each in [0, 1].
bool ParseColor(const std::string& text, std::array<double, 3>& color)
{
  std::istringstream in(text);
  for (double& c : color)
  {
    std::string word;
    if (!(in >> word))
    {
      return false;
    }
    char* end = nullptr;
    c = std::strtod(word.c_str(), &end);
    if (*end != '\0' || !(c >= 0.0 && c <= 1.0)) // NaN fails too
    {
      return false;
    }
  }
  std::string extra;
  return !(in >> extra);
}

InputError BadValue(const std::string& path, const std::string& key, const std::string& value,
  const std::string& expected)
{
  return InputError("'" + path + "' has " + key + " '" + Trim(value) + "': expected " + expected);
}

/// The Segment<i>_ entries, i = 0, 1, ... as long as some key has that prefix.
std::vector<Segment> ReadSegments(
  const itk::MetaDataDictionary& dictionary, unsigned int layers, const std::string& path)
{
  std::set<int> indices;
  for (const std::string& key : dictionary.GetKeys())
  {
    if (key.rfind("Segment", 0) != 0 || key.size() < 9 || !std::isdigit(static_cast<unsigned char>(key[7])))
    {
      continue;
    }
    const std::size_t underscore = key.find('_', 7);
    std::int64_t index = 0;
    if (underscore != std::string::npos &&
      ParseInteger(key.substr(7, underscore - 7), 0, std::numeric_limits<int>::max(), index))
    {
      indices.insert(static_cast<int>(index));
    }
  }

  std::vector<Segment> segments;
  for (int i = 0; indices.count(i) != 0; ++i)
  {
    Segment s;
    s.Index = i;
    if (!Lookup(dictionary, Key(i, "Name"), s.Name) || Trim(s.Name).empty())
    {
      Lookup(dictionary, Key(i, "ID"), s.Name);
    }
    s.Name = Trim(s.Name);

    std::string text;
    if (Lookup(dictionary, Key(i, "Color"), text) && !ParseColor(text, s.Color))
    {
      throw BadValue(path, Key(i, "Color"), text, "three numbers in [0, 1] (\"r g b\")");
    }
    if (Lookup(dictionary, Key(i, "LabelValue"), text) && !ParseInteger(text, 1, MaxLabel, s.LabelValue))
    {
      throw BadValue(path, Key(i, "LabelValue"), text, "an integer in [1, 2147483647]");
    }
    // Without a Layer key Slicer puts segment i in layer i; in a 3D file that
    // can only mean layer 0.
    std::int64_t layer = layers == 1 ? 0 : i;
    if (Lookup(dictionary, Key(i, "Layer"), text) &&
      !ParseInteger(text, 0, std::numeric_limits<int>::max(), layer))
    {
      throw BadValue(path, Key(i, "Layer"), text, "a non-negative integer");
    }
    if (layer >= static_cast<std::int64_t>(layers))
    {
      throw BadValue(path, Key(i, "Layer"), std::to_string(layer),
        "a layer index below " + std::to_string(layers) + ", the number of layers in the file");
    }
    s.Layer = static_cast<int>(layer);
    segments.push_back(s);
  }
  return segments;
}

/// Merged labels: the label values when they tell the segments apart, else 1..N.
void AssignLabels(std::vector<Segment>& segments, const std::string& path, std::vector<std::string>& notes)
{
  std::map<std::pair<int, std::int64_t>, const Segment*> byLayerValue;
  std::set<std::int64_t> values;
  bool repeated = false;
  for (const Segment& s : segments)
  {
    auto inserted = byLayerValue.emplace(std::make_pair(s.Layer, s.LabelValue), &s);
    if (!inserted.second)
    {
      // One voxel value, two segments: nothing in the file tells them apart.
      throw InputError("'" + path + "': segments '" + inserted.first->second->Title() + "' and '" +
        s.Title() + "' both have label value " + std::to_string(s.LabelValue) + " in layer " +
        std::to_string(s.Layer) + ": labelmesher needs one material per voxel");
    }
    repeated = !values.insert(s.LabelValue).second || repeated;
  }
  for (Segment& s : segments)
  {
    s.Merged = static_cast<std::int32_t>(repeated ? s.Index + 1 : s.LabelValue);
  }
  if (repeated)
  {
    notes.push_back("segments renumbered 1.." + std::to_string(segments.size()) +
      ": label values repeat across layers");
  }
}

/// True when `v` can be a label: an integer that fits 32 bits.
template <typename TPixel>
bool FitsLabel(TPixel v)
{
  constexpr double low = std::numeric_limits<std::int32_t>::min();
  if constexpr (std::is_floating_point<TPixel>::value)
  {
    return std::isfinite(v) && v == std::floor(v) && v >= low && v <= static_cast<double>(MaxLabel);
  }
  else if constexpr (std::numeric_limits<TPixel>::digits <= 31)
  {
    return true;
  }
  else if constexpr (std::is_signed<TPixel>::value)
  {
    return v >= std::numeric_limits<std::int32_t>::min() && v <= MaxLabel;
  }
  else
  {
    return v <= static_cast<unsigned long long>(MaxLabel);
  }
}

/// What is wrong with a value FitsLabel rejects.
template <typename TPixel>
std::string ValueProblem(TPixel v)
{
  std::ostringstream s;
  if (std::is_floating_point<TPixel>::value && !std::isfinite(static_cast<double>(v)))
  {
    return std::isnan(static_cast<double>(v)) ? "NaN" : "an infinite value";
  }
  if (std::is_floating_point<TPixel>::value && v != std::floor(static_cast<double>(v)))
  {
    s << "the non-integer value " << v;
    return s.str();
  }
  s << "the value " << v << ", which does not fit a 32-bit label";
  return s.str();
}

/// The layers of the file merged into one image of merged labels.
class Merger
{
public:
  Merger(const std::string& path, const std::vector<Segment>& segments, unsigned int layers)
    : Path(path)
    , Segments(segments)
    , Layers(layers)
    , ToMerged(layers)
  {
    for (const Segment& s : segments)
    {
      this->ToMerged[s.Layer][s.LabelValue] = s.Merged;
      this->Declared[std::make_pair(s.Layer, s.LabelValue)] = &s;
    }
  }

  template <typename TPixel>
  vtkSmartPointer<vtkImageData> Run(itk::NrrdImageIO* io, std::vector<std::string>& notes)
  {
    using ImageType = itk::VectorImage<TPixel, 3>;
    auto reader = itk::ImageFileReader<ImageType>::New();
    reader->SetFileName(this->Path);
    reader->SetImageIO(io);
    reader->Update();
    typename ImageType::Pointer image = reader->GetOutput();
    vtkSmartPointer<vtkImageData> output = detail::GeometryFromITK(image.GetPointer(), this->Path);
    output->GetDimensions(this->Dims);
    const std::size_t n = image->GetLargestPossibleRegion().GetNumberOfPixels();
    const TPixel* data = image->GetBufferPointer();
    const unsigned int layers = this->Layers;

    // Pass 1: at most one non-zero layer per voxel; which values each layer holds.
    std::vector<std::set<std::int64_t>> present(layers);
    std::vector<std::int64_t> last(layers, 0);
    for (std::size_t v = 0; v < n; ++v)
    {
      int hit = -1;
      for (unsigned int l = 0; l < layers; ++l)
      {
        const TPixel x = data[v * layers + l];
        if (x == 0)
        {
          continue;
        }
        if (!FitsLabel(x))
        {
          throw InputError("'" + this->Path + "' is not a label image: voxel " + VoxelText(v, this->Dims) +
            (layers > 1 ? " of layer " + std::to_string(l) : std::string()) + " holds " + ValueProblem(x));
        }
        const auto value = static_cast<std::int64_t>(x);
        if (hit >= 0)
        {
          const auto first = static_cast<unsigned int>(hit);
          this->Overlap(v, first, static_cast<std::int64_t>(data[v * layers + first]), l, value);
        }
        hit = static_cast<int>(l);
        if (value != last[l]) // runs of one value are the rule
        {
          present[l].insert(value);
          last[l] = value;
        }
      }
    }
    this->AssignUndeclared(present, notes);

    // Pass 2: the merged labels.
    vtkNew<vtkIntArray> labels;
    labels->SetName("Labels");
    labels->SetNumberOfValues(static_cast<vtkIdType>(n));
    int* out = labels->GetPointer(0);
    std::vector<std::int64_t> lastValue(layers, 0);
    std::vector<std::int32_t> lastLabel(layers, 0);
    for (std::size_t v = 0; v < n; ++v)
    {
      std::int32_t label = 0;
      for (unsigned int l = 0; l < layers; ++l)
      {
        const TPixel x = data[v * layers + l];
        if (x != 0)
        {
          const auto value = static_cast<std::int64_t>(x);
          if (value != lastValue[l]) // never at first: lastValue starts at 0
          {
            lastValue[l] = value;
            lastLabel[l] = this->ToMerged[l].at(value);
          }
          label = lastLabel[l];
          break; // pass 1 proved it is the only one
        }
      }
      out[v] = label;
    }
    output->GetPointData()->SetScalars(labels);
    return output;
  }

private:
  const Segment* Find(unsigned int layer, std::int64_t value) const
  {
    auto at = this->Declared.find(std::make_pair(static_cast<int>(layer), value));
    return at != this->Declared.end() ? at->second : nullptr;
  }

  [[noreturn]] void Overlap(std::size_t voxel, unsigned int layerA, std::int64_t valueA, unsigned int layerB,
    std::int64_t valueB) const
  {
    const Segment* a = this->Find(layerA, valueA);
    const Segment* b = this->Find(layerB, valueB);
    // "segments 'A' (layer 0) and 'B' (layer 1)", "segment 'A' (layer 0) and undeclared value 7 (layer 1)"
    auto describe = [a, b](const Segment* s, unsigned int layer, std::int64_t value) {
      const std::string what = !s ? "undeclared value " + std::to_string(value)
        : a && b                  ? "'" + s->Title() + "'"
                                  : "segment '" + s->Title() + "'";
      return what + " (layer " + std::to_string(layer) + ")";
    };
    throw InputError("'" + this->Path + "': " + (a && b ? "segments " : "") + describe(a, layerA, valueA) +
      " and " + describe(b, layerB, valueB) + " overlap at voxel " + VoxelText(voxel, this->Dims) +
      ": labelmesher needs one material per voxel");
  }

  /// Values no segment declares keep their own number as label, unless a
  /// segment already has that label: then they get a fresh one above all.
  void AssignUndeclared(const std::vector<std::set<std::int64_t>>& present, std::vector<std::string>& notes)
  {
    std::set<std::int64_t> taken;
    std::int64_t top = 0;
    for (const Segment& s : this->Segments)
    {
      taken.insert(s.Merged);
      top = std::max<std::int64_t>(top, s.Merged);
    }
    for (const auto& values : present)
    {
      if (!values.empty())
      {
        top = std::max(top, *values.rbegin());
      }
    }
    std::vector<std::string> items;
    for (unsigned int l = 0; l < this->Layers; ++l)
    {
      for (std::int64_t value : present[l])
      {
        if (this->ToMerged[l].count(value) != 0)
        {
          continue;
        }
        std::int64_t label = value;
        if (taken.count(value) != 0)
        {
          if (top >= MaxLabel)
          {
            throw InputError("'" + this->Path + "': no 32-bit label is left for the undeclared value " +
              std::to_string(value) + " of layer " + std::to_string(l));
          }
          label = ++top;
        }
        this->ToMerged[l][value] = static_cast<std::int32_t>(label);
        std::string item = std::to_string(value);
        if (this->Layers > 1)
        {
          item += " (layer " + std::to_string(l) +
            (label != value ? ", as label " + std::to_string(label) : std::string()) + ")";
        }
        else if (label != value)
        {
          item += " (as label " + std::to_string(label) + ")";
        }
        items.push_back(item);
      }
    }
    if (items.empty() || this->Segments.empty())
    {
      return; // without segments the caller's note says it all
    }
    std::string note = "voxel values no segment declares, meshed as unnamed labels:";
    const std::size_t shown = std::min<std::size_t>(items.size(), 10);
    for (std::size_t i = 0; i < shown; ++i)
    {
      note += (i == 0 ? " " : ", ") + items[i];
    }
    if (items.size() > shown)
    {
      note += " and " + std::to_string(items.size() - shown) + " more";
    }
    notes.push_back(note);
  }

  const std::string& Path;
  const std::vector<Segment>& Segments;
  const unsigned int Layers;
  std::vector<std::map<std::int64_t, std::int32_t>> ToMerged; ///< per layer: voxel value -> label
  std::map<std::pair<int, std::int64_t>, const Segment*> Declared;
  int Dims[3] = { 0, 0, 0 };
};

LabeledImage Read(const std::string& path)
{
  auto io = itk::NrrdImageIO::New();
  if (!io->CanReadFile(path.c_str()))
  {
    throw InputError("'" + path + "' is not a NRRD file, which a .seg.nrrd segmentation must be");
  }
  const detail::TextHeader header = detail::ReadTextHeader(path);
  detail::CheckDetachedDataFile(path, header);
  io->SetFileName(path);
  io->ReadImageInformation();
  detail::CheckHeaderSpacing(io, path);
  // A 4D file with a `list` axis comes as a 3D image whose components are the layers.
  for (unsigned int d = 3; d < io->GetNumberOfDimensions(); ++d)
  {
    if (io->GetDimensions(d) > 1)
    {
      throw InputError("'" + path + "' has " + std::to_string(io->GetNumberOfDimensions()) +
        " dimensions: expected a 3D segmentation (4D only with a first, `list` axis of layers)");
    }
  }
  const unsigned int layers = io->GetNumberOfComponents();
  detail::CheckNotTruncated(path, io, header);

  LabeledImage result;
  std::vector<Segment> segments = ReadSegments(io->GetMetaDataDictionary(), layers, path);
  if (segments.empty())
  {
    result.Notes.push_back("no segment metadata (Segment0_... keys): read as a plain label image, "
                           "without names or colours");
  }
  AssignLabels(segments, path, result.Notes);
  for (const Segment& s : segments)
  {
    MaterialInfo info;
    info.Label = s.Merged;
    info.Name = s.Name;
    info.Color = s.Color;
    result.Materials.Set(info);
  }

  Merger merger(path, segments, layers);
  using C = itk::IOComponentEnum;
  switch (io->GetComponentType())
  {
    case C::UCHAR: result.Image = merger.Run<unsigned char>(io, result.Notes); break;
    case C::CHAR: result.Image = merger.Run<signed char>(io, result.Notes); break;
    case C::USHORT: result.Image = merger.Run<unsigned short>(io, result.Notes); break;
    case C::SHORT: result.Image = merger.Run<short>(io, result.Notes); break;
    case C::UINT: result.Image = merger.Run<unsigned int>(io, result.Notes); break;
    case C::INT: result.Image = merger.Run<int>(io, result.Notes); break;
    case C::ULONG: result.Image = merger.Run<unsigned long>(io, result.Notes); break;
    case C::LONG: result.Image = merger.Run<long>(io, result.Notes); break;
    case C::ULONGLONG: result.Image = merger.Run<unsigned long long>(io, result.Notes); break;
    case C::LONGLONG: result.Image = merger.Run<long long>(io, result.Notes); break;
    case C::FLOAT: result.Image = merger.Run<float>(io, result.Notes); break;
    case C::DOUBLE: result.Image = merger.Run<double>(io, result.Notes); break;
    default:
      throw InputError("'" + path + "' has an unsupported pixel type " +
        itk::ImageIOBase::GetComponentTypeAsString(io->GetComponentType()));
  }
  return result;
}

} // namespace

bool IsSegmentationFile(const std::string& path)
{
  return EndsWith(Lower(path), ".seg.nrrd");
}

LabeledImage ReadSegmentation(const std::string& path)
{
  detail::CheckInputFile(path);
  try
  {
    return Read(path);
  }
  catch (const itk::ExceptionObject& e)
  {
    throw detail::ITKReadError(path, e);
  }
}

} // namespace io
} // namespace labelmesher
