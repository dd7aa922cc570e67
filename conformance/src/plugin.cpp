// Candidate implementations in shared libraries, called in a child process (hinge/conformance/plugin.hpp).
#include "hinge/conformance/plugin.hpp"

#include <dlfcn.h>
#include <poll.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <stdexcept>

namespace hinge::conformance {
namespace {

using Clock = std::chrono::steady_clock;
constexpr std::size_t kOutputs = 1 + 12 + 144;  // theta (or psi), grad, hess

// The doubles a request carries: x, and for a bending term its rest hinge after it.
std::size_t input_count(PluginKind kind) { return kind == PluginKind::energy ? 24 : 12; }

// The child's answer to one case: the plugin's return value and its outputs.
struct Answer {
  std::int32_t status;
  double out[kOutputs];
};

// Reads exactly n bytes before `deadline`: 1 when done, 0 at the end of the stream (the child is gone), -1
// when the deadline passed first.
int read_all(int fd, void* buffer, std::size_t n, Clock::time_point deadline) {
  char* p = static_cast<char*>(buffer);
  std::size_t got = 0;
  while (got < n) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
    if (left <= 0) return -1;
    pollfd ready{fd, POLLIN, 0};
    const int polled = ::poll(&ready, 1, static_cast<int>(std::min<long long>(left, 1 << 30)));
    if (polled < 0 && errno == EINTR) continue;
    if (polled < 0) return 0;
    if (polled == 0) return -1;
    const ssize_t k = ::read(fd, p + got, n - got);
    if (k < 0 && (errno == EINTR || errno == EAGAIN)) continue;
    if (k <= 0) return 0;
    got += static_cast<std::size_t>(k);
  }
  return 1;
}

// Writes n bytes; false when the other side is gone (no SIGPIPE: MSG_NOSIGNAL).
bool write_all(int fd, const void* buffer, std::size_t n) {
  const char* p = static_cast<const char*>(buffer);
  while (n > 0) {
    const ssize_t k = ::send(fd, p, n, MSG_NOSIGNAL);
    if (k < 0 && errno == EINTR) continue;
    if (k <= 0) return false;
    p += k;
    n -= static_cast<std::size_t>(k);
  }
  return true;
}

// The requests: one case, or a batch to time.
constexpr std::int32_t kCase = 0, kTime = 1;

// A batch to time: how the parent describes it (then 12 doubles per hinge).
struct TimingRequest {
  std::uint64_t beside;  // Plugin::PerHinge, an address in the parent's image, which the child shares
  std::uint32_t hinges, rounds, repeats;
};

// Per hinge of `hinges`, one call of `f` writing into slot i of `out` (theta, then 12 gradient and 144
// Hessian entries per hinge, in three arrays), after one call not timed (warm caches, as the study's own
// passes); ns per hinge, and f's first nonzero return.
template <class F>
double timed_pass(F&& f, const std::vector<double>& hinges, std::vector<double>& out, int repeats, int& status) {
  const std::size_t n = hinges.size() / 12;
  double* theta = out.data();
  double* grad = theta + n;
  double* hess = grad + 12 * n;
  if (n > 0)
    if (const int s = f(&hinges[0], &theta[0], &grad[0], &hess[0]); s != 0 && status == 0) status = s;
  const auto start = Clock::now();
  for (int r = 0; r < repeats; ++r)
    for (std::size_t i = 0; i < n; ++i) {
      const int s = f(&hinges[12 * i], &theta[i], &grad[12 * i], &hess[144 * i]);
      if (s != 0 && status == 0) status = s;
    }
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return 1e9 * seconds / static_cast<double>(n * static_cast<std::size_t>(repeats));
}

// The child's side of Plugin::time: reads the batch, times it, answers a status and the rounds. false when
// the parent is gone.
bool serve_timing(int fd, hinge_candidate_fn* candidate) {
  TimingRequest t;
  if (read_all(fd, &t, sizeof t, Clock::time_point::max()) != 1) return false;
  std::vector<double> hinges(12 * static_cast<std::size_t>(t.hinges));
  if (read_all(fd, hinges.data(), sizeof(double) * hinges.size(), Clock::time_point::max()) != 1) return false;
  const auto beside = reinterpret_cast<Plugin::PerHinge>(t.beside);
  std::vector<double> mine(157 * static_cast<std::size_t>(t.hinges)), theirs(mine.size());
  std::vector<double> rounds;
  int status = 0;
  const auto plugin_pass = [&] { return timed_pass(candidate, hinges, mine, 1, status); };
  const auto beside_pass = [&] {
    int unused = 0;
    return timed_pass(
        [beside](const double* x, double* theta, double* grad, double* hess) {
          beside(x, theta, grad, hess);
          return 0;
        },
        hinges, theirs, static_cast<int>(t.repeats), unused);
  };
  for (std::uint32_t r = 0; r < t.rounds && status == 0; ++r) {
    double a = 0, b = 0;
    if (r % 2) {
      b = beside_pass();
      a = plugin_pass();
    } else {
      a = plugin_pass();
      b = beside_pass();
    }
    rounds.push_back(a);
    rounds.push_back(b);
  }
  const std::int32_t answer = status;
  const auto count = static_cast<std::uint32_t>(status == 0 ? rounds.size() : 0);
  return write_all(fd, &answer, sizeof answer) && write_all(fd, &count, sizeof count) &&
         write_all(fd, rounds.data(), sizeof(double) * count);
}

// The child: loads the library, reports (status 0, or 1 and why), then answers requests until the parent
// closes the socket. Never returns.
[[noreturn]] void serve(int fd, const std::string& path, const std::string& symbol, PluginKind kind) {
  ::dup2(STDERR_FILENO, STDOUT_FILENO);  // what the plugin prints must not mix with the report
  auto report = [fd](std::int32_t status, const std::string& why) {
    const auto length = static_cast<std::uint32_t>(why.size());
    write_all(fd, &status, sizeof status);
    write_all(fd, &length, sizeof length);
    write_all(fd, why.data(), why.size());
  };
  void* handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    report(1, "cannot load plugin " + path + ": " + ::dlerror());
    ::_exit(0);
  }
  void* symbol_address = ::dlsym(handle, symbol.c_str());
  if (!symbol_address) {
    report(1, "plugin " + path + " has no symbol " + symbol + ": " + ::dlerror());
    ::_exit(0);
  }
  const auto theta_function = reinterpret_cast<hinge_candidate_fn*>(symbol_address);
  const auto energy_function = reinterpret_cast<hinge_energy_candidate_fn*>(symbol_address);
  report(0, "");
  const std::size_t count = input_count(kind);
  for (;;) {
    std::int32_t request = 0;
    if (read_all(fd, &request, sizeof request, Clock::time_point::max()) != 1) ::_exit(0);
    if (request == kTime) {
      if (!serve_timing(fd, theta_function)) ::_exit(0);
      continue;
    }
    double in[24];  // x, then the rest hinge for a bending term
    if (read_all(fd, in, sizeof(double) * count, Clock::time_point::max()) != 1) ::_exit(0);
    Answer answer;
    for (double& v : answer.out) v = std::numeric_limits<double>::quiet_NaN();  // unwritten: non-finite
    answer.status = kind == PluginKind::energy
                        ? energy_function(in, in + 12, &answer.out[0], &answer.out[1], &answer.out[13])
                        : theta_function(in, &answer.out[0], &answer.out[1], &answer.out[13]);
    if (!write_all(fd, &answer.status, sizeof answer.status) || !write_all(fd, answer.out, sizeof answer.out))
      ::_exit(0);
  }
}

