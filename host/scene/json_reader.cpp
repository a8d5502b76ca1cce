#include "json_reader.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>

#include "input_file.hpp"
#include "parashade/errors.hpp"

namespace parashade::detail {

namespace {

std::string type_name(const nlohmann::json& v) {
  if (v.is_number_integer() || v.is_number_float()) return "a number";
  if (v.is_string()) return "a string";
  if (v.is_boolean()) return "true/false";
  if (v.is_array()) return "an array";
  if (v.is_object()) return "an object";
  return "null";
}

}  // namespace

void JsonValue::fail(const std::string& reason) const {
  throw InputError(*file_ + ": " + (path_.empty() ? "" : path_ + ": ") + reason);
}

std::string JsonValue::string() const {
  if (!value_->is_string()) fail("expected a string, got " + type_name(*value_));
  return value_->get<std::string>();
}

bool JsonValue::boolean() const {
  if (!value_->is_boolean()) fail("expected true or false, got " + type_name(*value_));
  return value_->get<bool>();
}

double JsonValue::number() const {
  if (!value_->is_number()) fail("expected a number, got " + type_name(*value_));
  const double v = value_->get<double>();
  // Scenes are float: 1e300 is finite here but would become inf in the renderer.
  if (!(std::abs(v) <= double(std::numeric_limits<float>::max())))
    fail("must be finite and within single precision, |x| <= 3.4e38 (got " + dump() + ")");
  return v;
}

int JsonValue::integer(int lo, int hi) const {
  if (!value_->is_number_integer()) fail("expected an integer, got " + (value_->is_number() ? dump() : type_name(*value_)));
  const auto v = value_->get<long long>();
  if (v < lo || v > hi)
    fail("must be in " + std::to_string(lo) + ".." + std::to_string(hi) + " (got " + std::to_string(v) + ")");
  return static_cast<int>(v);
}

long long JsonValue::any_integer() const {
  if (!value_->is_number_integer()) fail("expected an integer, got " + (value_->is_number() ? dump() : type_name(*value_)));
  if (value_->is_number_unsigned() && value_->get<unsigned long long>() > 9223372036854775807ULL)
    return 9223372036854775807LL;
  return value_->get<long long>();
}

glm::vec3 JsonValue::vec3() const {
  if (!value_->is_array() || value_->size() != 3) fail("expected [x, y, z], got " + (value_->is_array() ? dump() : type_name(*value_)));
  glm::vec3 v;
  for (int i = 0; i < 3; ++i) v[i] = float(JsonValue((*value_)[i], child_path(i), *file_).number());
  return v;
}

glm::vec3 JsonValue::color() const {
  if (!value_->is_array() || value_->size() != 3) fail("expected [r, g, b], got " + (value_->is_array() ? dump() : type_name(*value_)));
  glm::vec3 c;
  for (int i = 0; i < 3; ++i) {
    const JsonValue channel((*value_)[i], child_path(i), *file_);
    c[i] = float(channel.number());
    if (c[i] < 0.0f) channel.fail("a colour channel must be >= 0 (got " + channel.dump() + ")");
  }
  return c;
}

std::vector<JsonValue> JsonValue::array(std::size_t min_size) const {
  if (!value_->is_array()) fail("expected an array, got " + type_name(*value_));
  if (value_->size() < min_size) fail("needs at least " + std::to_string(min_size) + " element(s)");
  std::vector<JsonValue> items;
  for (std::size_t i = 0; i < value_->size(); ++i) items.emplace_back((*value_)[i], child_path(i), *file_);
  return items;
}

JsonObject JsonValue::object() const {
  if (!value_->is_object()) fail("expected an object, got " + type_name(*value_));
  return JsonObject(*this, *value_);
}

std::string JsonValue::choice(const std::vector<std::string>& options) const {
  const std::string s = string();
  if (std::find(options.begin(), options.end(), s) != options.end()) return s;
  std::string list;
  for (const std::string& o : options) list += (list.empty() ? "" : ", ") + o;
  fail("'" + s + "' is not one of: " + list);
}

JsonValue JsonObject::member(const std::string& key) const {
  const std::string& parent = self_.path();
  return JsonValue(value_->at(key), parent.empty() ? key : parent + "." + key, self_.file());
}

std::optional<JsonValue> JsonObject::optional(const std::string& key) {
  taken_.push_back(key);
  if (!value_->contains(key)) return std::nullopt;
  return member(key);
}

JsonValue JsonObject::required(const std::string& key) {
  taken_.push_back(key);
  if (!value_->contains(key)) self_.fail("missing key '" + key + "'");
  return member(key);
}

std::vector<std::pair<std::string, JsonValue>> JsonObject::members() {
  std::vector<std::pair<std::string, JsonValue>> all;
  for (const auto& item : value_->items()) {
    taken_.push_back(item.key());
    all.emplace_back(item.key(), member(item.key()));
  }
  return all;
}

void JsonObject::finish() const {
  for (const auto& item : value_->items()) {
    if (std::find(taken_.begin(), taken_.end(), item.key()) != taken_.end()) continue;
    std::set<std::string> accepted(taken_.begin(), taken_.end());
    std::string list;
    for (const std::string& k : accepted) list += (list.empty() ? "" : ", ") + k;
    member(item.key()).fail("unknown key (expected one of: " + list + ")");
  }
}

nlohmann::json parse_json_file(const std::filesystem::path& path) {
  const std::string name = path.string();
  check_input_file(path, name, kMaxSceneFileBytes, "scene file");  // before opening: a FIFO would block
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(name + ": cannot open for reading");
  std::stringstream text;
  text << in.rdbuf();

  // nlohmann keeps the last of two equal keys silently; a strict reader refuses them.
  std::vector<std::set<std::string>> open_objects;
  std::string duplicate;
  const auto watch_keys = [&](int, nlohmann::json::parse_event_t event, nlohmann::json& parsed) {
    using Event = nlohmann::json::parse_event_t;
    if (event == Event::object_start) open_objects.emplace_back();
    if (event == Event::object_end && !open_objects.empty()) open_objects.pop_back();
    if (event == Event::key && !open_objects.empty() && !open_objects.back().insert(parsed.get<std::string>()).second &&
        duplicate.empty())
      duplicate = parsed.get<std::string>();
    return true;
  };
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(text.str(), watch_keys);
  } catch (const nlohmann::json::exception& e) {
    // parse_error, and out_of_range for a number beyond double ("number overflow parsing '1e999'").
    std::string what = e.what();  // "[json.exception.parse_error.101] parse error at line 3, column 5: ..."
    if (const auto bracket = what.find("] "); what.rfind("[json.exception", 0) == 0 && bracket != std::string::npos)
      what = what.substr(bracket + 2);
    throw InputError(name + ": invalid JSON: " + what);
  }
  if (!duplicate.empty()) throw InputError(name + ": key '" + duplicate + "' appears twice in one object");
  return doc;
}

}  // namespace parashade::detail
