// SPDX-License-Identifier: GPL-2.0-or-later
// Checked, atomic file output: a POSIX-descriptor stream buffer that keeps the
// first errno, and the temporary-then-rename protocol around it.
#include "SafeFile.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <streambuf>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace labelmesher
{
namespace io
{
namespace
{

namespace fs = std::filesystem;

std::string Quoted(const std::string& path)
{
  return "'" + path + "'";
}

std::string ParentFolder(const std::string& target)
{
  const fs::path parent = fs::path(target).parent_path();
  return parent.empty() ? std::string(".") : parent.string();
}

/// mkstemp beside `target`; -1 with errno on failure.
int CreateTemporaryBeside(const std::string& target, std::string& name)
{
  const fs::path t(target);
  std::string pattern = (t.has_parent_path() ? t.parent_path().string() + "/" : std::string()) + "." +
    t.filename().string() + ".labelmesher-XXXXXX";
  std::vector<char> buffer(pattern.begin(), pattern.end());
  buffer.push_back('\0');
  const int fd = ::mkstemp(buffer.data());
  if (fd >= 0)
  {
    name = buffer.data();
    // mkstemp makes 0600; the finished file gets the usual 0666 & ~umask.
    const mode_t mask = ::umask(0);
    ::umask(mask);
    ::fchmod(fd, 0666 & ~mask);
  }
  return fd;
}

bool IsDevice(const std::string& target)
{
  struct stat st;
  return ::stat(target.c_str(), &st) == 0 && (S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode) || S_ISSOCK(st.st_mode));
}

/// Written in place, not through a temporary: a device or a pipe, and any name
/// under /dev or /proc (/dev/stdout redirected to a file leads, through
/// /proc/self/fd/1, to that file, which the shell holds open: replacing it
/// would lose what is written).
bool WrittenDirectly(const std::string& target)
{
  return IsDevice(target) || target.rfind("/dev/", 0) == 0 || target.rfind("/proc/", 0) == 0;
}

} // namespace

/// Writes through ::write in 1 MiB chunks; remembers the first error.
class SafeFile::Buffer : public std::streambuf
{
public:
  explicit Buffer(int fd)
    : Fd(fd)
    , Data(1 << 20)
  {
    this->setp(this->Data.data(), this->Data.data() + this->Data.size());
  }
  int Error = 0; ///< first errno, 0 when none
  int Fd;

  bool Drain()
  {
    const char* at = this->pbase();
    std::size_t left = static_cast<std::size_t>(this->pptr() - this->pbase());
    while (left > 0 && this->Error == 0)
    {
      const ssize_t n = ::write(this->Fd, at, left);
      if (n < 0)
      {
        if (errno == EINTR)
        {
          continue;
        }
        this->Error = errno;
        break;
      }
      at += n;
      left -= static_cast<std::size_t>(n);
    }
    this->setp(this->Data.data(), this->Data.data() + this->Data.size());
    return this->Error == 0;
  }

protected:
  int_type overflow(int_type c) override
  {
    if (!this->Drain())
    {
      return traits_type::eof();
    }
    if (!traits_type::eq_int_type(c, traits_type::eof()))
    {
      *this->pptr() = traits_type::to_char_type(c);
      this->pbump(1);
    }
    return traits_type::not_eof(c);
  }
  int sync() override { return this->Drain() ? 0 : -1; }

private:
  std::vector<char> Data;
};

std::string WrittenPath(const std::string& target)
{
  // /dev/stdout's link reads "pipe:[N]" or names the file the shell redirected to: written
  // directly, not resolved.
  if (WrittenDirectly(target))
  {
    return target;
  }
  fs::path at(target);
  for (int links = 0; links <= 40; ++links)
  {
    std::error_code ec;
    if (!fs::is_symlink(fs::symlink_status(at, ec)))
    {
      return at.string();
    }
    const fs::path next = fs::read_symlink(at, ec);
    if (ec)
    {
      throw WriteError("cannot write " + Quoted(target) + ": " + ec.message());
    }
    at = next.is_absolute() ? next : at.parent_path() / next;
  }
  throw WriteError("cannot write " + Quoted(target) + ": too many levels of symbolic links");
}

void CheckOutputPath(const std::string& requested)
{
  if (requested.empty())
  {
    throw WriteError("empty output file name");
  }
  // Through a link, the folder that must exist is its target's; messages name what was asked for.
  const std::string target = WrittenPath(requested);
  const std::string named = Quoted(requested);
  std::error_code ec;
  const fs::file_status status = fs::status(target, ec);
  if (fs::is_directory(status))
  {
    throw WriteError("cannot write " + named + ": it is a folder");
  }
  if (WrittenDirectly(target))
  {
    if (::access(target.c_str(), W_OK) != 0)
    {
      throw WriteError("cannot write " + named + ": " + std::strerror(errno));
    }
    return;
  }
  const std::string folder = ParentFolder(target);
  const fs::file_status folderStatus = fs::status(folder, ec);
  if (!fs::exists(folderStatus))
  {
    throw WriteError("cannot write " + named + ": folder " + Quoted(folder) + " does not exist");
  }
  if (!fs::is_directory(folderStatus))
  {
    throw WriteError("cannot write " + named + ": " + Quoted(folder) + " is not a folder");
  }
  std::string probe;
  const int fd = CreateTemporaryBeside(target, probe);
  if (fd < 0)
  {
    throw WriteError("cannot write " + named + ": " + std::strerror(errno));
  }
  ::close(fd);
  ::unlink(probe.c_str());
}

SafeFile::SafeFile(const std::string& target)
  : TargetPath(target)
  , Destination(WrittenPath(target))
{
  CheckOutputPath(target);
  int fd = -1;
  if (WrittenDirectly(this->Destination))
  {
    this->Device = true;
    // Appended: /dev/stdout redirected with >> keeps what the file held.
    fd = ::open(this->Destination.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
  }
  else
  {
    fd = CreateTemporaryBeside(this->Destination, this->Temporary);
  }
  if (fd < 0)
  {
    throw WriteError("cannot write " + Quoted(target) + ": " + std::strerror(errno));
  }
  this->Buf = std::make_unique<Buffer>(fd);
}

SafeFile::~SafeFile()
{
  if (this->Buf && this->Buf->Fd >= 0)
  {
    ::close(this->Buf->Fd);
  }
  if (!this->Committed && !this->Temporary.empty())
  {
    ::unlink(this->Temporary.c_str());
  }
}

std::ostream& SafeFile::Stream()
{
  if (!this->Out)
  {
    this->Out = std::make_unique<std::ostream>(this->Buf.get());
  }
  return *this->Out;
}

void SafeFile::Fail(const std::string& reason)
{
  if (this->Buf->Fd >= 0)
  {
    ::close(this->Buf->Fd);
    this->Buf->Fd = -1;
  }
  if (!this->Temporary.empty())
  {
    ::unlink(this->Temporary.c_str());
  }
  throw WriteError("cannot write " + Quoted(this->TargetPath) + ": " + reason);
}

void SafeFile::Commit()
{
  if (this->Out)
  {
    this->Out->flush();
  }
  this->Buf->Drain();
  if (this->Buf->Error == 0 && !this->Device && ::fsync(this->Buf->Fd) != 0)
  {
    this->Buf->Error = errno;
  }
  const int fd = this->Buf->Fd;
  this->Buf->Fd = -1;
  if (::close(fd) != 0 && this->Buf->Error == 0 && !this->Device)
  {
    this->Buf->Error = errno;
  }
  if (this->Buf->Error != 0)
  {
    this->Fail(std::strerror(this->Buf->Error));
  }
  if (this->Out && this->Out->bad())
  {
    this->Fail("the stream failed");
  }
  if (!this->Device)
  {
    if (::rename(this->Temporary.c_str(), this->Destination.c_str()) != 0)
    {
      this->Fail(std::strerror(errno));
    }
  }
  this->Committed = true;
}

} // namespace io
} // namespace labelmesher
