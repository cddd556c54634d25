// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_io_ColorTableReader_h
#define labelmesher_io_ColorTableReader_h

/**
 * @file ColorTableReader.h
 * Reads the names and colours of labels from a text colour table (the CLI's --labels),
 * in either of the two forms label images usually come with, told apart line
 * by line (`#` comments and blank lines are skipped):
 *
 *   ITK-SNAP label description:  IDX -R- -G- -B- -A-- VIS MSH-VIS "LABEL NAME"
 *       e.g.     1   255    0    0        1  1  1    "Liver tissue"
 *   3D Slicer colour table (.ctbl, .txt):  IDX NAME R G B A
 *       e.g.  1 liver 221 130 101 255
 *
 * RGB are integers in [0, 255] (stored in [0, 1]); alpha and visibility are
 * checked but not kept. A label is an integer in [0, 2^31).
 */

#include "MaterialTable.h"

#include <string>

namespace labelmesher
{
namespace io
{

/// Throws InputError (ImageReader.h), naming the file and line.
MaterialTable ReadColorTable(const std::string& path);

} // namespace io
} // namespace labelmesher

#endif
