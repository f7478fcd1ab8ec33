#include "jobs.hpp"

#include <algorithm>
#include <cstdio>
#include <exception>
#include <set>

#include "cli.hpp"
#include "curvetext/error.hpp"

namespace curvetext::cli {

namespace {

// One job line's JSON object, read into arguments as it is parsed.
class JobParser {
 public:
  explicit JobParser(std::string_view line) : s_(line) {}

  Job parse() {
    skip_space();
    expect('{');
    skip_space();
    if (!take('}')) {
      do {
        member();
        skip_space();
      } while (take(','));
      if (!take('}')) fail("expected ',' or '}'");
    }
    skip_space();
    if (i_ != s_.size()) fail("text after the job's object");
    return std::move(job_);
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw Error(ErrorCode::InvalidArgument,
                "column " + std::to_string(i_ + 1) + ": " + what + " (a job is one JSON object of options)");
  }
  void skip_space() {
    while (i_ < s_.size() && (s_[i_] == ' ' || s_[i_] == '\t' || s_[i_] == '\r' || s_[i_] == '\n')) ++i_;
  }
  bool take(char c) {
    if (i_ < s_.size() && s_[i_] == c) return ++i_, true;
    return false;
  }
  void expect(char c) {
    if (!take(c)) fail(std::string("expected '") + c + "'" + (i_ < s_.size() ? "" : ", found the line's end"));
  }

  // "key": value, where the key names an option.
  void member() {
    skip_space();
    if (i_ >= s_.size() || s_[i_] != '"') fail("expected a key in double quotes");
    const std::size_t key_column = i_;
    const std::string key = string();
    check_key(key, key_column);
    skip_space();
    expect(':');
    skip_space();
    const std::string option = key == "output" ? "-o" : "--" + key;
    if (take('[')) {
      skip_space();
      if (take(']')) return;
      do {
        skip_space();
        scalar(key, option, /*in_array=*/true);
        skip_space();
      } while (take(','));
      expect(']');
    } else {
      scalar(key, option, /*in_array=*/false);
    }
  }

