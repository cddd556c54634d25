// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_report_JsonWriter_h
#define labelmesher_report_JsonWriter_h

/**
 * @file JsonWriter.h
 * A minimal streaming JSON writer (objects, arrays, strings, numbers, booleans,
 * null) with two-space indentation; non-finite numbers are written as null.
 */

#include <ostream>
#include <string>
#include <vector>

namespace labelmesher
{
namespace report
{

class JsonWriter
{
public:
  explicit JsonWriter(std::ostream& out);
  JsonWriter& BeginObject();
  JsonWriter& EndObject();
  JsonWriter& BeginArray();
  JsonWriter& EndArray();
  /// The key of the next value inside an object.
  JsonWriter& Key(const std::string& key);
  JsonWriter& String(const std::string& value);
  JsonWriter& Number(double value);
  JsonWriter& Integer(long long value);
  JsonWriter& Bool(bool value);
  JsonWriter& Null();

  static std::string Escape(const std::string& text);

private:
  void BeforeValue();
  void Close(char bracket);

  std::ostream& Out;
  std::vector<bool> HasItems; ///< one entry per open container
  bool AfterKey = false;
};

} // namespace report
} // namespace labelmesher

#endif
