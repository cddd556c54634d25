// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_io_PngCheck_h
#define labelmesher_io_PngCheck_h

/**
 * @file PngCheck.h
 * Checks a PNG's structure before libpng sees it: on a malformed file libpng
 * prints to stderr and then VTK's reader crashes (ITK's aborts). The check
 * walks the chunks (lengths, CRCs, IHDR first, IEND last), validates the
 * header fields, inflates the image data and requires exactly the bytes the
 * header implies, with a valid filter byte on every row. A file that passes
 * gives libpng nothing to complain about.
 */

#include <string>

namespace labelmesher
{
namespace io
{

/// Throws InputError naming `path` and the first problem found.
void CheckPngStructure(const std::string& path);

} // namespace io
} // namespace labelmesher

#endif
