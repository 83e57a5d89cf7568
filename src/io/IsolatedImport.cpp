#include "io/IsolatedImport.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/mman.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <thread>

#include "io/AssimpImport.h"
#include "io/ImportWire.h"
#include "io/OwnFile.h"

extern char** environ;  // NOLINT(readability-redundant-declaration): POSIX names it so

namespace termshade {
namespace {

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kSanitized = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kSanitized = true;
#else
constexpr bool kSanitized = false;
#endif
#else
constexpr bool kSanitized = false;
#endif

// Owns a file descriptor.
class Descriptor {
 public:
  explicit Descriptor(int fd = -1) : fd_(fd) {}
  Descriptor(const Descriptor&) = delete;
  Descriptor& operator=(const Descriptor&) = delete;
  Descriptor(Descriptor&& other) noexcept : fd_(other.fd_) { other.fd_ = -1; }
  Descriptor& operator=(Descriptor&&) = delete;
  ~Descriptor() { Reset(); }
  int Get() const { return fd_; }
  void Reset(int fd = -1) {
    if (fd_ >= 0) close(fd_);
    fd_ = fd;
  }
  // Moved to 10 or above (close-on-exec), clear of the child's 0 to 3.
  bool MoveHigh() {
    const int high = fcntl(fd_, F_DUPFD_CLOEXEC, 10);
    if (high < 0) return false;
    Reset(high);
    return true;
  }

 private:
  int fd_;
};

bool WriteAll(int fd, const void* from, size_t size) {
  const auto* bytes = static_cast<const char*>(from);
  while (size > 0) {
    const ssize_t n = write(fd, bytes, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    bytes += n;
    size -= static_cast<size_t>(n);
  }
  return true;
}

bool Cancelled(const LoadOptions& options) {
  return options.cancel != nullptr && options.cancel->load(std::memory_order_relaxed);
}

// The request in an anonymous file, read from its start: the helper's standard input.
Descriptor RequestFile(const ImportSource& source, std::string bytes, const LoadOptions& options) {
  Descriptor file(memfd_create("termshade-import-request", MFD_CLOEXEC));
  if (file.Get() < 0 || !file.MoveHigh()) {
    throw std::runtime_error(std::string("cannot make the import request: ") +
                             std::strerror(errno));
  }
  ImportRequest request;
  request.stamp = ModuleBuildStamp();
  request.source = source;
  request.memoryBudgetBytes = options.memoryBudgetBytes;
  request.bytes = std::move(bytes);
  const WireSink sink = [&](const void* from, size_t size) {
    return WriteAll(file.Get(), from, size);
  };
  const bool written =
      WriteRequestHead(request, sink) && sink(request.bytes.data(), request.bytes.size());
  if (!written || lseek(file.Get(), 0, SEEK_SET) != 0) {
    throw std::runtime_error(std::string("cannot write the import request: ") +
                             std::strerror(errno));
  }
  return file;
}

// The helper started with the request as its standard input, its frames on
// fd 3, its output (and, but in sanitizer builds, its errors) discarded.
pid_t SpawnHelper(const std::string& path, int requestFd, int frameFd, const ImportLimits& limits) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, requestFd, 0);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  if (!kSanitized) posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, frameFd, 3);
  posix_spawn_file_actions_addclosefrom_np(&actions, 4);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  sigset_t none, all;
  sigemptyset(&none);
  sigfillset(&all);
  sigdelset(&all, SIGKILL);
  sigdelset(&all, SIGSTOP);
  posix_spawnattr_setsigmask(&attributes, &none);
  posix_spawnattr_setsigdefault(&attributes, &all);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);
  std::string space = std::to_string(limits.addressSpaceBytes);
  std::string seconds = std::to_string(limits.cpuSeconds);
  std::string program = path;
  char* argv[] = {program.data(), space.data(), seconds.data(), nullptr};
  pid_t pid = -1;
  const int failed = posix_spawn(&pid, path.c_str(), &actions, &attributes, argv, environ);
  posix_spawnattr_destroy(&attributes);
  posix_spawn_file_actions_destroy(&actions);
  if (failed != 0) {
    throw std::runtime_error("cannot start the import helper " + path + ": " +
                             std::strerror(failed));
  }
  return pid;
}

// How the helper ended: its wait status and the processor time it used.
struct Ending {
  int status = 0;
  double cpuSeconds = 0.0;
};

// Waits for the helper, killing it at once when the load is cancelled, or
// once `patience` has passed (a helper that gave its result ends at once).
Ending Reap(pid_t pid, const LoadOptions& options, std::chrono::steady_clock::duration patience) {
  const auto deadline = std::chrono::steady_clock::now() + patience;
  Ending ending;
  rusage usage{};
  for (;;) {
    const pid_t done = wait4(pid, &ending.status, WNOHANG, &usage);
    if (done == pid || (done < 0 && errno != EINTR)) break;
    if (Cancelled(options) || std::chrono::steady_clock::now() > deadline) kill(pid, SIGKILL);
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  const auto seconds = [](timeval t) { return static_cast<double>(t.tv_sec) + t.tv_usec * 1e-6; };
  ending.cpuSeconds = seconds(usage.ru_utime) + seconds(usage.ru_stime);
  return ending;
}

// Why a helper that gave no result ended.
std::string EndingMessage(const Ending& ending, const ImportLimits& limits) {
  const int status = ending.status;
  if (WIFSIGNALED(status)) {
    const int signal = WTERMSIG(status);
    const char* name = sigabbrev_np(signal);
    const std::string which =
        "signal " + std::to_string(signal) + (name != nullptr ? std::string(", SIG") + name : "");
    if (signal == SIGXCPU ||
        (signal == SIGKILL && ending.cpuSeconds >= static_cast<double>(limits.cpuSeconds))) {
      return "the importer was stopped after " + std::to_string(limits.cpuSeconds) +
             " s of processor time without finishing the file (Assimp may loop on it)";
    }
    return "the importer (Assimp) crashed on the file (" + which + "); nothing of it was used";
  }
  return "the import helper ended without a result (exit status " +
         std::to_string(WEXITSTATUS(status)) + ")";
}

// Reads `size` bytes of frames, waiting at most 20 ms at a time so a cancel is seen at once.
bool ReadFrames(int fd, void* to, size_t size, const LoadOptions& options, bool& cancelled) {
  auto* at = static_cast<char*>(to);
  while (size > 0) {
    if (Cancelled(options)) {
      cancelled = true;
      return false;
    }
    pollfd ready{fd, POLLIN, 0};
    const int polled = poll(&ready, 1, 20);
    if (polled < 0 && errno != EINTR) return false;
    if (polled <= 0) continue;
    const ssize_t n = read(fd, at, size);
    if (n < 0 && (errno == EINTR || errno == EAGAIN)) continue;
    if (n <= 0) return false;
    at += n;
    size -= static_cast<size_t>(n);
  }
  return true;
}

}  // namespace

