// A candidate: any implementation of (A.2) that is not this library, named by a spec
//
//   lib:PATH[:SYMBOL]   a shared library; SYMBOL (default contact_candidate, or
//                       contact_candidate_f in single precision) is
//                         double contact_candidate(double u, double dy, double phi, int* which)
//                         float contact_candidate_f(float u, float dy, float phi, int* which)
//   cmd:COMMAND         a program (run by /bin/sh -c) speaking contact-solve's line
//                       protocol: lines "u dy phi" in, lines "s case" or "error ..." out
//
// The candidate's code never runs in the caller's process: a library is loaded
// by a forked worker that answers over a pipe, one answer per input, so that a
// crash or a hang is pinned to the input that caused it; a command runs once per
// batch of lines. The contact-check tool and contact-report share this runner.
#pragma once

#include <dlfcn.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "contact/harness/random.hpp"

namespace contact::harness {

// A spec that cannot be used: bad syntax, a missing library or symbol. Usage
// errors, as opposed to the candidate's failures.
struct candidate_error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct candidate_spec {
  enum class kind { library, command } form = kind::library;
  std::string path, symbol;  // library
  std::string command;       // command
};

inline candidate_spec parse_candidate_spec(const std::string& text, bool single_precision) {
  candidate_spec spec;
  if (text.rfind("lib:", 0) == 0) {
    const std::string rest = text.substr(4);
    const auto colon = rest.find(':');
    spec.path = rest.substr(0, colon);
    spec.symbol = colon == std::string::npos ? (single_precision ? "contact_candidate_f" : "contact_candidate")
                                             : rest.substr(colon + 1);
    if (spec.path.empty()) throw candidate_error("'" + text + "': lib: needs a path");
    if (spec.symbol.empty()) throw candidate_error("'" + text + "': empty symbol after the path");
    return spec;
  }
  if (text.rfind("cmd:", 0) == 0) {
    spec.form = candidate_spec::kind::command;
    spec.command = text.substr(4);
    if (spec.command.find_first_not_of(" \t") == std::string::npos)
      throw candidate_error("'" + text + "': cmd: needs a command");
    return spec;
  }
  throw candidate_error("'" + text + "' is not a candidate spec: expected lib:PATH[:SYMBOL] or cmd:COMMAND");
}

// What one call gave: an answer, or the reason there is none.
struct outcome {
  enum class status { answered, crashed, hung, unreadable, not_run } kind = status::not_run;
  double s = std::numeric_limits<double>::quiet_NaN();
  int which = 0;
  std::string detail;  // how it crashed, or what it wrote
  bool answered() const { return kind == status::answered; }
  bool faulted() const { return kind == status::crashed || kind == status::hung || kind == status::unreadable; }
};

class candidate {
 public:
  virtual ~candidate() = default;
  // One outcome per input. After the first fault (crash, hang, unreadable
  // answer) the remaining inputs stay not_run: a caller that meets a fault has
  // its failure, and a hanging candidate costs one timeout per call, not one per input.
  virtual std::vector<outcome> solve(const std::vector<input<double>>& inputs) = 0;
};

namespace detail_candidate {

using clock = std::chrono::steady_clock;

// Reads exactly `size` bytes unless the writer closes (false, eof) or the deadline passes (false, !eof).
inline bool read_fully(int fd, void* buffer, std::size_t size, clock::time_point deadline, bool& eof) {
  auto* bytes = static_cast<char*>(buffer);
  eof = false;
  while (size > 0) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - clock::now()).count();
    if (left <= 0) return false;
    pollfd p{fd, POLLIN, 0};
    const int ready = ::poll(&p, 1, static_cast<int>(std::min<long long>(left, 1 << 30)));
    if (ready < 0 && errno == EINTR) continue;
    if (ready <= 0) return false;
    const ssize_t got = ::read(fd, bytes, size);
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) { eof = true; return false; }
    bytes += got;
    size -= static_cast<std::size_t>(got);
  }
  return true;
}

inline bool write_fully(int fd, const void* buffer, std::size_t size) {
  const auto* bytes = static_cast<const char*>(buffer);
  while (size > 0) {
    const ssize_t put = ::write(fd, bytes, size);
    if (put < 0 && errno == EINTR) continue;
    if (put <= 0) return false;
    bytes += put;
    size -= static_cast<std::size_t>(put);
  }
  return true;
}

