#include "common/protocol/report.h"
#include "common/text.h"

#include <nlohmann/json.hpp>

#include <stdexcept>
#include <type_traits>

namespace labkit::report {

using nlohmann::json;

namespace {

template <class T> constexpr bool is_optional = false;
template <class T> constexpr bool is_optional<std::optional<T>> = true;
template <class T> constexpr bool is_list = false;
template <class T> constexpr bool is_list<std::vector<T>> = true;
template <class T> constexpr bool is_record = std::is_class_v<T> && !std::is_same_v<T, std::string>;

// A value as JSON: a record (a struct with fields()) as an object, keyed by its fields.
template <class T> json write(const T& value) {
  if constexpr (is_optional<T>) {
    return value ? write(*value) : json(nullptr);
  } else if constexpr (is_list<T>) {
    json list = json::array();
    for (const auto& item : value) list.push_back(write(item));
    return list;
  } else if constexpr (is_record<T>) {
    json object = json::object();
    fields(const_cast<T&>(value), [&](const char* key, const auto& member) { object[key] = write(member); });
    return object;
  } else {
    return json(value);
  }
}

// `json` into `out`, or an error naming the place (`where`: "query 0's \"failure\"") that
// is missing, misspelt or of another type.
template <class T> void read(const json& j, T& out, const std::string& where) {
  if constexpr (is_optional<T>) {
    if (j.is_null()) return out.reset();
    read(j, out.emplace(), where);
  } else if constexpr (is_list<T>) {
    if (!j.is_array()) throw std::runtime_error(where + " is not a list (" + j.type_name() + ")");
    out.resize(j.size());
    for (std::size_t i = 0; i < j.size(); ++i) read(j[i], out[i], where + "[" + std::to_string(i) + "]");
  } else if constexpr (is_record<T>) {
    if (!j.is_object()) throw std::runtime_error(where + " is not an object");
    fields(out, [&](const char* key, auto& member) {
      const auto it = j.find(key);
      if (it == j.end()) throw std::runtime_error(where + " has no \"" + key + "\"");
      read(*it, member, where + "'s \"" + key + "\"");
    });
  } else {
    try {
      out = j.get<T>();
    } catch (const json::exception&) {
      throw std::runtime_error(where + " has the wrong type (" + j.type_name() + ")");
    }
  }
}

}  // namespace

json to_json(const Step& step) { return write(step); }

Step step_from_json(const json& j) {
  Step step;
  read(j, step, "the report");
  return step;
}

std::string format(const Failure& f, const std::string& query, const std::string& indent) {
  const std::string under = indent + std::string(10, ' ');
  std::string text = indent + "query     " + query + (f.title.empty() ? "" : ", " + f.title);
  if (f.shrinks > 0) text += " (shrunk " + std::to_string(f.shrinks) + " times)";
  text += "\n" + indent + "input     " + labkit::indent(f.input, under);
  text += "\n" + indent + "expected  " + labkit::indent(f.expected, under);
  text += "\n" + indent + "got       " + labkit::indent(f.got, under);
  text += "\n" + indent + "why       " + labkit::indent(f.why, under) + "\n";
  return text;
}

}  // namespace labkit::report