ImportLimits ImportLimitsFor(size_t fileBytes, const LoadOptions& options) {
  constexpr uint64_t kHelperBytes = uint64_t{1} << 30;
  constexpr uint64_t kBaseSeconds = 30;
  ImportLimits limits;
  limits.addressSpaceBytes = options.memoryBudgetBytes + kHelperBytes;
  limits.cpuSeconds = options.importCpuSeconds > 0
                          ? options.importCpuSeconds
                          : kBaseSeconds + static_cast<uint64_t>(fileBytes >> 20);
  return limits;
}

Loaded<Mesh> ImportWithAssimpIsolated(const ImportSource& source, std::string bytes,
                                      const LoadOptions& options) {
  const auto fail = [&](std::string message) {
    return LoadError{source.displayName, 0, 0, std::move(message)};
  };
  // Step 1: the module's file (the helper opens it and names its problems) and the helper.
  if (const OwnFile module = FindOwnFile(kAssimpModuleName, "the Assimp import module");
      module.path.empty()) {
    return fail(module.problem);
  }
  const OwnFile helper = FindOwnFile(kImportHelperName, "the import helper");
  if (helper.path.empty()) return fail(helper.problem);
  // Step 2: the request, the frame pipe and the helper.
  const ImportLimits limits = ImportLimitsFor(bytes.size(), options);
  Descriptor request = RequestFile(source, std::move(bytes), options);
  int ends[2] = {-1, -1};
  if (pipe2(ends, O_CLOEXEC) != 0) {
    throw std::runtime_error(std::string("cannot make a pipe: ") + std::strerror(errno));
  }
  Descriptor frameRead(ends[0]), frameWrite(ends[1]);
  if (!frameRead.MoveHigh() || !frameWrite.MoveHigh()) {
    throw std::runtime_error(std::string("cannot place a pipe: ") + std::strerror(errno));
  }
  const pid_t pid = SpawnHelper(helper.path, request.Get(), frameWrite.Get(), limits);
  request.Reset();
  frameWrite.Reset();
  // Step 3: progress frames, then the result; nothing beyond the budget is taken.
  bool cancelled = false;
  WireReader reader(
      [&](void* to, size_t size) {
        return ReadFrames(frameRead.Get(), to, size, options, cancelled);
      },
      options.memoryBudgetBytes + (uint64_t{1} << 20));
  bool gotResult = false;
  ModuleStatus status = ModuleStatus::kDone;
  std::string exceptionText;
  Loaded<Mesh> result = fail("the importer gave no result");
  for (uint8_t kind = 0; !gotResult && reader.U8(kind);) {
    double share = 0.0;
    if (kind == static_cast<uint8_t>(ImportFrame::kProgress) && reader.F64(share)) {
      if (options.progress && std::isfinite(share)) options.progress(std::clamp(share, 0.0, 1.0));
    } else if (kind == static_cast<uint8_t>(ImportFrame::kResult)) {
      gotResult = ReadResultFrame(reader, status, exceptionText, result);
      break;
    } else {
      break;
    }
  }
  // Step 4: the helper's end (killed at once when cancelled or when its frames were wrong).
  if (cancelled || (!gotResult && !reader.Problem().empty())) kill(pid, SIGKILL);
  frameRead.Reset();
  // Without a result the helper is ending or stopped by its limits.
  const auto patience =
      gotResult ? std::chrono::seconds(10) : std::chrono::seconds(limits.cpuSeconds + 10);
  const Ending ending = Reap(pid, options, patience);
  if (cancelled || Cancelled(options)) return fail("loading cancelled");
  const bool exitedCleanly = WIFEXITED(ending.status) && WEXITSTATUS(ending.status) == 0;
  if (kSanitized && !exitedCleanly && !WIFSIGNALED(ending.status)) {
    throw std::logic_error("the import helper exited with status " +
                           std::to_string(WEXITSTATUS(ending.status)) + " (a sanitizer report?)");
  }
  if (!gotResult) {
    if (!reader.Problem().empty()) {
      return fail("the import helper sent a broken result (" + reader.Problem() + ")");
    }
    if (kSanitized && WIFSIGNALED(ending.status) && WTERMSIG(ending.status) != SIGXCPU &&
        WTERMSIG(ending.status) != SIGKILL) {
      throw std::logic_error("the import helper crashed: " + EndingMessage(ending, limits));
    }
    return fail(EndingMessage(ending, limits));
  }
  RethrowModuleStatus(status, exceptionText);
  return result;
}

}  // namespace termshade