std::string seconds(double s) {
  char b[32];
  std::snprintf(b, sizeof b, "%g", s);
  return b;
}

}  // namespace

Plugin::Plugin(const std::string& path, const std::string& symbol, double timeout_seconds, PluginKind kind)
    : path_(path), symbol_(symbol), timeout_(timeout_seconds), kind_(kind) {
  start();
}

Plugin::~Plugin() { stop(); }

void Plugin::stop() {
  if (socket_ >= 0) ::close(socket_);
  socket_ = -1;
  if (child_ > 0) {
    ::kill(child_, SIGKILL);
    ::waitpid(child_, nullptr, 0);
  }
  child_ = -1;
}

// How the child ended, once its end of the socket closed: "crashed (signal 11, SIGSEGV)" or "exited with
// status N". Reaps it.
static std::string ended(pid_t child) {
  int status = 0;
  if (::waitpid(child, &status, 0) != child) return "ended";
  if (WIFSIGNALED(status)) {
    const int s = WTERMSIG(status);
    const char* name = ::sigabbrev_np(s);
    return "crashed (signal " + std::to_string(s) + (name ? std::string(", SIG") + name : std::string()) + ")";
  }
  if (WIFEXITED(status)) return "exited with status " + std::to_string(WEXITSTATUS(status));
  return "ended";
}

void Plugin::start() {
  int pair[2];
  if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, pair) != 0)
    throw PluginError(std::string("cannot start the plugin's process: ") + std::strerror(errno));
  std::fflush(nullptr);  // nothing buffered may be written twice
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(pair[0]);
    ::close(pair[1]);
    throw PluginError(std::string("cannot start the plugin's process: ") + std::strerror(errno));
  }
  if (pid == 0) {
    ::close(pair[0]);
    serve(pair[1], path_, symbol_, kind_);
  }
  ::close(pair[1]);
  socket_ = pair[0];
  child_ = pid;
  std::int32_t status = 0;
  std::uint32_t length = 0;
  const auto deadline = Clock::now() + std::chrono::duration<double>(timeout_);
  const int got = read_all(socket_, &status, sizeof status, std::chrono::time_point_cast<Clock::duration>(deadline));
  if (got != 1) {
    const std::string why = got < 0 ? "timed out after " + seconds(timeout_) + " s" : ended(child_);
    if (got == 0) child_ = -1;  // reaped
    stop();
    throw PluginError("plugin " + path_ + " " + why + " while loading");
  }
  if (read_all(socket_, &length, sizeof length, Clock::time_point::max()) != 1) length = 0;
  std::string why(length, '\0');
  if (length > 0 && read_all(socket_, why.data(), length, Clock::time_point::max()) != 1)
    why = "cannot load plugin " + path_;
  if (status != 0) {
    stop();
    throw PluginError(why);
  }
}

