// A small strict JSON reader (RFC 8259) for shape documents: no comments, no
// trailing commas, no NaN/Infinity, no duplicate keys, nesting limited to
// kMaxJsonDepth. Errors are Error(InvalidArgument) "line L, column C: ...".
// Every value remembers where it starts, so later checks can say where.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace curvetext::json {

inline constexpr int kMaxJsonDepth = 64;

struct Value {
  enum class Type { Null, Bool, Number, String, Array, Object };
  Type type = Type::Null;
  bool boolean = false;
  double number = 0.0;
  std::string string;
  std::vector<Value> array;
  std::vector<std::pair<std::string, Value>> object;  // in document order
  int line = 1;
  int column = 1;

  // Declared here, defined where Value is complete: `object` holds pairs of
  // Value, which clang (with libstdc++) refuses to destroy or copy inside
  // Value's own definition.
  Value();
  Value(const Value&);
  Value(Value&&) noexcept;
  Value& operator=(const Value&);
  Value& operator=(Value&&) noexcept;
  ~Value();

  // Member by key, or nullptr.
  const Value* find(std::string_view key) const;
  // "line L, column C"
  std::string where() const;
};

const char* type_name(Value::Type type);

Value parse(std::string_view text);

}  // namespace curvetext::json
