// reference/json.hpp — a small JSON reader, enough for the sidecar files.
//
// Values keep the object's key order (the sidecar writes a fixed order and a
// reader that keeps it makes error messages predictable).  Numbers are
// doubles; "null" reads as a null value (the sidecar writes non-finite
// floats as null).  Errors throw ts::Error "json: <what> at line L column C".
#pragma once
#include <string>
#include <utility>
#include <vector>

namespace ref::json {
struct Value {
  enum class Type { Null, Bool, Number, String, Array, Object };
  Type type = Type::Null;
  bool boolean = false;
  double number = 0;
  std::string string;
  std::vector<Value> array;
  std::vector<std::pair<std::string, Value>> object;

  bool isNull() const { return type == Type::Null; }
  bool isNumber() const { return type == Type::Number; }
  bool isString() const { return type == Type::String; }
  bool isArray() const { return type == Type::Array; }
  bool isObject() const { return type == Type::Object; }
  // Member lookup: nullptr if absent (or not an object).
  const Value* find(const std::string& key) const;
  // Member lookup that throws ts::Error "<path>: missing key '<key>'".
  const Value& at(const std::string& key) const;
  // Typed accessors; throw ts::Error naming the expected type.
  double asNumber() const;
  const std::string& asString() const;
  bool asBool() const;
  const std::vector<Value>& asArray() const;
};

// Parses a whole document (trailing non-space characters are an error).
Value parse(const std::string& text);
const char* typeName(Value::Type t);
}  // namespace ref::json
