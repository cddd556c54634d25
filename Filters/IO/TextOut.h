// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_io_TextOut_h
#define labelmesher_io_TextOut_h

/**
 * @file TextOut.h
 * Fast number formatting for the text mesh formats: std::to_chars into a
 * buffer handed to the stream a megabyte at a time. Reals are written in the
 * shortest form that reads back to the same double, so coordinates match the
 * .vtu exactly.
 */

#include <charconv>
#include <cstdint>
#include <ostream>
#include <string>

namespace labelmesher
{
namespace io
{

class TextOut
{
public:
  explicit TextOut(std::ostream& out)
    : Out(out)
  {
    this->Buffer.reserve(Capacity + 64);
  }
  ~TextOut() { this->Flush(); }
  TextOut(const TextOut&) = delete;
  TextOut& operator=(const TextOut&) = delete;

  TextOut& Int(std::int64_t v) { return this->Number(v); }
  TextOut& Real(double v) { return this->Number(v); }
  TextOut& Text(const std::string& s)
  {
    this->Buffer += s;
    return this->Check();
  }
  TextOut& Char(char c)
  {
    this->Buffer += c;
    return this->Check();
  }
  void Flush()
  {
    this->Out.write(this->Buffer.data(), static_cast<std::streamsize>(this->Buffer.size()));
    this->Buffer.clear();
  }

private:
  static constexpr std::size_t Capacity = 1 << 20;

  template <typename T>
  TextOut& Number(T v)
  {
    char digits[32];
    const auto end = std::to_chars(digits, digits + sizeof digits, v).ptr;
    this->Buffer.append(digits, end);
    return this->Check();
  }
  TextOut& Check()
  {
    if (this->Buffer.size() >= Capacity)
    {
      this->Flush();
    }
    return *this;
  }

  std::ostream& Out;
  std::string Buffer;
};

} // namespace io
} // namespace labelmesher

#endif