inline std::string killed_by(int sig) {
  const char* abbrev = sigabbrev_np(sig);
  return "killed by SIG" + std::string(abbrev ? abbrev : std::to_string(sig).c_str()) + " (" + strsignal(sig) + ")";
}

// "killed by SIGSEGV (Segmentation fault)" or "exited with status 3". A shell
// reports a child killed by signal N as status 128 + N: `through_shell` reads it so.
inline std::string how_it_ended(int status, bool through_shell = false) {
  if (WIFSIGNALED(status)) return killed_by(WTERMSIG(status));
  if (through_shell && WIFEXITED(status) && WEXITSTATUS(status) > 128 && WEXITSTATUS(status) < 128 + NSIG)
    return killed_by(WEXITSTATUS(status) - 128);
  if (WIFEXITED(status)) return "exited with status " + std::to_string(WEXITSTATUS(status));
  return "ended";
}

inline void redirect_to_null(int fd) {
  const int null = ::open("/dev/null", O_RDWR);
  if (null >= 0) { ::dup2(null, fd); ::close(null); }
}

struct request { double u, dy, phi; };
struct reply { double s; std::int32_t which, pad; };

}  // namespace detail_candidate

// A shared library, called in a forked worker process.
class library_candidate final : public candidate {
 public:
  library_candidate(candidate_spec spec, bool single_precision, double call_timeout_seconds)
      : spec_(std::move(spec)), single_(single_precision), timeout_(call_timeout_seconds) {
    ::signal(SIGPIPE, SIG_IGN);  // a worker that dies leaves a broken pipe, not a dead caller
    if (spec_.path.find('/') == std::string::npos) spec_.path = "./" + spec_.path;  // a file, not a search
    struct stat info;
    if (::stat(spec_.path.c_str(), &info) != 0) throw candidate_error("no such library: " + spec_.path);
    start();  // loading it once here turns a missing symbol into a usage error
  }
  ~library_candidate() override { stop(); }
  library_candidate(const library_candidate&) = delete;
  library_candidate& operator=(const library_candidate&) = delete;

  std::vector<outcome> solve(const std::vector<input<double>>& inputs) override {
    using namespace detail_candidate;
    std::vector<outcome> out(inputs.size());
    // at most this many requests in flight: they fit the pipe's buffer, so writing never blocks
    constexpr std::size_t chunk = 1024;
    for (std::size_t begin = 0; begin < inputs.size(); begin += chunk) {
      const std::size_t end = std::min(inputs.size(), begin + chunk);
      if (pid_ <= 0) start();
      std::vector<request> requests;
      for (std::size_t i = begin; i < end; ++i) requests.push_back({inputs[i].u, inputs[i].dy, inputs[i].phi});
      write_fully(to_worker_, requests.data(), requests.size() * sizeof(request));  // a dead worker shows on reading
      for (std::size_t i = begin; i < end; ++i) {
        reply r;
        bool eof = false;
        const auto deadline = clock::now() + std::chrono::duration_cast<clock::duration>(std::chrono::duration<double>(timeout_));
        if (read_fully(from_worker_, &r, sizeof r, deadline, eof)) {
          out[i].kind = outcome::status::answered;
          out[i].s = r.s;
          out[i].which = r.which;
          continue;
        }
        if (!eof) ::kill(pid_, SIGKILL);
        const int status = reap();
        out[i].kind = eof ? outcome::status::crashed : outcome::status::hung;
        out[i].detail = eof ? how_it_ended(status) : "no answer within " + seconds_text() + " s";
        return out;
      }
    }
    return out;
  }

 private:
  void start() {
    using namespace detail_candidate;
    int down[2], up[2];
    if (::pipe2(down, O_CLOEXEC) != 0 || ::pipe2(up, O_CLOEXEC) != 0) throw std::runtime_error("pipe failed");
    pid_ = ::fork();
    if (pid_ < 0) throw std::runtime_error("fork failed");
    if (pid_ == 0) {
      ::close(down[1]);
      ::close(up[0]);
      redirect_to_null(0);
      redirect_to_null(1);  // the candidate's own prints must not mix with the caller's
      redirect_to_null(2);
      serve(down[0], up[1]);
    }
    ::close(down[0]);
    ::close(up[1]);
    to_worker_ = down[1];
    from_worker_ = up[0];
    // the worker's first message: 0 loaded, or 1 and dlerror's text
    char loaded = 1;
    bool eof = false;
    if (!read_fully(from_worker_, &loaded, 1, clock::now() + std::chrono::seconds(30), eof)) {
      if (!eof) ::kill(pid_, SIGKILL);
      const int status = reap();
      throw candidate_error("loading " + spec_.path + ": the worker " + how_it_ended(status));
    }
    if (loaded != 0) {
      char message[1024] = {};
      read_fully(from_worker_, message, sizeof message - 1, clock::now() + std::chrono::seconds(5), eof);
      reap();
      throw candidate_error(message);
    }
  }

