// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_io_StringUtilities_h
#define labelmesher_io_StringUtilities_h

/**
 * @file StringUtilities.h
 * The string helpers the readers (and the CLI) need for file names and headers.
 */

#include <algorithm>
#include <cctype>
#include <string>

namespace labelmesher
{
namespace io
{

/// True when `text` ends with `suffix` (case-sensitive).
inline bool EndsWith(const std::string& text, const std::string& suffix)
{
  return text.size() >= suffix.size() &&
    text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

/// `text` without the blanks (spaces, tabs, line ends) around it.
inline std::string Trim(const std::string& text)
{
  const auto first = text.find_first_not_of(" \t\r\n");
  const auto last = text.find_last_not_of(" \t\r\n");
  return first == std::string::npos ? std::string() : text.substr(first, last - first + 1);
}

/// ASCII lower case.
inline std::string Lower(std::string text)
{
  std::transform(text.begin(), text.end(), text.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

} // namespace io
} // namespace labelmesher

#endif
