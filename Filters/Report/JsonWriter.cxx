// SPDX-License-Identifier: GPL-2.0-or-later
// A minimal streaming JSON writer for the CLI's reports.
#include "JsonWriter.h"

#include <cmath>
#include <cstdio>

namespace labelmesher
{
namespace report
{

JsonWriter::JsonWriter(std::ostream& out)
  : Out(out)
{
}

std::string JsonWriter::Escape(const std::string& text)
{
  std::string s = "\"";
  for (const unsigned char c : text)
  {
    switch (c)
    {
      case '"': s += "\\\""; break;
      case '\\': s += "\\\\"; break;
      case '\n': s += "\\n"; break;
      case '\r': s += "\\r"; break;
      case '\t': s += "\\t"; break;
      default:
        if (c < 0x20)
        {
          char buffer[8];
          std::snprintf(buffer, sizeof(buffer), "\\u%04x", c);
          s += buffer;
        }
        else
        {
          s += static_cast<char>(c);
        }
    }
  }
  return s + "\"";
}

void JsonWriter::BeforeValue()
{
  if (this->AfterKey)
  {
    this->AfterKey = false;
    return;
  }
  if (!this->HasItems.empty())
  {
    this->Out << (this->HasItems.back() ? ",\n" : "\n")
              << std::string(2 * this->HasItems.size(), ' ');
    this->HasItems.back() = true;
  }
}

JsonWriter& JsonWriter::Key(const std::string& key)
{
  this->BeforeValue();
  this->Out << Escape(key) << ": ";
  this->AfterKey = true;
  return *this;
}

JsonWriter& JsonWriter::BeginObject()
{
  this->BeforeValue();
  this->Out << '{';
  this->HasItems.push_back(false);
  return *this;
}

JsonWriter& JsonWriter::BeginArray()
{
  this->BeforeValue();
  this->Out << '[';
  this->HasItems.push_back(false);
  return *this;
}

void JsonWriter::Close(char bracket)
{
  const bool hadItems = this->HasItems.back();
  this->HasItems.pop_back();
  if (hadItems)
  {
    this->Out << '\n' << std::string(2 * this->HasItems.size(), ' ');
  }
  this->Out << bracket;
  if (this->HasItems.empty())
  {
    this->Out << '\n';
  }
}

JsonWriter& JsonWriter::EndObject()
{
  this->Close('}');
  return *this;
}

JsonWriter& JsonWriter::EndArray()
{
  this->Close(']');
  return *this;
}

JsonWriter& JsonWriter::String(const std::string& value)
{
  this->BeforeValue();
  this->Out << Escape(value);
  return *this;
}

JsonWriter& JsonWriter::Number(double value)
{
  if (!std::isfinite(value))
  {
    return this->Null();
  }
  this->BeforeValue();
  char buffer[32];
  // Round-trip precision: reports are compared against exact bounds.
  std::snprintf(buffer, sizeof(buffer), "%.17g", value);
  this->Out << buffer;
  return *this;
}

JsonWriter& JsonWriter::Integer(long long value)
{
  this->BeforeValue();
  this->Out << value;
  return *this;
}

JsonWriter& JsonWriter::Bool(bool value)
{
  this->BeforeValue();
  this->Out << (value ? "true" : "false");
  return *this;
}

JsonWriter& JsonWriter::Null()
{
  this->BeforeValue();
  this->Out << "null";
  return *this;
}

} // namespace report
} // namespace labelmesher
