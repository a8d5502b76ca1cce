#pragma once
// Strict reading of a JSON file: every key must be one the reader asks for, every value of the expected
// type; errors name the file and the value's path, e.g. "scenes/x.json: objects[2].transfrom: unknown key".
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

namespace parashade::detail {

class JsonObject;

// One value and where it is. Holds references into the document, which must outlive it.
class JsonValue {
 public:
  JsonValue(const nlohmann::json& value, std::string path, const std::string& file)
      : value_(&value), path_(std::move(path)), file_(&file) {}

  [[noreturn]] void fail(const std::string& reason) const;
  const std::string& path() const { return path_; }
  const std::string& file() const { return *file_; }
  std::string dump() const { return value_->dump(); }

  std::string string() const;
  bool boolean() const;
  double number() const;                                  // finite
  int integer(int lo, int hi) const;                      // lo <= value <= hi
  long long any_integer() const;                          // an integer of any size, clamped to long long
  glm::vec3 vec3() const;                                 // [x, y, z], finite
  glm::vec3 color() const;                                // [r, g, b], finite and >= 0
  std::vector<JsonValue> array(std::size_t min_size = 0) const;
  JsonObject object() const;
  // One of the given strings.
  std::string choice(const std::vector<std::string>& options) const;
  bool is_number() const { return value_->is_number(); }
  bool is_string() const { return value_->is_string(); }

 private:
  std::string child_path(std::size_t index) const { return path_ + "[" + std::to_string(index) + "]"; }

  const nlohmann::json* value_;
  std::string path_;
  const std::string* file_;
};

// The members of one object, taken by key; finish() rejects the keys nobody took.
class JsonObject {
 public:
  explicit JsonObject(const JsonValue& self, const nlohmann::json& value) : self_(self), value_(&value) {}

  std::optional<JsonValue> optional(const std::string& key);
  JsonValue required(const std::string& key);
  bool has(const std::string& key) const { return value_->contains(key); }
  // Every member, in key order (materials by name).
  std::vector<std::pair<std::string, JsonValue>> members();
  // Throws for the first key not taken, listing the keys this object accepts.
  void finish() const;
  const JsonValue& self() const { return self_; }

 private:
  JsonValue member(const std::string& key) const;

  JsonValue self_;
  const nlohmann::json* value_;
  std::vector<std::string> taken_;
};

// Parses a whole file; InputError for an unreadable file, malformed JSON (with line and column) or a
// key that appears twice in one object (the JSON library would keep only the last).
nlohmann::json parse_json_file(const std::filesystem::path& path);

}  // namespace parashade::detail
