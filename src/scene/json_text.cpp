// SPDX-License-Identifier: Apache-2.0
// JSON text to a document, every failure an InputError naming where it is: the line and
// column of a syntax error, the JSON path of a number a double cannot hold.
#include <preimage/scene/scene.hpp>

#include <preimage/error.hpp>

#include <vector>

namespace preimage::scene {

using nlohmann::json;

namespace {

// A SAX pass that only follows the JSON path, so the error nlohmann reports without one
// (a number out of the range of doubles, e.g. 1e400) can be given its path. It runs only
// after json::parse has failed.
class PathTracker {
 public:
  std::string error_path;
  std::string error_token;

  bool null() { return value(); }
  bool boolean(bool) { return value(); }
  bool number_integer(json::number_integer_t) { return value(); }
  bool number_unsigned(json::number_unsigned_t) { return value(); }
  bool number_float(json::number_float_t, const std::string&) { return value(); }
  bool string(std::string&) { return value(); }
  bool binary(json::binary_t&) { return value(); }
  bool start_object(std::size_t) { return open(false); }
  bool key(std::string& k) {
    frames_.back().key = k;
    return true;
  }
  bool end_object() { return close(); }
  bool start_array(std::size_t) { return open(true); }
  bool end_array() { return close(); }
  bool parse_error(std::size_t, const std::string& token, const nlohmann::detail::exception&) {
    error_path = path();
    error_token = token;
    return false;
  }

 private:
  struct Frame {
    bool array;
    std::size_t next = 0;  // index of the next element of an array
    std::string key;       // current key of an object
  };
  std::vector<Frame> frames_;

  bool value() {
    if (!frames_.empty() && frames_.back().array) ++frames_.back().next;
    return true;
  }
  bool open(bool array) {
    frames_.push_back({array, 0, {}});
    return true;
  }
  bool close() {
    frames_.pop_back();
    return value();
  }
  // An array's `next` counts the elements already closed, so it is the index of the one
  // being read (the open container, or the failing value).
  std::string path() const {
    std::string p = "$";
    for (const Frame& f : frames_) {
      if (f.array) p.append("[").append(std::to_string(f.next)).append("]");
      else p.append(".").append(f.key);
    }
    return p;
  }
};

}  // namespace

json parse_json(const std::string& text, const std::string& source) {
  try {
    return json::parse(text);
  } catch (const json::parse_error& e) {
    // byte is the 1-based position of the error: turn it into line:column.
    std::size_t line = 1, col = 1;
    for (std::size_t i = 0; i + 1 < e.byte && i < text.size(); ++i) {
      if (text[i] == '\n') ++line, col = 1;
      else ++col;
    }
    const std::string what = e.what();
    const auto colon = what.rfind(": ");
    throw InputError(source + ":" + std::to_string(line) + ":" + std::to_string(col) + ": JSON syntax error: " +
                     (colon == std::string::npos ? what : what.substr(colon + 2)));
  } catch (const json::out_of_range&) {
    // The only one json::parse raises: a number beyond the range of doubles.
    PathTracker tracker;
    json::sax_parse(text, &tracker);
    throw InputError(source + ": " + (tracker.error_path.empty() ? "$" : tracker.error_path) + ": number " +
                     tracker.error_token + " is outside the range of doubles");
  }
}

}  // namespace preimage::scene
