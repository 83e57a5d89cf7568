#include "io/import/IsolatedImport.h"

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
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <thread>

#include "io/import/AssimpModule.h"
#include "io/import/ImportWire.h"
#include "io/import/OwnFile.h"
#include "io/import/WholeTransfer.h"
#include "io/read/FileDescriptor.h"
#include "io/read/LoadBudget.h"

extern char** environ;  // NOLINT(readability-redundant-declaration): POSIX names it so

namespace termshade {
namespace {

constexpr bool kSanitized = kAddressSanitizerBuild;

// fd moved to 10 or above (close-on-exec), clear of the child's 0 to 3.
bool MoveHigh(FileDescriptor& fd) {
  const int high = fcntl(fd.Get(), F_DUPFD_CLOEXEC, 10);
  if (high < 0) return false;
  fd.Reset(high);
  return true;
}

bool Cancelled(const LoadOptions& options) {
  return options.cancel != nullptr && options.cancel->load(std::memory_order_relaxed);
}

// The request in an anonymous file, read from its start: the helper's standard input.
FileDescriptor RequestFile(const ImportSource& source, std::string bytes,
                           const LoadOptions& options) {
  FileDescriptor file(memfd_create("termshade-import-request", MFD_CLOEXEC));
  if (file.Get() < 0 || !MoveHigh(file)) {
    throw std::runtime_error(std::string("cannot make the import request: ") +
                             std::strerror(errno));
  }
  ImportRequest request;
  request.stamp = ModuleBuildStamp();
  request.source = source;
  request.memoryBudgetBytes = options.memoryBudgetBytes;
  request.bytes = std::move(bytes);
  const WireSink sink = [&](const void* from, size_t size) {
    return WriteWhole(file.Get(), from, size);
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
  // Its own session: no controlling terminal, no Ctrl-C from it, and one
  // process group to kill with whatever it may start.
  posix_spawnattr_setflags(&attributes,
                           POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSID);
  std::string space = std::to_string(limits.addressSpaceBytes);
  std::string data = std::to_string(limits.dataBytes);
  std::string seconds = std::to_string(limits.cpuSeconds);
  std::string parent = std::to_string(getpid());
  std::string program = path;
  char* argv[] = {program.data(), space.data(),  data.data(),
                  seconds.data(), parent.data(), nullptr};
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
  bool statusRead = true;  ///< false: reaped by someone else (SIGCHLD ignored)
};

// The running helper: killed (its whole process group) and reaped when
// left, whatever the way out.
class HelperProcess {
 public:
  explicit HelperProcess(pid_t pid) : pid_(pid) {}
  HelperProcess(const HelperProcess&) = delete;
  HelperProcess& operator=(const HelperProcess&) = delete;
  ~HelperProcess() {
    if (reaped_) return;
    Kill();
    int status = 0;
    while (waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
    }
  }
  void Kill() const {
    kill(-pid_, SIGKILL);
    kill(pid_, SIGKILL);
  }
  // Waits for its end, killing it at once when the load is cancelled, or
  // once `patience` has passed (a helper that gave its result ends at once).
  Ending Reap(const LoadOptions& options, std::chrono::steady_clock::duration patience) {
    const auto deadline = std::chrono::steady_clock::now() + patience;
    Ending ending;
    rusage usage{};
    // Its end seen without reaping it, so its group is killed while its id is still taken.
    for (;;) {
      siginfo_t info{};
      const int waited = waitid(P_PID, static_cast<id_t>(pid_), &info, WEXITED | WNOHANG | WNOWAIT);
      if ((waited == 0 && info.si_pid == pid_) || (waited < 0 && errno != EINTR)) break;
      if (Cancelled(options) || std::chrono::steady_clock::now() > deadline) Kill();
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    kill(-pid_, SIGKILL);  // anything it left behind in its group
    int reaped = 0;
    while ((reaped = wait4(pid_, &ending.status, 0, &usage)) < 0 && errno == EINTR) {
    }
    ending.statusRead = reaped == pid_;
    reaped_ = true;
    const auto seconds = [](timeval t) {
      return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_usec) * 1e-6;
    };
    ending.cpuSeconds = seconds(usage.ru_utime) + seconds(usage.ru_stime);
    return ending;
  }

 private:
  pid_t pid_;
  bool reaped_ = false;
};

// Why a helper that gave no result ended.
std::string EndingMessage(const Ending& ending, const ImportLimits& limits) {
  if (!ending.statusRead) {
    return "the import helper ended without a result; how it ended could not be read (does "
           "this process ignore SIGCHLD?)";
  }
  const int status = ending.status;
  if (WIFSIGNALED(status)) {
    const int signal = WTERMSIG(status);
    const char* name = sigabbrev_np(signal);
    const std::string which =
        "signal " + std::to_string(signal) + (name != nullptr ? std::string(", SIG") + name : "");
    if (signal == SIGXCPU ||
        (signal == SIGKILL && ending.cpuSeconds >= static_cast<double>(limits.cpuSeconds))) {
      return "the importer was stopped after " + std::to_string(limits.cpuSeconds) +
             " s of processor time without finishing the file (Assimp may loop on it; "
             "--import-seconds or TERMSHADE_IMPORT_SECONDS sets the limit)";
    }
    return "the importer (Assimp) crashed on the file (" + which + "); nothing of it was used";
  }
  return "the import helper ended without a result (exit status " +
         std::to_string(WEXITSTATUS(status)) + ")";
}

// The helper's frames as the wire reader takes them: waiting at most 20 ms
// at a time, so a cancel is seen at once, and no longer than the deadline
// (a helper that blocks uses no processor time, so its limit never comes).
struct FrameSource {
  int fd;
  const LoadOptions& options;
  std::chrono::steady_clock::time_point deadline;
  bool cancelled = false;
  bool timedOut = false;

  bool Read(void* to, size_t size) {
    auto* at = static_cast<char*>(to);
    while (size > 0) {
      if (Cancelled(options)) {
        cancelled = true;
        return false;
      }
      if (std::chrono::steady_clock::now() > deadline) {
        timedOut = true;
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
};

// In sanitizer builds a helper that failed (a sanitizer report: its exit
// status, or a crash) ends this process too, so that tests see it.
[[noreturn]] void SanitizedHelperFailed(const std::string& what) {
  std::fprintf(stderr, "termshade: %s\n", SanitizeForTerminal(what).c_str());
  std::abort();
}

}  // namespace

ImportLimits ImportLimitsFor(size_t fileBytes, const LoadOptions& options) {
  constexpr uint64_t kHelperBytes = uint64_t{1} << 30;
  constexpr uint64_t kBaseSeconds = 30;
  ImportLimits limits;
  limits.addressSpaceBytes = options.memoryBudgetBytes + kHelperBytes;
  limits.dataBytes = options.memoryBudgetBytes + kHelperDataBytes;
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
  FileDescriptor request = RequestFile(source, std::move(bytes), options);
  int ends[2] = {-1, -1};
  if (pipe2(ends, O_CLOEXEC) != 0) {
    throw std::runtime_error(std::string("cannot make a pipe: ") + std::strerror(errno));
  }
  FileDescriptor frameRead(ends[0]), frameWrite(ends[1]);
  if (!MoveHigh(frameRead) || !MoveHigh(frameWrite)) {
    throw std::runtime_error(std::string("cannot place a pipe: ") + std::strerror(errno));
  }
  HelperProcess child(SpawnHelper(helper.path, request.Get(), frameWrite.Get(), limits));
  request.Reset();
  frameWrite.Reset();
  // Step 3: progress frames, then the result; nothing beyond the budget is
  // taken, nothing later than twice the processor limit and 10 s waited for.
  const auto waitLimit = std::chrono::seconds(2 * limits.cpuSeconds + 10);
  FrameSource frames{frameRead.Get(), options, std::chrono::steady_clock::now() + waitLimit};
  WireReader reader([&](void* to, size_t size) { return frames.Read(to, size); },
                    options.memoryBudgetBytes + (uint64_t{1} << 20));
  bool gotResult = false;
  ModuleStatus status = ModuleStatus::kDone;
  std::string exceptionText;
  Loaded<Mesh> result = fail("the importer gave no result");
  for (uint8_t kind = 0; !gotResult && reader.U8(kind);) {
    double share = 0.0;
    if (kind == static_cast<uint8_t>(ImportFrame::kProgress)) {
      if (!reader.F64(share)) break;
      if (options.progress && std::isfinite(share)) options.progress(std::clamp(share, 0.0, 1.0));
    } else if (kind == static_cast<uint8_t>(ImportFrame::kResult)) {
      gotResult = ReadResultFrame(reader, status, exceptionText, result);
      break;
    } else {
      reader.Refuse("a frame of an unknown kind");
      break;
    }
  }
  // Step 4: the helper's end (killed at once when cancelled, late, or its frames were wrong).
  if (frames.cancelled || frames.timedOut || (!gotResult && !reader.Problem().empty())) {
    child.Kill();
  }
  frameRead.Reset();
  // Without a result the helper is ending or stopped by its limits.
  const Ending ending = child.Reap(options, gotResult ? std::chrono::seconds(10) : waitLimit);
  if (frames.cancelled || Cancelled(options)) return fail("loading cancelled");
  if (frames.timedOut) {
    return fail("the importer gave no result within " + std::to_string(waitLimit.count()) +
                " s and was stopped");
  }
  if (kSanitized && !WIFSIGNALED(ending.status) && WEXITSTATUS(ending.status) != 0) {
    SanitizedHelperFailed("the import helper exited with status " +
                          std::to_string(WEXITSTATUS(ending.status)) + " (a sanitizer report?)");
  }
  if (!gotResult) {
    if (!reader.Problem().empty()) {
      return fail("the import helper sent a broken result (" + reader.Problem() + ")");
    }
    if (kSanitized && WIFSIGNALED(ending.status) && WTERMSIG(ending.status) != SIGXCPU &&
        WTERMSIG(ending.status) != SIGKILL) {
      SanitizedHelperFailed("the import helper crashed: " + EndingMessage(ending, limits));
    }
    return fail(EndingMessage(ending, limits));
  }
  RethrowModuleStatus(status, exceptionText);
  // Step 5: the mesh's size against the budget, as the import checks it in-process.
  if (result.Ok()) {
    const Mesh& mesh = result.Value();
    const auto needed = static_cast<double>(
        EstimateMeshBytes(mesh.verticesFile.size(), mesh.faceCorners.size(), mesh.FaceCount()));
    if (needed > static_cast<double>(options.memoryBudgetBytes)) {
      return fail(OverBudgetMessage(needed, options.memoryBudgetBytes));
    }
  }
  return result;
}

}  // namespace termshade