  void check_key(const std::string& key, std::size_t column) {
    bool word = !key.empty() && key.front() >= 'a' && key.front() <= 'z';
    for (char c : key) word = word && ((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-');
    if (!word) {
      i_ = column;
      fail("key \"" + key + "\" is not an option name (lower case, as on the command line without '--')");
    }
    if (key == "jobs") fail("a job cannot name more jobs");
    if (!keys_.insert(key).second) fail("key \"" + key + "\" given twice (repeat an option with an array)");
  }

  // A string, number or true/false: the option's value, or the flag.
  void scalar(const std::string& key, const std::string& option, bool in_array) {
    if (i_ >= s_.size()) fail("expected a value for \"" + key + "\", found the line's end");
    const char c = s_[i_];
    if (c == '"') {
      const std::size_t column = i_;
      std::string value = string();
      if (value == "-" && (key == "text" || key == "text-file" || key == "input" || key == "output")) {
        i_ = column;
        fail("\"" + key + "\": \"-\" (standard input or output) is not available to a job");
      }
      if (key == "output") job_.output = value;
      job_.arguments.push_back(option);
      job_.arguments.push_back(std::move(value));
    } else if (c == '-' || (c >= '0' && c <= '9')) {
      job_.arguments.push_back(option);
      job_.arguments.push_back(number());
    } else if (!in_array && s_.substr(i_, 4) == "true") {
      i_ += 4;
      job_.arguments.push_back(option);
    } else if (!in_array && s_.substr(i_, 5) == "false") {
      i_ += 5;
    } else if (c == '{' || c == '[') {
      fail("\"" + key + "\": nested " + (c == '{' ? "objects" : "arrays") + " are not options");
    } else {
      fail("\"" + key + "\": expected a string, a number" + (in_array ? "" : ", true or false"));
    }
  }

  // A JSON number, kept as written (the option parses it).
  std::string number() {
    const std::size_t start = i_;
    take('-');
    const auto digits = [&] {
      const std::size_t from = i_;
      while (i_ < s_.size() && s_[i_] >= '0' && s_[i_] <= '9') ++i_;
      return i_ > from;
    };
    const bool leading_zero = i_ < s_.size() && s_[i_] == '0';
    if (!digits() || (leading_zero && i_ - start > (s_[start] == '-' ? 2u : 1u))) fail("bad number");
    if (take('.') && !digits()) fail("bad number");
    if (take('e') || take('E')) {
      if (!take('+')) take('-');
      if (!digits()) fail("bad number");
    }
    return std::string(s_.substr(start, i_ - start));
  }

  // A JSON string (after its opening quote is seen), escapes decoded to UTF-8.
  std::string string() {
    ++i_;
    std::string out;
    while (true) {
      if (i_ >= s_.size()) fail("string not closed before the line's end");
      const auto c = static_cast<unsigned char>(s_[i_++]);
      if (c == '"') return out;
      if (c < 0x20) fail("control character in a string (write it as an escape)");
      if (c != '\\') {
        out += static_cast<char>(c);
        continue;
      }
      if (i_ >= s_.size()) fail("string not closed before the line's end");
      const char e = s_[i_++];
      switch (e) {
        case '"':
          out += '"';
          break;
        case '\\':
          out += '\\';
          break;
        case '/':
          out += '/';
          break;
        case 'b':
          out += '\b';
          break;
        case 'f':
          out += '\f';
          break;
        case 'n':
          out += '\n';
          break;
        case 'r':
          out += '\r';
          break;
        case 't':
          out += '\t';
          break;
        case 'u':
          append_utf8(out, code_point());
          break;
        default:
          --i_;
          fail(std::string("bad escape \\") + e);
      }
    }
  }

  unsigned hex4() {
    if (i_ + 4 > s_.size()) fail("\\u needs four hex digits");
    unsigned v = 0;
    for (int k = 0; k < 4; ++k) {
      const char h = s_[i_++];
      v <<= 4;
      if (h >= '0' && h <= '9')
        v |= static_cast<unsigned>(h - '0');
      else if (h >= 'a' && h <= 'f')
        v |= static_cast<unsigned>(h - 'a' + 10);
      else if (h >= 'A' && h <= 'F')
        v |= static_cast<unsigned>(h - 'A' + 10);
      else
        fail("\\u needs four hex digits");
    }
    return v;
  }

  // After "\u": one code point, a surrogate pair joined.
  char32_t code_point() {
    const unsigned high = hex4();
    if (high >= 0xDC00 && high <= 0xDFFF) fail("\\u escape: a low surrogate alone");
    if (high < 0xD800 || high > 0xDBFF) return high;
    if (s_.substr(i_, 2) != "\\u") fail("\\u escape: a high surrogate alone");
    i_ += 2;
    const unsigned low = hex4();
    if (low < 0xDC00 || low > 0xDFFF) fail("\\u escape: a high surrogate alone");
    return 0x10000 + ((high - 0xD800) << 10) + (low - 0xDC00);
  }

  static void append_utf8(std::string& out, char32_t c) {
    if (c < 0x80) {
      out += static_cast<char>(c);
    } else if (c < 0x800) {
      out += static_cast<char>(0xC0 | (c >> 6));
      out += static_cast<char>(0x80 | (c & 0x3F));
    } else if (c < 0x10000) {
      out += static_cast<char>(0xE0 | (c >> 12));
      out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (c & 0x3F));
    } else {
      out += static_cast<char>(0xF0 | (c >> 18));
      out += static_cast<char>(0x80 | ((c >> 12) & 0x3F));
      out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (c & 0x3F));
    }
  }