  [[noreturn]] void serve(int in, int out) {
    using namespace detail_candidate;
    void* library = ::dlopen(spec_.path.c_str(), RTLD_NOW | RTLD_LOCAL);
    void* symbol = library ? ::dlsym(library, spec_.symbol.c_str()) : nullptr;
    if (!symbol) {
      const std::string why = library ? "no symbol '" + spec_.symbol + "' in " + spec_.path : std::string(::dlerror());
      const char failed = 1;
      write_fully(out, &failed, 1);
      write_fully(out, why.c_str(), why.size());
      ::_exit(3);
    }
    const char loaded = 0;
    write_fully(out, &loaded, 1);
    using double_solver = double (*)(double, double, double, int*);
    using float_solver = float (*)(float, float, float, int*);
    request q;
    bool eof = false;
    while (read_fully(in, &q, sizeof q, clock::time_point::max(), eof)) {
      int which = -1;
      reply r{};
      if (single_) r.s = reinterpret_cast<float_solver>(symbol)(float(q.u), float(q.dy), float(q.phi), &which);
      else r.s = reinterpret_cast<double_solver>(symbol)(q.u, q.dy, q.phi, &which);
      r.which = which;
      if (!write_fully(out, &r, sizeof r)) break;
    }
    ::_exit(0);
  }

  int reap() {
    int status = 0;
    if (pid_ > 0) ::waitpid(pid_, &status, 0);
    pid_ = -1;
    ::close(to_worker_);
    ::close(from_worker_);
    return status;
  }

  void stop() {
    if (pid_ <= 0) return;
    ::close(to_worker_);  // the worker's read sees the end and it exits
    to_worker_ = ::open("/dev/null", O_WRONLY);
    bool eof = false;
    char ignored;
    if (!detail_candidate::read_fully(from_worker_, &ignored, 1, detail_candidate::clock::now() + std::chrono::seconds(1), eof) && !eof)
      ::kill(pid_, SIGKILL);
    reap();
  }

  std::string seconds_text() const {
    std::ostringstream text;
    text << timeout_;
    return text.str();
  }

  candidate_spec spec_;
  bool single_;
  double timeout_;
  pid_t pid_ = -1;
  int to_worker_ = -1, from_worker_ = -1;
};

// A program speaking contact-solve's protocol, started once per batch: the
// batch is its standard input (a file, so that writing can never block on a
// reader that does not read), its answers are read until it ends.
class command_candidate final : public candidate {
 public:
  command_candidate(candidate_spec spec, bool single_precision, double call_timeout_seconds)
      : spec_(std::move(spec)), single_(single_precision), timeout_(call_timeout_seconds) {
    ::signal(SIGPIPE, SIG_IGN);
  }

  std::vector<outcome> solve(const std::vector<input<double>>& inputs) override {
    std::vector<outcome> out(inputs.size());
    solve_range(inputs, 0, inputs.size(), out);
    return out;
  }

 private:
  // Runs [begin, end); on a fault, narrows it down to one input by halving
  // the unanswered part (output may be buffered, so the last answer read does
  // not say which input the program was on).
  void solve_range(const std::vector<input<double>>& inputs, std::size_t begin, std::size_t end,
                   std::vector<outcome>& out) {
    std::size_t answered = run(inputs, begin, end, out);
    if (answered == end || out[answered].kind == outcome::status::unreadable) return;
    outcome fault = out[answered];
    std::size_t lo = answered, hi = end;  // the fault lies in [lo, hi)
    while (hi - lo > 1) {
      const std::size_t mid = lo + (hi - lo) / 2;
      const std::size_t got = run(inputs, lo, mid, out);
      if (got < mid) {
        fault = out[got];
        if (fault.kind == outcome::status::unreadable) return;
        lo = got;
        hi = mid;
      } else {
        lo = mid;
      }
    }
    out[lo] = fault;
    for (std::size_t i = lo + 1; i < end; ++i) out[i] = outcome{};
  }

