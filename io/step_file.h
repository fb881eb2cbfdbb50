// SPDX-License-Identifier: GPL-3.0-or-later
// STEP physical files (ISO 10303-21), the text form of IFC: writing instances one by one with
// deterministic numbers and values, and reading a file into its instances.
//
// The reader keeps each instance's parameters as a tree of values (references, numbers,
// strings, enumerations, lists, typed values such as IFCLENGTHMEASURE(2.), `$` and `*`); what
// the entities mean is the IFC importer's business (import/ifc_import.h).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "core/error.h"

namespace roomcad::step {

/// Appends `x` as a STEP real: the shortest decimal that reads back to exactly `x`, always with
/// a decimal point ("3.", "0.25", "1.E-05"); -0 is written "0.". @pre std::isfinite(x).
void append_real(std::string& out, double x);

/// Appends `text` (UTF-8) as a STEP string: quoted, `'` and `\` doubled, characters outside
/// printable ASCII as \X2\hhhh\X0\ (UTF-16, ISO 10303-21 8.3.2.2 and 2.3).
void append_string(std::string& out, std::string_view text);

/// Builds the DATA section: instances numbered #1, #2, ... in the order they are added.
class Writer {
 public:
  /// Adds `#n=TYPE(parameters);`. @param type upper case entity name; @param parameters the
  /// text between the parentheses. @return n. O(length).
  int add(std::string_view type, std::string_view parameters);
  /// @return the whole file: header (schema, file name, a fixed time stamp so that the same
  ///   content gives the same bytes), the instances, the end. O(size).
  [[nodiscard]] std::string finish(std::string_view file_name, std::string_view schema,
                                   std::string_view description) const;

 private:
  std::string data_;
  int next_ = 1;
};

/// @return "#n".
[[nodiscard]] std::string ref(int n);

/// One parameter value of an instance.
struct Value {
  enum class Kind : std::uint8_t {
    null,
    derived,
    ref,
    integer,
    real,
    string,
    enumeration,
    list,
    typed
  };
  Kind kind = Kind::null;
  double number = 0.0;   ///< integer and real
  std::uint32_t id = 0;  ///< ref: the instance number
  std::string text{};  ///< string (decoded to UTF-8), enumeration (without dots), typed: type name
  std::vector<Value> items{};  ///< list items; typed: its one parameter

  [[nodiscard]] bool is_number() const { return kind == Kind::integer || kind == Kind::real; }
};

/// One instance: `#id=TYPE(parameters)`; a complex instance `#id=(A(..)B(..))` keeps its parts'
/// parameters one after the other and the type of its first part.
struct Instance {
  std::uint32_t id = 0;
  std::string type{};  ///< upper case
  std::vector<Value> parameters{};
};

/// A read file: its schema and its instances by number.
struct File {
  std::string schema{};  ///< the first name of FILE_SCHEMA, upper case ("IFC4", "IFC2X3")
  std::vector<Instance> instances{};
  std::unordered_map<std::uint32_t, std::size_t> index{};  ///< instance number -> position

  /// @return the instance numbered `id`, or nullptr. O(1).
  [[nodiscard]] const Instance* find(std::uint32_t id) const;
};

/// Most instances a file may hold (a 1 GB model holds about ten million).
inline constexpr std::size_t kMaxInstances = 50'000'000;

/// Parses the text of a STEP physical file.
/// @param name the file's name for messages.
/// @return the file, or a parse_error naming the file, the line and what was expected (not
///   ISO-10303-21, an unterminated string or list, a duplicate instance number, nesting deeper
///   than 64), or too_large past kMaxInstances. O(n) in the text's length.
[[nodiscard]] Result<File> parse(std::string_view text, std::string_view name);

}  // namespace roomcad::step