CandidateResult Plugin::operator()(const std::array<double, 12>& x) {
  if (kind_ != PluginKind::theta) throw std::logic_error("Plugin: a bending term is called with x and its rest hinge");
  return call(x.data(), 12);
}

CandidateResult Plugin::operator()(const std::array<double, 12>& x, const std::array<double, 12>& rest) {
  if (kind_ != PluginKind::energy) throw std::logic_error("Plugin: a bend angle is called with x alone");
  double in[24];
  std::copy(x.begin(), x.end(), in);
  std::copy(rest.begin(), rest.end(), in + 12);
  return call(in, 24);
}

CandidateResult Plugin::call(const double* in, std::size_t count) {
  CandidateResult r;
  r.status = CandidateResult::Status::error;
  if (child_ < 0) start();  // after a crash or a time-out
  Answer answer;
  const auto deadline =
      std::chrono::time_point_cast<Clock::duration>(Clock::now() + std::chrono::duration<double>(timeout_));
  int got = write_all(socket_, &kCase, sizeof kCase) && write_all(socket_, in, sizeof(double) * count) ? 1 : 0;
  if (got == 1) got = read_all(socket_, &answer.status, sizeof answer.status, deadline);
  if (got == 1) got = read_all(socket_, answer.out, sizeof answer.out, deadline);
  if (got != 1) {
    if (got < 0) {
      r.error = "timed out after " + seconds(timeout_) + " s";
    } else {
      r.error = ended(child_);
      child_ = -1;  // reaped
    }
    stop();
    return r;
  }
  if (answer.status != 0) {
    r.error = "returned " + std::to_string(answer.status);
    return r;
  }
  r.status = CandidateResult::Status::ok;
  r.theta = answer.out[0];
  std::copy(answer.out + 1, answer.out + 13, r.grad.begin());
  std::copy(answer.out + 13, answer.out + kOutputs, r.hess.begin());
  io::check_finite(r);
  return r;
}

Plugin::Timing Plugin::time(const std::vector<std::array<double, 12>>& hinges, int rounds, PerHinge beside, int repeats,
                            double timeout_seconds) {
  if (kind_ != PluginKind::theta) throw std::logic_error("Plugin: only a bend angle is timed");
  Timing result;
  if (child_ < 0) start();  // after a crash or a time-out
  const TimingRequest request{reinterpret_cast<std::uint64_t>(beside), static_cast<std::uint32_t>(hinges.size()),
                              static_cast<std::uint32_t>(std::max(rounds, 0)),
                              static_cast<std::uint32_t>(std::max(repeats, 1))};
  const auto deadline =
      std::chrono::time_point_cast<Clock::duration>(Clock::now() + std::chrono::duration<double>(timeout_seconds));
  std::int32_t status = 0;
  std::uint32_t count = 0;
  int got = write_all(socket_, &kTime, sizeof kTime) && write_all(socket_, &request, sizeof request) &&
                    write_all(socket_, hinges.data(), sizeof(double) * 12 * hinges.size())
                ? 1
                : 0;
  if (got == 1) got = read_all(socket_, &status, sizeof status, deadline);
  if (got == 1) got = read_all(socket_, &count, sizeof count, deadline);
  std::vector<double> values(count);
  if (got == 1 && count > 0) got = read_all(socket_, values.data(), sizeof(double) * count, deadline);
  if (got != 1) {
    if (got < 0) {
      result.error = "timed out after " + seconds(timeout_seconds) + " s";
    } else {
      result.error = ended(child_);
      child_ = -1;  // reaped
    }
    stop();
    return result;
  }
  if (status != 0) {
    result.error = "returned " + std::to_string(status);
    return result;
  }
  for (std::size_t r = 0; r + 1 < values.size(); r += 2) result.rounds.push_back({values[r], values[r + 1]});
  return result;
}

bool Plugin::fatal(const CandidateResult& r) {
  return r.status == CandidateResult::Status::error &&
         (r.error.rfind("crashed", 0) == 0 || r.error.rfind("timed out", 0) == 0 || r.error.rfind("exited", 0) == 0);
}

}  // namespace hinge::conformance
