#include "core/json_file.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "core/error.h"
#include "core/file_access.h"

namespace maquette {
namespace {

using json = nlohmann::json;

constexpr size_t kExcerptChars = 60;

// "line L, column C" of the character before `offset` (nlohmann counts characters read).
std::string position_text(std::string_view text, size_t offset) {
  offset = std::min(offset, text.size());
  const std::string_view before = text.substr(0, offset);
  const size_t line_start =
      before.rfind('\n') == std::string_view::npos ? 0 : before.rfind('\n') + 1;
  const auto lines = std::count(before.begin(), before.end(), '\n');
  return "line " + std::to_string(lines + 1) + ", column " + std::to_string(offset - line_start);
}

// Where the nesting of `text` first goes deeper than kMaxJsonDepth (brackets outside strings).
size_t too_deep_offset(std::string_view text) {
  int depth = 0;
  bool in_string = false;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      if (c == '\\')
        ++i;
      else if (c == '"')
        in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > kMaxJsonDepth) return i + 1;
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
  return text.size();
}

// nlohmann's DOM builder, which also knows the field being parsed (as steps[0].params.x) and
// refuses nesting deeper than kMaxJsonDepth; errors become maquette::Error naming the source,
// line, column and field.
class Parser : public nlohmann::detail::json_sax_dom_parser<json> {
  using Base = nlohmann::detail::json_sax_dom_parser<json>;

 public:
  Parser(json& root, std::string_view text, const std::string& source)
      : Base(root, true), text_(text), source_(source) {}

  bool null() { return value(), Base::null(); }
  bool boolean(bool v) { return value(), Base::boolean(v); }
  bool number_integer(number_integer_t v) { return value(), Base::number_integer(v); }
  bool number_unsigned(number_unsigned_t v) { return value(), Base::number_unsigned(v); }
  bool number_float(number_float_t v, const string_t& s) {
    return value(), Base::number_float(v, s);
  }
  bool string(string_t& v) { return value(), Base::string(v); }
  bool binary(binary_t& v) { return value(), Base::binary(v); }
  bool start_object(std::size_t n) { return open(false), Base::start_object(n); }
  bool end_object() { return frames_.pop_back(), Base::end_object(); }
  bool start_array(std::size_t n) { return open(true), Base::start_array(n); }
  bool end_array() { return frames_.pop_back(), Base::end_array(); }
  bool key(string_t& k) {
    frames_.back().key = k;
    return Base::key(k);
  }

  template <class Exception>
  bool parse_error(std::size_t offset, const std::string& token, const Exception& e) {
    if (e.id == 406) {  // a number beyond double's range: the value being read
      value();
      throw Error(source_ + ": " + position_text(text_, offset) + ": " + field() + "number " +
                  excerpt(token) + " is out of range (beyond +-1.8e308)");
    }
    // e.what() is "[json.exception.parse_error.101] parse error at line 3, column 5: ...".
    std::string what = e.what();
    if (const size_t end = what.find("] "); what.starts_with("[json.") && end != std::string::npos)
      what = what.substr(end + 2);
    // "...; last read: 'TOKEN'": the token may be a whole huge string.
    if (const size_t read = what.find("last read: '"); read != std::string::npos) {
      const size_t begin = read + 12, end = what.rfind('\'');
      if (end > begin)
        what = what.substr(0, begin) + excerpt(std::string_view(what).substr(begin, end - begin)) +
               what.substr(end);
    }
    const std::string at = field();
    throw Error(source_ + ": " + what +
                (at.empty() ? "" : " (in " + at.substr(0, at.size() - 2) + ")"));
  }

 private:
  struct Frame {
    bool array = false;
    int64_t index = -1;  // of the array's current element
    std::string key;     // of the object's current member
  };

  void value() {
    if (!frames_.empty() && frames_.back().array) ++frames_.back().index;
  }

  void open(bool array) {
    value();
    if (int(frames_.size()) >= kMaxJsonDepth)
      throw Error(source_ + ": " + position_text(text_, too_deep_offset(text_)) + ": " + field() +
                  "nested deeper than " + std::to_string(kMaxJsonDepth) + " levels");
    frames_.push_back({array, -1, {}});
  }

  // "steps[0].params.x: ", or "" at the top level; the first 8 levels of a deeper one.
  std::string field() const {
    constexpr size_t kShownLevels = 8;
    std::string path;
    for (size_t i = 0; i < frames_.size() && i < kShownLevels; ++i) {
      const Frame& f = frames_[i];
      if (f.array && f.index >= 0)
        path += "[" + std::to_string(f.index) + "]";
      else if (!f.array && !f.key.empty())
        path += (path.empty() ? "" : ".") + excerpt(f.key);
    }
    if (frames_.size() > kShownLevels) path += "...";
    return path.empty() ? path : path + ": ";
  }

  std::string_view text_;
  const std::string& source_;
  std::vector<Frame> frames_;
};

}  // namespace

json parse_json(std::string_view text, const std::string& source) {
  json out;
  Parser parser(out, text, source);
  json::sax_parse(text.begin(), text.end(), &parser);
  return out;
}

std::string read_text_file(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))  // opened and read as an empty file
    throw Error("cannot read " + path + ": it is a directory");
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw Error("cannot read " + path + ": " + file_access_problem(path).value_or("read error"));
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

json read_json_file(const std::string& path) { return parse_json(read_text_file(path), path); }

std::string excerpt(std::string_view text) {
  if (text.size() <= kExcerptChars) return std::string(text);
  return std::string(text.substr(0, kExcerptChars)) + "... (" + std::to_string(text.size()) +
         " characters)";
}

}  // namespace maquette