  // Answers inputs [begin, end) into `out`; returns the index of the first
  // input without an answer (end when all have one), whose outcome says why.
  std::size_t run(const std::vector<input<double>>& inputs, std::size_t begin, std::size_t end, std::vector<outcome>& out) {
    using namespace detail_candidate;
    std::FILE* batch = std::tmpfile();
    if (!batch) throw std::runtime_error("cannot create a temporary file");
    for (std::size_t i = begin; i < end; ++i) std::fprintf(batch, "%a %a %a\n", inputs[i].u, inputs[i].dy, inputs[i].phi);
    std::fflush(batch);
    std::rewind(batch);
    int answers[2];
    if (::pipe2(answers, O_CLOEXEC) != 0) throw std::runtime_error("pipe failed");
    const pid_t pid = ::fork();
    if (pid == 0) {
      ::setpgid(0, 0);  // its own group: a hang is ended with everything it started
      ::dup2(::fileno(batch), 0);
      ::dup2(answers[1], 1);
      redirect_to_null(2);
      ::execl("/bin/sh", "sh", "-c", spec_.command.c_str(), static_cast<char*>(nullptr));
      ::_exit(127);
    }
    ::close(answers[1]);
    std::fclose(batch);
    const auto allowed = std::chrono::duration<double>(timeout_ * (1 + double(end - begin) / 1000));
    const auto deadline = clock::now() + std::chrono::duration_cast<clock::duration>(allowed);
    std::string text;
    bool eof = false, timed_out = false;
    char buffer[65536];
    while (true) {
      pollfd p{answers[0], POLLIN, 0};
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - clock::now()).count();
      if (left <= 0) { timed_out = true; break; }
      const int ready = ::poll(&p, 1, static_cast<int>(left));
      if (ready < 0 && errno == EINTR) continue;
      if (ready == 0) { timed_out = true; break; }
      const ssize_t got = ::read(answers[0], buffer, sizeof buffer);
      if (got < 0 && errno == EINTR) continue;
      if (got <= 0) { eof = true; break; }
      text.append(buffer, static_cast<std::size_t>(got));
    }
    (void)eof;
    if (timed_out) ::kill(-pid, SIGKILL);
    ::close(answers[0]);
    int status = 0;
    ::waitpid(pid, &status, 0);

    std::istringstream lines(text);
    std::string line;
    std::size_t i = begin;
    while (i < end && std::getline(lines, line)) {
      if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
      if (!parse(line, out[i])) return i;
      ++i;
    }
    if (i < end) {
      out[i].kind = timed_out ? outcome::status::hung : outcome::status::crashed;
      out[i].detail = timed_out ? "no answer within " + std::to_string(allowed.count()) + " s"
                                : "the command " + how_it_ended(status, true) + " after " + std::to_string(i - begin) +
                                      " of " + std::to_string(end - begin) + " answers";
    }
    return i;
  }

  bool parse(const std::string& line, outcome& o) const {
    std::istringstream fields(line);
    std::string s_text;
    int which = -1;
    fields >> s_text;
    if (s_text == "error") {  // contact-solve's answer to invalid input
      o.kind = outcome::status::answered;
      o.s = std::numeric_limits<double>::quiet_NaN();
      o.which = 0;
      return true;
    }
    char* end = nullptr;
    const double s = std::strtod(s_text.c_str(), &end);
    if (s_text.empty() || *end != '\0' || !(fields >> which)) {
      o.kind = outcome::status::unreadable;
      o.detail = "unreadable answer '" + line + "'";
      return false;
    }
    o.kind = outcome::status::answered;
    o.s = single_ ? double(float(s)) : s;
    o.which = which;
    return true;
  }

  candidate_spec spec_;
  bool single_;
  double timeout_;
};

// Throws candidate_error for a spec that cannot be used.
inline std::unique_ptr<candidate> open_candidate(const std::string& spec_text, bool single_precision,
                                                 double call_timeout_seconds = 1.0) {
  candidate_spec spec = parse_candidate_spec(spec_text, single_precision);
  if (spec.form == candidate_spec::kind::library)
    return std::make_unique<library_candidate>(std::move(spec), single_precision, call_timeout_seconds);
  return std::make_unique<command_candidate>(std::move(spec), single_precision, call_timeout_seconds);
}

}  // namespace contact::harness
