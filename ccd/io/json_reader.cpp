#include <ccd/io/json_reader.hpp>

#include <ccd/util/nearest_name.hpp>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <set>
#include <streambuf>
#include <sys/stat.h>
#include <vector>

namespace ccd {

using nlohmann::json;

namespace {

// Follows the parse with a stack of open objects and arrays, so that a duplicate key or
// too deep a nesting is reported with the field path where it happens.
class StrictParse {
 public:
  explicit StrictParse(const std::string& file) : file_(file) {}

  void start(bool object) {
    if (frames_.size() >= static_cast<std::size_t>(kMaxJsonDepth))
      throw InputError(file_, path(), "nested deeper than " + std::to_string(kMaxJsonDepth) + " levels");
    frames_.push_back({object, {}, {}, 0});
  }
  void key(const std::string& k) {
    Frame& top = frames_.back();
    top.key = k;
    if (!top.keys.insert(top.key).second) throw InputError(file_, path(), "key given twice in one object");
  }
  void end() {
    frames_.pop_back();
    element_done();
  }
  void value() { element_done(); }

 private:
  struct Frame {
    bool object;
    std::set<std::string> keys;
    std::string key;      // object: the key being read
    std::size_t index;    // array: elements read so far
  };
  void element_done() {
    if (!frames_.empty() && !frames_.back().object) ++frames_.back().index;
  }
  std::string path() const {
    std::string p;
    for (const Frame& f : frames_) {
      if (f.object && !f.key.empty()) p += (p.empty() ? "" : ".") + f.key;
      if (!f.object) p += "[" + std::to_string(f.index) + "]";
    }
    return p;
  }

  const std::string& file_;
  std::vector<Frame> frames_;
};

// SAX events to nlohmann's plain document builder, with the strict checks on the way.
// Not json::parse with a callback: its builder scans the enclosing array for discarded
// elements at the end of every object, which makes an array of n objects cost O(n^2)
// (a 1,000,000-body scene did not load in 10 minutes).
class StrictDomBuilder {
 public:
  using number_integer_t = json::number_integer_t;
  using number_unsigned_t = json::number_unsigned_t;
  using number_float_t = json::number_float_t;
  using string_t = json::string_t;
  using binary_t = json::binary_t;

  StrictDomBuilder(json& result, const std::string& file) : dom_(result, true), strict_(file) {}

  bool null() { return leaf(dom_.null()); }
  bool boolean(bool v) { return leaf(dom_.boolean(v)); }
  bool number_integer(number_integer_t v) { return leaf(dom_.number_integer(v)); }
  bool number_unsigned(number_unsigned_t v) { return leaf(dom_.number_unsigned(v)); }
  bool number_float(number_float_t v, const string_t& s) { return leaf(dom_.number_float(v, s)); }
  bool string(string_t& v) { return leaf(dom_.string(v)); }
  bool binary(binary_t& v) { return leaf(dom_.binary(v)); }
  bool start_object(std::size_t n) {
    strict_.start(true);
    return dom_.start_object(n);
  }
  bool key(string_t& k) {
    strict_.key(k);
    return dom_.key(k);
  }
  bool end_object() {
    const bool ok = dom_.end_object();
    strict_.end();
    return ok;
  }
  bool start_array(std::size_t n) {
    strict_.start(false);
    return dom_.start_array(n);
  }
  bool end_array() {
    const bool ok = dom_.end_array();
    strict_.end();
    return ok;
  }
  template <class Exception>
  bool parse_error(std::size_t position, const std::string& token, const Exception& ex) {
    return dom_.parse_error(position, token, ex);  // throws ex
  }

 private:
  bool leaf(bool ok) {
    strict_.value();
    return ok;
  }
  nlohmann::detail::json_sax_dom_parser<json> dom_;
  StrictParse strict_;
};

template <class Input>
json parse_strictly(Input&& input, const std::string& file) {
  json result;
  StrictDomBuilder builder(result, file);
  try {
    json::sax_parse(std::forward<Input>(input), &builder);
  } catch (const json::exception& e) {
    throw InputError(file, "", std::string("malformed JSON: ") + e.what());
  }
  return result;
}

// A stream buffer over a file that reports end of input after `limit` bytes and says so.
class LimitedFileBuffer : public std::streambuf {
 public:
  LimitedFileBuffer(std::filebuf& in, std::uint64_t limit) : in_(in), left_(limit) {}
  bool exceeded() const { return exceeded_; }

 protected:
  int_type underflow() override {
    if (gptr() < egptr()) return traits_type::to_int_type(*gptr());
    if (left_ == 0) {
      exceeded_ = in_.sgetc() != traits_type::eof();
      return traits_type::eof();
    }
    const std::streamsize n = in_.sgetn(buffer_, static_cast<std::streamsize>(std::min<std::uint64_t>(sizeof buffer_, left_)));
    if (n <= 0) return traits_type::eof();
    left_ -= static_cast<std::uint64_t>(n);
    setg(buffer_, buffer_, buffer_ + n);
    return traits_type::to_int_type(*gptr());
  }

