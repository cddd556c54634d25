// SPDX-License-Identifier: GPL-2.0-or-later
// Reads ITK-SNAP label descriptions and 3D Slicer colour tables (--labels) into a MaterialTable.
#include "ColorTableReader.h"

#include "ImageReader.h"
#include "StringUtilities.h"

#include <array>
#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

namespace labelmesher
{
namespace io
{
namespace
{

constexpr long long MaxLabel = 2147483647; // 2^31 - 1

std::vector<std::string> Words(const std::string& text)
{
  std::istringstream in(text);
  std::vector<std::string> words;
  for (std::string w; in >> w;)
  {
    words.push_back(w);
  }
  return words;
}

bool ParseInteger(const std::string& text, long long low, long long high, long long& value)
{
  char* end = nullptr;
  errno = 0;
  const long long v = std::strtoll(text.c_str(), &end, 10);
  if (text.empty() || errno != 0 || *end != '\0' || v < low || v > high)
  {
    return false;
  }
  value = v;
  return true;
}

/// One line's trouble; Read adds the file and line number.
struct LineError
{
  std::string Message;
};

std::int32_t ParseLabel(const std::string& word)
{
  long long label = 0;
  if (!ParseInteger(word, 0, MaxLabel, label))
  {
    throw LineError{ "label '" + word + "' is not an integer in [0, 2147483647]" };
  }
  return static_cast<std::int32_t>(label);
}

/// Three words, each an integer in [0, 255].
std::array<double, 3> ParseRGB(const std::vector<std::string>& words, std::size_t first)
{
  std::array<double, 3> color{};
  for (int c = 0; c < 3; ++c)
  {
    long long v = 0;
    if (!ParseInteger(words[first + c], 0, 255, v))
    {
      throw LineError{ std::string("colour component ") + "RGB"[c] + " '" + words[first + c] +
        "' is not an integer in [0, 255]" };
    }
    color[c] = static_cast<double>(v) / 255.0;
  }
  return color;
}

/// ITK-SNAP: IDX R G B A VIS MSH "NAME" (the name may hold spaces, even quotes).
MaterialInfo ParseITKSNAP(const std::string& line)
{
  const std::size_t open = line.find('"');
  const std::size_t close = line.rfind('"');
  const std::vector<std::string> words = Words(line.substr(0, open));
  if (words.size() != 7 || close == open || !Trim(line.substr(close + 1)).empty())
  {
    throw LineError{ "" };
  }
  MaterialInfo info;
  info.Label = ParseLabel(words[0]);
  info.Color = ParseRGB(words, 1);
  char* end = nullptr;
  const double alpha = std::strtod(words[4].c_str(), &end);
  if (*end != '\0' || !(alpha >= 0.0 && alpha <= 1.0))
  {
    throw LineError{ "opacity '" + words[4] + "' is not a number in [0, 1]" };
  }
  for (int w = 5; w < 7; ++w)
  {
    if (words[w] != "0" && words[w] != "1")
    {
      throw LineError{ std::string(w == 5 ? "visibility" : "mesh visibility") + " '" + words[w] +
        "' is not 0 or 1" };
    }
  }
  info.Name = line.substr(open + 1, close - open - 1);
  return info;
}

/// 3D Slicer: IDX NAME R G B A (the name without spaces).
MaterialInfo ParseSlicer(const std::string& line)
{
  const std::vector<std::string> words = Words(line);
  if (words.size() != 6)
  {
    throw LineError{ "" };
  }
  MaterialInfo info;
  info.Label = ParseLabel(words[0]);
  info.Name = words[1];
  info.Color = ParseRGB(words, 2);
  long long alpha = 0;
  if (!ParseInteger(words[5], 0, 255, alpha))
  {
    throw LineError{ "opacity '" + words[5] + "' is not an integer in [0, 255]" };
  }
  return info;
}

} // namespace

MaterialTable ReadColorTable(const std::string& path)
{
  std::error_code ec;
  if (!std::filesystem::exists(path, ec))
  {
    throw InputError("cannot read '" + path + "': no such file");
  }
  if (!std::filesystem::is_regular_file(path, ec))
  {
    throw InputError("cannot read '" + path + "': not a regular file");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    throw InputError("cannot read '" + path + "': " + std::strerror(errno));
  }

  MaterialTable table;
  std::map<std::int32_t, int> firstLine;
  std::string raw;
  for (int number = 1; std::getline(in, raw); ++number)
  {
    if (number == 1 && raw.rfind("\xEF\xBB\xBF", 0) == 0)
    {
      raw.erase(0, 3); // UTF-8 byte-order mark
    }
    const std::string line = Trim(raw);
    if (line.empty() || line[0] == '#')
    {
      continue;
    }
    const std::string where = "'" + path + "' line " + std::to_string(number) + ": ";
    MaterialInfo info;
    try
    {
      // Only ITK-SNAP quotes its names.
      info = line.find('"') != std::string::npos ? ParseITKSNAP(line) : ParseSlicer(line);
    }
    catch (const LineError& e)
    {
      throw InputError(where +
        (e.Message.empty() ? "expected an ITK-SNAP label line (IDX R G B A VIS MSH \"NAME\") or a "
                             "3D Slicer colour-table line (IDX NAME R G B A)"
                           : e.Message));
    }
    auto seen = firstLine.emplace(info.Label, number);
    if (!seen.second)
    {
      throw InputError(where + "label " + std::to_string(info.Label) + " given twice (first on line " +
        std::to_string(seen.first->second) + ")");
    }
    table.Set(info);
  }
  if (in.bad())
  {
    throw InputError("cannot read '" + path + "': " + std::strerror(errno));
  }
  if (table.Empty())
  {
    throw InputError("'" + path + "' holds no labels: expected ITK-SNAP label lines or a 3D Slicer "
                     "colour table");
  }
  return table;
}

} // namespace io
} // namespace labelmesher
