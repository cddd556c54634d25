// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_io_VtiCheck_h
#define labelmesher_io_VtiCheck_h

/**
 * @file VtiCheck.h
 * Checks the compression headers of a VTK XML image before VTK reads its arrays. VTK 9.1's reader
 * allocates a compressed array's block table and blocks as its header announces them, so a
 * 652-byte file whose header announced 1.8e9 blocks made it take 7 GB (found by fuzzing the VTI
 * reader). Each compressed array's header must fit in the file and announce exactly the bytes
 * its extent (or NumberOfTuples) and components hold.
 */

#include <string>

namespace labelmesher
{
namespace io
{

/// Throws InputError naming `path` and the first array whose compression header is wrong. A file
/// that VTK cannot parse as XML is left to VTK's reader, which reports it.
void CheckVtiCompressionHeaders(const std::string& path);

} // namespace io
} // namespace labelmesher

#endif
