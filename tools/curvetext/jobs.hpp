// Many images from one process: `curvetext render --jobs FILE` (and `shape`)
// reads one job per line, a JSON object holding the command's options, and
// runs each in the same process, with one GL context for all.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace curvetext::cli {

// A job line longer than this is refused (twice the text limit, 4 MiB: room
// for a text at the limit in UTF-8, or with its 3-byte characters written as
// \u escapes), and a list of more jobs than this stops there: memory stays
// bounded whatever is piped in.
inline constexpr std::size_t kMaxJobLineBytes = std::size_t{8} << 20;
inline constexpr std::size_t kMaxJobs = 100000;

// A job line: the arguments it stands for, and its output (for the report).
// Each key is an option without its dashes ("output" is -o), a string or
// number its value, true a flag (false leaves it out), an array the option
// repeated in order:
//   {"text": "Hi", "size": 24, "markup": true, "font": ["A", "B"], "output": "a.png"}
//   -> --text Hi --size 24 --markup --font A --font B -o a.png
// Throws Error(InvalidArgument) naming the column for anything else: not one
// JSON object, null or a nested object, a key given twice, "jobs", or "-"
// (standard input or output, which the job list and the report use) as text,
// text-file, input or output.
struct Job {
  std::vector<std::string> arguments;
  std::string output;
};
Job parse_job(std::string_view line);

// The FILE of `--jobs FILE` ("-": standard input) when `args` starts with
// it; nullopt when it does not. Throws UsageError (kJobsAlone) when other
// options come with it: each job has its own.
inline constexpr const char* kJobsAlone = "--jobs FILE takes no other options: each job line has its own";
std::optional<std::string> jobs_source(const std::vector<std::string>& args);

// Reads the job list at `source` line by line, running `run` on each job's
// arguments as it is read (blank lines are skipped). Every job is reported on
// standard output, one JSON line each, flushed: {"line":N,"output":"a.png"}
// or {"line":N,"error":"..."}; each error is also one line on standard error,
// "curvetext: SOURCE:N: ...". A failed job does not stop the others. Returns
// 0 when every job succeeded, 1 otherwise (also when the list could not be
// read, or had more than kMaxJobs jobs: those after are not run).
int run_jobs(const std::string& source, const std::function<void(const std::vector<std::string>&)>& run);

}  // namespace curvetext::cli
