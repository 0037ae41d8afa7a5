#include "hullinspect/files/json_document.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <set>
#include <vector>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/core/numbers.hpp"

namespace hullinspect::io {

using nlohmann::json;

namespace {

// Forwards SAX events to nlohmann's DOM builder while tracking the field path, so a parse error
// (which nlohmann reports with a byte position only) can name the field it happened in.
class PathTrackingSax {
 public:
  explicit PathTrackingSax(json& result) : dom_(result, true) {}

  bool null() { return value(), dom_.null(); }
  bool boolean(bool v) { return value(), dom_.boolean(v); }
  bool number_integer(json::number_integer_t v) { return value(), dom_.number_integer(v); }
  bool number_unsigned(json::number_unsigned_t v) { return value(), dom_.number_unsigned(v); }
  bool number_float(json::number_float_t v, const json::string_t& s) {
    return value(), dom_.number_float(v, s);
  }
  bool string(json::string_t& v) { return value(), dom_.string(v); }
  bool binary(json::binary_t& v) { return value(), dom_.binary(v); }
  bool start_object(std::size_t n) {
    value();
    frames_.push_back({false, 0, 0, {}, {}, {}});
    return dom_.start_object(n);
  }
  bool key(json::string_t& k) {
    // nlohmann keeps the last of two equal keys silently; a document that gives a field twice is
    // ambiguous, so it is refused.
    if (!frames_.back().add_key(k)) {
      problem_ = fmt::format("duplicate key '{}'", escape_for_message(k, 60));
      duplicate_key_ = true;
      frames_.back().key.clear();  // path() then names the object that holds the key
      return false;
    }
    frames_.back().key = k;
    return dom_.key(k);
  }
  bool end_object() {
    frames_.pop_back();
    return dom_.end_object();
  }
  bool start_array(std::size_t n) {
    value();
    frames_.push_back({true, 0, 0, {}, {}, {}});
    return dom_.start_array(n);
  }
  bool end_array() {
    frames_.pop_back();
    return dom_.end_array();
  }
  bool parse_error(std::size_t position, const std::string& /*token*/,
                   const nlohmann::detail::exception& e) {
    position_ = position;
    // A number no double holds (out_of_range.406) is a field's problem; a syntax error is a
    // position's, shown as FILE:LINE only.
    number_error_ = e.id == 406;
    problem_ = e.what();
    // "[json.exception.parse_error.101] parse error at line 3, column 1: syntax error ...": the
    // line is reported as FILE:LINE, so keep only what went wrong.
    if (auto close = problem_.find("] "); close != std::string::npos) {
      problem_ = problem_.substr(close + 2);
    }
    if (problem_.starts_with("parse error")) {
      if (auto colon = problem_.find(": "); colon != std::string::npos) {
        problem_ = problem_.substr(colon + 2);
      }
    }
    std::replace(problem_.begin(), problem_.end(), '\n', ' ');
    return false;
  }

  /// The path of the value being read when the error happened ("" at the top level).
  std::string path() const {
    std::string out;
    for (std::size_t k = 0; k < frames_.size(); ++k) {
      const Frame& f = frames_[k];
      const bool last = k + 1 == frames_.size();
      if (f.array) {
        out += fmt::format("[{}]", last ? f.next : f.current);
      } else if (!f.key.empty()) {
        out += (out.empty() ? "" : ".") + escape_for_message(f.key, 40);
      }
    }
    return out;
  }
  std::size_t position() const { return position_; }
  const std::string& problem() const { return problem_; }
  bool number_error() const { return number_error_; }
  bool duplicate_key() const { return duplicate_key_; }

 private:
  struct Frame {
    bool array;
    std::size_t next;
    std::size_t current;
    std::string key;
    // The object's keys so far: a short list searched in order, a set once it grows.
    std::vector<std::string> keys;
    std::set<std::string> many_keys;
    bool add_key(const std::string& k) {
      if (!many_keys.empty()) return many_keys.insert(k).second;
      if (std::find(keys.begin(), keys.end(), k) != keys.end()) return false;
      keys.push_back(k);
      if (keys.size() > 32) {
        many_keys.insert(keys.begin(), keys.end());
        keys.clear();
      }
      return true;
    }
  };
  void value() {
    if (!frames_.empty() && frames_.back().array) frames_.back().current = frames_.back().next++;
  }
  nlohmann::detail::json_sax_dom_parser<json> dom_;
  std::vector<Frame> frames_;
  std::size_t position_ = 0;
  bool number_error_ = false;
  bool duplicate_key_ = false;
  std::string problem_;
};

}  // namespace

json parse_json_document(std::string_view text, const std::string& source, std::string_view what) {
  json result;
  PathTrackingSax sax(result);
  bool ok = false;
  try {
    ok = json::sax_parse(text.begin(), text.end(), &sax);
  } catch (const json::exception& e) {
    throw InputError(source, 0, fmt::format("not {}: {}", what, e.what()));
  }
  if (!ok && sax.duplicate_key()) {
    // The parser does not tell a callback where it is; the key and the object's path name it.
    const std::string object = sax.path();
    throw InputError(source, 0,
                     fmt::format("not {}: {}{}", what, sax.problem(),
                                 object.empty() ? "" : " (in " + object + ")"));
  }
  if (!ok) {
    const auto end = std::min(sax.position(), text.size());
    const int line = 1 + static_cast<int>(std::count(
                             text.begin(), text.begin() + static_cast<std::ptrdiff_t>(end), '\n'));
    const std::string field = sax.number_error() ? sax.path() : std::string();
    throw InputError(source, line,
                     fmt::format("not {}: {}{}", what, escape_for_message(sax.problem(), 400),
                                 field.empty() ? "" : " (in " + field + ")"));
  }
  return result;
}

}  // namespace hullinspect::io
