// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_io_SafeFile_h
#define labelmesher_io_SafeFile_h

/**
 * @file SafeFile.h
 * Files written whole or not at all. Bytes go to a temporary file beside the
 * target (same folder, so the final rename is atomic); Commit() flushes,
 * fsyncs, closes, checks every step and renames. A failure anywhere throws
 * WriteError with one line naming the target and the reason (the system's
 * message, e.g. "No space left on device"), and the temporary is removed, so
 * a half-written mesh never appears under the target's name.
 *
 * A target that is a character device or a pipe (/dev/null, /dev/full), or any
 * name under /dev or /proc (/dev/stdout, also when the shell redirected it to
 * a file), is written directly (appended), checked the same way: it cannot be
 * replaced.
 * A target that is a symbolic link is written through: the file it leads to is
 * replaced (its temporary beside that file), and the link stays a link.
 */

#include <memory>
#include <ostream>
#include <stdexcept>
#include <string>

namespace labelmesher
{
namespace io
{

/// A file that could not be written; the message is one line.
struct WriteError : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

/// The file a write to `target` lands in: `target` itself, or the end of the
/// chain of symbolic links it names (which need not exist yet). Throws
/// WriteError for a chain of more than 40 links (a loop).
std::string WrittenPath(const std::string& target);

/// Throws WriteError unless `target` can be written: its folder exists and is
/// a folder, it is not itself a folder, and a file can be created beside it
/// (tried, then removed). Call before long work so a bad path fails first.
void CheckOutputPath(const std::string& target);

class SafeFile
{
public:
  /// Creates the temporary (throws WriteError when it cannot).
  explicit SafeFile(const std::string& target);
  /// Removes the temporary unless Commit() succeeded.
  ~SafeFile();
  SafeFile(const SafeFile&) = delete;
  SafeFile& operator=(const SafeFile&) = delete;

  /// A stream onto the temporary (or the device); its errors are kept and
  /// reported by Commit().
  std::ostream& Stream();
  /// Throws WriteError naming the target with `reason`, after cleaning up.
  [[noreturn]] void Fail(const std::string& reason);
  /// Completes the file under the target's name; throws WriteError.
  void Commit();
  const std::string& Target() const { return this->TargetPath; }
  /// Where the bytes land: WrittenPath(Target()).
  const std::string& DestinationPath() const { return this->Destination; }
  /// The target is a device or a pipe, written directly (nothing to take back).
  bool WritesDevice() const { return this->Device; }

private:
  class Buffer;
  std::string TargetPath;
  std::string Destination; ///< WrittenPath(TargetPath): renamed onto
  std::string Temporary; ///< empty when the target is a device written directly
  bool Device = false;
  bool Committed = false;
  std::unique_ptr<Buffer> Buf;
  std::unique_ptr<std::ostream> Out;
};

} // namespace io
} // namespace labelmesher

#endif