  std::string_view s_;
  std::size_t i_ = 0;
  Job job_;
  std::set<std::string> keys_;
};

// JSON string contents for the report.
std::string json_escaped(const std::string& s) {
  std::string out;
  for (char ch : s) {
    const auto c = static_cast<unsigned char>(ch);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += ch;
    } else if (c < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      out += buf;
    } else {
      out += ch;
    }
  }
  return out;
}

// Reads one line, without its line break, into `line`; false at the end.
// A line past kMaxJobLineBytes is read to its end but not kept (`too_long`).
bool read_line(std::FILE* in, std::string& line, bool& too_long) {
  line.clear();
  too_long = false;
  int c = 0;
  bool any = false;
  while ((c = getc_unlocked(in)) != EOF) {
    any = true;
    if (c == '\n') break;
    if (line.size() < kMaxJobLineBytes)
      line += static_cast<char>(c);
    else
      too_long = true;
  }
  return any;
}

bool blank(const std::string& line) { return line.find_first_not_of(" \t\r") == std::string::npos; }

// Runs one job; its error message, empty when it succeeded.
std::string run_one(const std::string& line, bool too_long,
                    const std::function<void(const std::vector<std::string>&)>& run, std::string& output) {
  try {
    if (too_long) throw Error(ErrorCode::InvalidArgument, "longer than " + std::to_string(kMaxJobLineBytes) + " bytes");
    const Job job = parse_job(line);
    output = job.output;
    run(job.arguments);
    return {};
  } catch (const UsageError& e) {
    const std::string unknown = "unknown option --";
    if (e.message.rfind(unknown, 0) == 0) return "unknown key \"" + e.message.substr(unknown.size()) + "\"";
    return e.message;
  } catch (const std::exception& e) {
    return e.what();
  }
}

}  // namespace

Job parse_job(std::string_view line) { return JobParser(line).parse(); }

std::optional<std::string> jobs_source(const std::vector<std::string>& args) {
  if (args.empty()) return std::nullopt;
  std::optional<std::string> source;
  std::size_t used = 1;
  if (args[0] == "--jobs") {
    if (args.size() < 2) throw UsageError{"--jobs needs a value"};
    source = args[1];
    used = 2;
  } else if (args[0].rfind("--jobs=", 0) == 0) {
    source = args[0].substr(7);
  }
  if (source && args.size() > used) throw UsageError{kJobsAlone};
  return source;
}

int run_jobs(const std::string& source, const std::function<void(const std::vector<std::string>&)>& run) {
  const bool from_stdin = source == "-";
  std::FILE* in = from_stdin ? stdin : std::fopen(source.c_str(), "rb");
  if (!in) throw Error(ErrorCode::Io, "cannot read the job list " + source);
  const std::string name = from_stdin ? std::string("standard input") : source;
  std::size_t line_number = 0, jobs = 0, failed = 0;
  bool overflow = false;
  std::string line;
  bool too_long = false;
  while (read_line(in, line, too_long)) {
    ++line_number;
    if (!too_long && blank(line)) continue;
    if (jobs == kMaxJobs) {
      std::fprintf(stderr, "curvetext: %s:%zu: more than %zu jobs; the rest are not run\n", name.c_str(), line_number,
                   kMaxJobs);
      overflow = true;
      break;
    }
    ++jobs;
    std::string output;
    const std::string error = run_one(line, too_long, run, output);
    if (error.empty()) {
      std::printf("{\"line\":%zu,\"output\":\"%s\"}\n", line_number, json_escaped(output).c_str());
    } else {
      ++failed;
      std::printf("{\"line\":%zu,\"error\":\"%s\"}\n", line_number, json_escaped(error).c_str());
      std::fprintf(stderr, "curvetext: %s:%zu: %s\n", name.c_str(), line_number, error.c_str());
    }
    std::fflush(stdout);
  }
  const bool read_failed = std::ferror(in) != 0;
  if (!from_stdin) std::fclose(in);
  if (read_failed) {
    std::fprintf(stderr, "curvetext: cannot read the job list %s after line %zu\n", name.c_str(), line_number);
    return 1;
  }
  if (failed) std::fprintf(stderr, "curvetext: %zu of %zu jobs failed\n", failed, jobs);
  return failed || overflow ? 1 : 0;
}

}  // namespace curvetext::cli
