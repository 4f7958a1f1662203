// SPDX-License-Identifier: Apache-2.0
// JSON text to a document, every failure an InputError naming where it is: the line and
// column of a syntax error, the JSON path of a number a double cannot hold.
#include <preimage/scene/scene.hpp>

#include <preimage/error.hpp>

#include <algorithm>
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

namespace {

std::string scalar_text(const json& v) { return v.dump(-1, ' ', false, json::error_handler_t::replace); }

// One line with ", " and ": " between items (easier to read than dump(-1)'s bare commas).
std::string inline_text(const json& v) {
  if (v.is_object()) {
    std::string s = "{";
    bool first = true;
    for (const auto& [key, value] : v.items()) {
      s.append(first ? "" : ", ").append(scalar_text(json(key))).append(": ").append(inline_text(value));
      first = false;
    }
    return s + "}";
  }
  if (v.is_array()) {
    std::string s = "[";
    for (std::size_t i = 0; i < v.size(); ++i) s.append(i ? ", " : "").append(inline_text(v[i]));
    return s + "]";
  }
  return scalar_text(v);
}

// An item short enough to share a line with its neighbours: a scalar or a point.
constexpr std::size_t kFillItem = 32;

// `column` is where the value starts on its line (after the indent and any "key": ).
void pretty(const json& v, std::size_t indent, std::size_t column, std::size_t width, std::string& out) {
  const std::string one_line = inline_text(v);
  if (!v.is_structured() || v.empty() || column + one_line.size() <= width) {
    out += one_line;
    return;
  }
  const std::string inner(indent + 2, ' ');
  if (v.is_object()) {
    out += "{\n";
    std::size_t k = 0;
    for (const auto& [key, value] : v.items()) {
      const std::string head = scalar_text(json(key)) + ": ";
      out.append(inner).append(head);
      pretty(value, indent + 2, inner.size() + head.size(), width, out);
      out += ++k < v.size() ? ",\n" : "\n";
    }
  } else {
    out += "[\n";
    std::vector<std::string> items;
    for (const auto& item : v) items.push_back(inline_text(item));
    const bool fill = std::all_of(items.begin(), items.end(), [](const std::string& s) { return s.size() <= kFillItem; });
    if (fill) {
      std::size_t column = 0;
      for (std::size_t i = 0; i < items.size(); ++i) {
        const std::string piece = items[i] + (i + 1 < items.size() ? "," : "");
        if (column > 0 && column + 1 + piece.size() > width) {
          out += "\n";
          column = 0;
        }
        if (column == 0) {
          out += inner;
          column = inner.size();
        } else {
          out += " ";
          ++column;
        }
        out += piece;
        column += piece.size();
      }
      out += "\n";
    } else {
      for (std::size_t i = 0; i < v.size(); ++i) {
        out += inner;
        pretty(v[i], indent + 2, inner.size(), width, out);
        out += i + 1 < v.size() ? ",\n" : "\n";
      }
    }
  }
  out.append(indent, ' ').append(v.is_object() ? "}" : "]");
}

}  // namespace

std::string format_json(const json& doc, JsonLayout layout, std::size_t width) {
  if (layout == JsonLayout::Compact) return scalar_text(doc);
  std::string out;
  pretty(doc, 0, 0, width, out);
  return out;
}

}  // namespace preimage::scene
