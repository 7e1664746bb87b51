// kit_json_schema SCHEMA FILE...: checks each JSON file against a JSON Schema, using the
// keywords grading/gradescope-results.schema.json needs (type, enum, properties,
// required, additionalProperties, items, minimum). Prints each violation with its path.
#include <nlohmann/json.hpp>

#include <fstream>
#include <iostream>
#include <string>

using nlohmann::json;

namespace {

bool has_type(const json& value, const std::string& type) {
  if (type == "object") return value.is_object();
  if (type == "array") return value.is_array();
  if (type == "string") return value.is_string();
  if (type == "number") return value.is_number();
  if (type == "integer")
    return value.is_number_integer() ||
           (value.is_number_float() && value.get<double>() == double(static_cast<long long>(value.get<double>())));
  if (type == "boolean") return value.is_boolean();
  if (type == "null") return value.is_null();
  return false;
}

void check(const json& schema, const json& value, const std::string& path, int& errors) {
  const auto fail = [&](const std::string& why) {
    std::cout << "  " << (path.empty() ? "(root)" : path) << ": " << why << "\n";
    ++errors;
  };
  for (const auto& [keyword, _] : schema.items())
    if (keyword != "type" && keyword != "enum" && keyword != "properties" && keyword != "required" &&
        keyword != "additionalProperties" && keyword != "items" && keyword != "minimum" && keyword[0] != '$' &&
        keyword != "title" && keyword != "description")
      fail("the schema uses '" + keyword + "', which this checker does not know");
  if (schema.contains("type")) {
    bool ok = false;
    for (const json& t : schema["type"].is_array() ? schema["type"] : json::array({schema["type"]}))
      ok = ok || has_type(value, t.get<std::string>());
    if (!ok) return fail("is not of type " + schema["type"].dump());
  }
  if (schema.contains("enum")) {
    bool ok = false;
    for (const json& e : schema["enum"]) ok = ok || e == value;
    if (!ok) fail(value.dump() + " is not one of " + schema["enum"].dump());
  }
  if (schema.contains("minimum") && value.is_number() && value.get<double>() < schema["minimum"].get<double>())
    fail(value.dump() + " is below " + schema["minimum"].dump());
  if (value.is_object()) {
    for (const json& name : schema.value("required", json::array()))
      if (!value.contains(name.get<std::string>())) fail("has no '" + name.get<std::string>() + "'");
    const json properties = schema.value("properties", json::object());
    for (const auto& [name, item] : value.items()) {
      if (properties.contains(name))
        check(properties[name], item, path + "." + name, errors);
      else if (schema.value("additionalProperties", true) == false)
        fail("has '" + name + "', which the schema does not allow");
    }
  }
  if (value.is_array() && schema.contains("items"))
    for (std::size_t i = 0; i < value.size(); ++i)
      check(schema["items"], value[i], path + "[" + std::to_string(i) + "]", errors);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::cerr << "usage: kit_json_schema SCHEMA FILE...\n";
    return 2;
  }
  const json schema = json::parse(std::ifstream(argv[1]));
  int failed = 0;
  for (int i = 2; i < argc; ++i) {
    int errors = 0;
    try {
      const json value = json::parse(std::ifstream(argv[i]));
      check(schema, value, "", errors);
    } catch (const json::exception& e) {
      std::cout << "  not JSON: " << e.what() << "\n";
      errors = 1;
    }
    std::cout << argv[i] << ": " << (errors ? "does not match the schema" : "matches the schema") << "\n";
    failed += errors > 0;
  }
  return failed == 0 ? 0 : 1;
}