 private:
  std::filebuf& in_;
  std::uint64_t left_;
  bool exceeded_ = false;
  char buffer_[1 << 16];
};

}  // namespace

json parse_json_text(std::string_view text, const std::string& file) {
  if (text.size() > kMaxJsonBytes)
    throw InputError(file, "", "larger than " + std::to_string(kMaxJsonBytes) + " bytes");
  return parse_strictly(text, file);
}

json read_json_file(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) throw InputError(path, "", std::string("cannot open file: ") + std::strerror(errno));
  if (S_ISDIR(st.st_mode)) throw InputError(path, "", "cannot open file: is a folder");
  std::filebuf file;
  if (!file.open(path, std::ios::in | std::ios::binary))
    throw InputError(path, "", std::string("cannot open file: ") + std::strerror(errno));
  LimitedFileBuffer limited(file, kMaxJsonBytes);
  std::istream in(&limited);
  try {
    return parse_strictly(in, path);
  } catch (const InputError&) {
    if (limited.exceeded()) throw InputError(path, "", "larger than " + std::to_string(kMaxJsonBytes) + " bytes");
    throw;
  }
}

void JsonReader::only_fields(const json& obj, const std::string& path,
                             std::span<const std::string_view> known) const {
  if (!obj.is_object()) return;
  for (const auto& item : obj.items()) {
    const std::string& key = item.key();
    if (key == "comment" || std::find(known.begin(), known.end(), key) != known.end()) continue;
    const bool plain = std::all_of(key.begin(), key.end(), [](char c) { return c >= ' ' && c != 0x7f; });
    const std::string shown = plain ? key : json(key).dump();  // control characters escaped
    fail(path.empty() ? shown : path + "." + shown,
         "unknown field" + suggestion(key, known));
  }
}

const json& JsonReader::require(const json& obj, const char* key, const std::string& path) const {
  auto it = obj.find(key);
  if (it == obj.end()) fail(path.empty() ? key : path + "." + key, "missing required field");
  return *it;
}

double JsonReader::number(const json& v, const std::string& field) const {
  if (!v.is_number()) fail(field, "must be a number");
  const double x = v.get<double>();
  if (!std::isfinite(x)) fail(field, "must be finite");
  return x;
}

Vec3 JsonReader::vec3(const json& v, const std::string& field) const {
  if (!v.is_array() || v.size() != 3) fail(field, "must be an array of 3 numbers");
  return {number(v[0], field + "[0]"), number(v[1], field + "[1]"), number(v[2], field + "[2]")};
}

Vec3 JsonReader::optional_vec3(const json& obj, const char* key, const std::string& path) const {
  auto it = obj.find(key);
  return it == obj.end() ? Vec3::Zero() : vec3(*it, path + "." + key);
}

std::uint32_t JsonReader::index(const json& v, const std::string& field) const {
  if (!v.is_number_integer() || (!v.is_number_unsigned() && v.get<std::int64_t>() < 0))
    fail(field, "must be a non-negative integer");
  const std::uint64_t x = v.get<std::uint64_t>();
  if (x > std::numeric_limits<std::uint32_t>::max()) fail(field, "body index too large");
  return static_cast<std::uint32_t>(x);
}

std::uint64_t JsonReader::count(const json& v, const std::string& field, std::uint64_t max) const {
  if (!v.is_number_integer() || (!v.is_number_unsigned() && v.get<std::int64_t>() < 0) ||
      v.get<std::uint64_t>() > max)
    fail(field, "must be an integer in [0, " + std::to_string(max) + "]");
  return v.get<std::uint64_t>();
}

long long JsonReader::integer(const json& v, const std::string& field, long long lo, long long hi) const {
  const std::string rule = "must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  if (!v.is_number_integer()) fail(field, rule);
  if (v.is_number_unsigned() && v.get<std::uint64_t>() > static_cast<std::uint64_t>(hi)) fail(field, rule);
  const long long x = v.get<long long>();
  if (x < lo || x > hi) fail(field, rule);
  return x;
}

std::string JsonReader::string(const json& v, const std::string& field) const {
  if (!v.is_string()) fail(field, "must be a string");
  return v.get<std::string>();
}

bool JsonReader::boolean(const json& v, const std::string& field) const {
  if (!v.is_boolean()) fail(field, "must be true or false");
  return v.get<bool>();
}

double JsonReader::optional_number(const json& obj, const char* key, const std::string& path, double fallback) const {
  auto it = obj.find(key);
  return it == obj.end() ? fallback : number(*it, path.empty() ? key : path + "." + key);
}

bool JsonReader::optional_bool(const json& obj, const char* key, const std::string& path, bool fallback) const {
  auto it = obj.find(key);
  return it == obj.end() ? fallback : boolean(*it, path.empty() ? key : path + "." + key);
}

}  // namespace ccd
