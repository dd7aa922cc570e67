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
  int got = write_all(socket_, in, sizeof(double) * count) ? 1 : 0;
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

bool Plugin::fatal(const CandidateResult& r) {
  return r.status == CandidateResult::Status::error &&
         (r.error.rfind("crashed", 0) == 0 || r.error.rfind("timed out", 0) == 0 || r.error.rfind("exited", 0) == 0);
}

}  // namespace hinge::conformance
