#include "TerminalBench.h"

#include <fcntl.h>
#include <poll.h>
#include <pty.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace termshade {
namespace {

// What a terminal answers to DA1 (xterm's VT220 answer).
constexpr std::string_view kDeviceAnswer = "\x1b[?62;22c";
// What the link's sender holds before it stops reading the viewer's pty (and
// the viewer's writes block): sshd's send buffer over a slow link levelled
// off at about a megabyte (issue 31).
constexpr size_t kSenderBufferBytes = 1 << 20;

// Counts the DA1 requests (ESC [ c) in a stream read in pieces.
class RequestCounter {
 public:
  int Count(std::string_view bytes) {
    const std::string text = tail_ + std::string(bytes);
    int found = 0;
    for (size_t at = text.find("\x1b[c"); at != std::string::npos;
         at = text.find("\x1b[c", at + 3)) {
      ++found;
    }
    // Keep what may begin a request cut by the end of this piece.
    tail_ = text.size() >= 2 ? text.substr(text.size() - 2) : text;
    if (tail_.find("\x1b[c") != std::string::npos) tail_.clear();
    return found;
  }

 private:
  std::string tail_;
};

double RealtimeSeconds() {
  timespec now{};
  clock_gettime(CLOCK_REALTIME, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

// The viewer under test, on the master side of a pseudo-terminal.
class PtySession {
 public:
  bool Start(const std::vector<std::string>& argv, int cols, int rows) {
    winsize size{};
    size.ws_col = static_cast<unsigned short>(cols);
    size.ws_row = static_cast<unsigned short>(rows);
    pid_ = forkpty(&master_, nullptr, nullptr, &size);
    if (pid_ < 0) return false;
    if (pid_ == 0) {
      std::vector<char*> args;
      args.reserve(argv.size() + 1);
      for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
      args.push_back(nullptr);
      setenv("TERM", "xterm-256color", 1);
      unsetenv("NO_COLOR");
      execvp(args[0], args.data());
      _exit(127);
    }
    fcntl(master_, F_SETFL, fcntl(master_, F_GETFL) | O_NONBLOCK);
    return true;
  }

  // The child leads its own session (forkpty): the signals reach strace and
  // the viewer under it alike; one that ignores SIGTERM gets SIGKILL after 5 s.
  ~PtySession() {
    if (pid_ > 0) {
      kill(-pid_, SIGTERM);
      for (int waited = 0; waitpid(pid_, nullptr, WNOHANG) == 0; ++waited) {
        if (waited == 500) kill(-pid_, SIGKILL);
        usleep(10000);
      }
    }
    if (master_ >= 0) close(master_);
  }

  void Send(std::string_view keys) {
    [[maybe_unused]] const ssize_t n = write(master_, keys.data(), keys.size());
  }

  /// Answer each DA1 request at once, as a local terminal does.
  void AnswerRequests(bool answer) { answer_ = answer; }

  /// Appends what the viewer wrote that is waiting now; false once the
  /// viewer has closed the terminal (it ended).
  bool ReadAvailable(std::string& out) {
    char buffer[65536];
    for (;;) {
      const ssize_t n = read(master_, buffer, sizeof buffer);
      if (n > 0) {
        out.append(buffer, static_cast<size_t>(n));
        continue;
      }
      return n < 0 && errno == EAGAIN;
    }
  }
  int MasterFd() const { return master_; }

  // Waits up to limitMs for the first output (a sanitizer build under strace
  // on a busy machine can take seconds to start), then reads until quiet.
  long ReadFirstFrame(int quietMs, int limitMs) {
    pollfd fd{master_, POLLIN, 0};
    if (poll(&fd, 1, limitMs) <= 0) return 0;
    return ReadUntilQuiet(quietMs);
  }

  // Reads until the viewer has been quiet for quietMs; returns the bytes read.
  long ReadUntilQuiet(int quietMs, int limitMs = 10000) {
    long total = 0;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(limitMs);
    while (std::chrono::steady_clock::now() < deadline) {
      pollfd fd{master_, POLLIN, 0};
      if (poll(&fd, 1, quietMs) <= 0) break;
      total += Drain();
    }
    return total;
  }

  // Reads for a fixed time, noting when output arrived.
  long ReadFor(double seconds, std::vector<double>* arrivals) {
    long total = 0;
    const double end = RealtimeSeconds() + seconds;
    while (true) {
      const double now = RealtimeSeconds();
      if (now >= end) break;
      pollfd fd{master_, POLLIN, 0};
      if (poll(&fd, 1, static_cast<int>((end - now) * 1000) + 1) <= 0) continue;
      const long n = Drain();
      if (n > 0 && arrivals != nullptr) arrivals->push_back(RealtimeSeconds());
      total += n;
    }
    return total;
  }

  pid_t Pid() const { return pid_; }
  void Wait() {
    waitpid(pid_, nullptr, 0);
    pid_ = -1;
  }

 private:
  long Drain() {
    long total = 0;
    char buffer[65536];
    for (ssize_t n = read(master_, buffer, sizeof buffer); n > 0;
         n = read(master_, buffer, sizeof buffer)) {
      total += n;
      const int requests = answer_ ? requests_.Count({buffer, static_cast<size_t>(n)}) : 0;
      for (int i = 0; i < requests; ++i) Send(kDeviceAnswer);
    }
    return total;
  }

  int master_ = -1;
  bool answer_ = true;
  RequestCounter requests_;
  pid_t pid_ = -1;
};

// Groups times into bursts separated by more than gapSeconds: one burst, one frame.
int CountBursts(const std::vector<double>& times, double gapSeconds) {
  int bursts = 0;
  for (size_t i = 0; i < times.size(); ++i) {
    if (i == 0 || times[i] - times[i - 1] > gapSeconds) ++bursts;
  }
  return bursts;
}

// The gaps between the starts of bursts (frames), in milliseconds.
std::vector<double> BurstPeriodsMs(const std::vector<double>& times, double gapSeconds) {
  std::vector<double> starts, periods;
  for (size_t i = 0; i < times.size(); ++i) {
    if (i == 0 || times[i] - times[i - 1] > gapSeconds) starts.push_back(times[i]);
  }
  for (size_t i = 1; i < starts.size(); ++i) periods.push_back(1e3 * (starts[i] - starts[i - 1]));
  return periods;
}

// The q-quantile (0..1) of values, nearest rank; 0 when empty.
double Quantile(std::vector<double> values, double q) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const auto rank = static_cast<size_t>(q * static_cast<double>(values.size() - 1) + 0.5);
  return values[std::min(rank, values.size() - 1)];
}

// CPU seconds (user + system) a process has used, from /proc.
double ProcessCpuSeconds(pid_t pid) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string text((std::istreambuf_iterator<char>(stat)), std::istreambuf_iterator<char>());
  const size_t close = text.rfind(')');
  if (close == std::string::npos) return -1.0;
  std::istringstream fields(text.substr(close + 2));
  std::string field;
  long utime = 0, stime = 0;
  for (int i = 3; fields >> field; ++i) {
    if (i == 14) utime = std::stol(field);
    if (i == 15) {
      stime = std::stol(field);
      break;
    }
  }
  return static_cast<double>(utime + stime) / static_cast<double>(sysconf(_SC_CLK_TCK));
}

// The viewer's process: the traced child when strace runs it.
pid_t ViewerPid(pid_t sessionPid, bool traced) {
  if (!traced) return sessionPid;
  std::ifstream children("/proc/" + std::to_string(sessionPid) + "/task/" +
                         std::to_string(sessionPid) + "/children");
  pid_t child = -1;
  children >> child;
  return child > 0 ? child : sessionPid;
}

struct TracedWrite {
  double time = 0.0;
  long bytes = 0;
};

// strace -ttt lines: "PID 1700000000.123456 write(1, "..."..., 1234) = 1234".
std::vector<TracedWrite> ReadTrace(const std::string& path) {
  std::vector<TracedWrite> writes;
  std::ifstream log(path);
  for (std::string line; std::getline(log, line);) {
    std::istringstream fields(line);
    long pid = 0;
    double time = 0.0;
    std::string call;
    if (!(fields >> pid >> time >> call)) continue;
    if (call.rfind("write(1,", 0) != 0 && call.rfind("writev(1,", 0) != 0) continue;
    const size_t equals = line.rfind("= ");
    if (equals == std::string::npos) continue;
    writes.push_back({time, std::atol(line.c_str() + equals + 2)});
  }
  return writes;
}

struct Phase {
  double start = 0.0;
  double end = 0.0;
};

void WritesIn(const std::vector<TracedWrite>& writes, const Phase& phase, long& calls, long& bytes,
              std::vector<double>& times) {
  calls = bytes = 0;
  times.clear();
  for (const TracedWrite& w : writes) {
    if (w.time < phase.start || w.time > phase.end) continue;
    ++calls;
    bytes += w.bytes;
    times.push_back(w.time);
  }
}

double Median(std::vector<long> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const size_t mid = values.size() / 2;
  return values.size() % 2 ? static_cast<double>(values[mid])
                           : 0.5 * static_cast<double>(values[mid - 1] + values[mid]);
}

// The viewer behind a throttled link (both ways), the bench the terminal at
// the far end: it answers DA1 requests as they arrive, and notes when the
// viewer's bytes arrive.
class LinkedTerminal {
 public:
  LinkedTerminal(PtySession& session, LinkSpec spec, bool answer)
      : session_(session), down_(spec), up_(spec), spec_(spec), answer_(answer) {}

  /// Keys typed now, at the terminal.
  void Press(std::string_view keys) { up_.Push(RealtimeSeconds(), keys); }
  /// Runs the link until `until` (realtime seconds).
  void RunUntil(double until) {
    while (RealtimeSeconds() < until) Step(until);
  }
  /// Runs until nothing has arrived for quietSeconds (at most limitSeconds);
  /// returns when the last bytes arrived.
  double RunUntilQuiet(double quietSeconds, double limitSeconds) {
    const double start = RealtimeSeconds();
    for (;;) {
      const double now = RealtimeSeconds();
      const double quietFrom = std::max(lastArrival_, start);
      if (now - quietFrom >= quietSeconds || now - start >= limitSeconds) break;
      Step(quietFrom + quietSeconds);
    }
    return lastArrival_;
  }
  /// Runs until the viewer has ended and all it wrote has arrived (at most
  /// limitSeconds); returns then, plus the delay its end takes to cross the
  /// link (ssh's exit message). 0 if it did not end.
  double RunUntilEnded(double limitSeconds) {
    const double start = RealtimeSeconds();
    while (!(ended_ && down_.Empty()) && RealtimeSeconds() - start < limitSeconds) {
      Step(start + limitSeconds);
    }
    if (!ended_ || !down_.Empty()) return 0.0;
    return std::max(lastArrival_, endedAt_ + spec_.delaySeconds);
  }
  long BytesArrived() const { return arrived_; }
  long BytesWritten() const { return written_; }
  long WriteBursts() const { return bursts_; }

 private:
  void Step(double deadline) {
    double now = RealtimeSeconds();
    const bool reading = !ended_ && down_.QueuedBytes() < kSenderBufferBytes;
    if (reading) {
      std::string out;
      if (!session_.ReadAvailable(out)) {
        ended_ = true;
        endedAt_ = now;
      }
      if (!out.empty()) {
        if (now - lastWrite_ > 0.015) ++bursts_;  // one burst, one frame
        lastWrite_ = now;
        written_ += static_cast<long>(out.size());
        down_.Push(now, out);
      }
    }
    if (const std::string arrived = down_.TakeArrived(now); !arrived.empty()) {
      arrived_ += static_cast<long>(arrived.size());
      lastArrival_ = now;
      const int requests = requests_.Count(arrived);
      for (int i = 0; answer_ && i < requests; ++i) up_.Push(now, kDeviceAnswer);
    }
    if (const std::string keys = up_.TakeArrived(now); !keys.empty() && !ended_) {
      session_.Send(keys);
    }
    now = RealtimeSeconds();
    const double next = std::min({down_.NextArrival(), up_.NextArrival(), deadline});
    const int waitMs = static_cast<int>(std::clamp((next - now) * 1000.0 + 0.5, 0.0, 100.0));
    pollfd fd{session_.MasterFd(), POLLIN, 0};
    poll(&fd, reading ? 1 : 0, waitMs);
  }

  PtySession& session_;
  ThrottledLink down_;  ///< viewer to terminal
  ThrottledLink up_;    ///< terminal to viewer
  LinkSpec spec_;
  bool answer_;
  RequestCounter requests_;
  bool ended_ = false;
  double endedAt_ = 0.0;
  double lastArrival_ = 0.0;
  double lastWrite_ = 0.0;
  long arrived_ = 0;
  long written_ = 0;
  long bursts_ = 0;
};

std::string ModeText(const TerminalBenchOptions& options) {
  return "glyphs " + (options.glyphs.empty() ? std::string("picked") : options.glyphs) +
         ", colour " + (options.colour.empty() ? std::string("auto") : options.colour) +
         (options.answer ? "" : ", DA1 never answered");
}

// The link mode: 20 quick presses, the turntable then space, the turntable
// then q, each timed at the terminal's end of the link.
int RunLinkBench(const TerminalBenchOptions& options, const std::vector<std::string>& argv) {
  const LinkSpec spec = *options.link;
  PtySession session;
  if (!session.Start(argv, options.widthCells, options.heightCells)) {
    std::cerr << "termshade bench: cannot open a pseudo-terminal\n";
    return 1;
  }
  LinkedTerminal link(session, spec, options.answer);
  // Step 1: the first frame, then whatever follows a load.
  link.RunUntilQuiet(1.0, 60.0);
  if (link.BytesArrived() == 0) {
    std::cerr << "termshade bench: the viewer drew nothing in 60 s\n";
    return 1;
  }
  if (options.settleSeconds > 0.0) link.RunUntil(RealtimeSeconds() + options.settleSeconds);
  // Step 2: quick presses (xterm's keypad-mode right arrow), 45 ms apart.
  double lastPress = 0.0;
  for (int i = 0; i < options.arrowPresses; ++i) {
    lastPress = RealtimeSeconds();
    link.Press("\x1bOC");
    link.RunUntil(lastPress + 0.045);
  }
  const double settle = std::max(0.0, link.RunUntilQuiet(1.0, 300.0) - lastPress);
  // Step 3: the turntable, then space.
  link.Press(" ");
  const double turnStart = RealtimeSeconds();
  const long arrivedBefore = link.BytesArrived(), writtenBefore = link.BytesWritten();
  const long burstsBefore = link.WriteBursts();
  link.RunUntil(turnStart + options.turntableSeconds);
  const double turnSeconds = RealtimeSeconds() - turnStart;
  const double arrivedRate = static_cast<double>(link.BytesArrived() - arrivedBefore) / turnSeconds;
  const double writtenRate = static_cast<double>(link.BytesWritten() - writtenBefore) / turnSeconds;
  const double frameRate = static_cast<double>(link.WriteBursts() - burstsBefore) / turnSeconds;
  const double spaceAt = RealtimeSeconds();
  link.Press(" ");
  const double stop = std::max(0.0, link.RunUntilQuiet(1.0, 300.0) - spaceAt);
  // Step 4: the turntable again (at most 5 s), then q while it turns, until
  // the viewer has ended and its last bytes arrived.
  link.Press(" ");
  link.RunUntil(RealtimeSeconds() + std::min(5.0, options.turntableSeconds));
  const double quitAt = RealtimeSeconds();
  link.Press("q");
  const double ended = link.RunUntilEnded(300.0);
  session.Wait();

  std::printf(
      "termshade bench terminal: %dx%d cells, %s, TERM=xterm-256color, %s\n", options.widthCells,
      options.heightCells,
      options.modelPath.empty() ? "demo scene (data/sphere_cone.dat)" : options.modelPath.c_str(),
      ModeText(options).c_str());
  std::printf("link: %.0f kbit/s, %.0f ms each way (the bench plays the terminal at its end)\n",
              spec.bytesPerSecond * 8.0 / 1000.0, spec.delaySeconds * 1000.0);
  std::printf("%-46s %10s\n", "measure", "value");
  std::printf("%-46s %10.2f\n", "settle after the last of 20 quick presses, s", settle);
  std::printf("%-46s %10.2f\n", "turntable: frames a second the viewer wrote", frameRate);
  std::printf("%-46s %10.0f\n", "turntable: bytes a second the viewer wrote", writtenRate);
  std::printf("%-46s %10.0f\n", "turntable: bytes a second arriving", arrivedRate);
  std::printf("%-46s %10.2f\n", "turntable keeps turning after space, s", stop);
  if (ended > 0.0) {
    std::printf("%-46s %10.2f\n", "q gives the prompt back, s", ended - quitAt);
  } else {
    std::printf("%-46s %10s\n", "q gives the prompt back, s", "(no end)");
  }
  std::printf(
      "(%d presses 45 ms apart; turntable %.0f s, then space; turntable %.0f s, then q; times "
      "from the key at the terminal to the last byte arriving)\n",
      options.arrowPresses, options.turntableSeconds, std::min(5.0, options.turntableSeconds));
  return ended > 0.0 ? 0 : 1;
}

}  // namespace

int RunTerminalBench(const TerminalBenchOptions& options) {
  std::vector<std::string> viewerArgs{options.viewerPath};
  if (!options.modelPath.empty()) viewerArgs.push_back(options.modelPath);
  if (!options.lod.empty()) viewerArgs.insert(viewerArgs.end(), {"--lod", options.lod});
  if (!options.glyphs.empty()) viewerArgs.insert(viewerArgs.end(), {"--glyphs", options.glyphs});
  if (!options.colour.empty()) viewerArgs.insert(viewerArgs.end(), {"--color", options.colour});
  if (options.link) return RunLinkBench(options, viewerArgs);

  const bool traced = options.traceWrites && std::system("command -v strace >/dev/null 2>&1") == 0;
  char logTemplate[] = "/tmp/termshade-bench-XXXXXX";
  const int logFd = mkstemp(logTemplate);
  if (logFd >= 0) close(logFd);
  const std::string logPath = logTemplate;

  std::vector<std::string> argv;
  if (traced) {
    argv = {"strace", "-f",          "-qq", "-ttt", "-e", "trace=write,writev",
            "-e",     "signal=none", "-o",  logPath};
  }
  argv.insert(argv.end(), viewerArgs.begin(), viewerArgs.end());

  PtySession session;
  session.AnswerRequests(options.answer);
  if (!session.Start(argv, options.widthCells, options.heightCells)) {
    std::cerr << "termshade bench: cannot open a pseudo-terminal\n";
    return 1;
  }
  // Step 1: the first frame.
  const long firstFrameBytes = session.ReadFirstFrame(500, 30000);
  if (firstFrameBytes == 0) {
    std::cerr << "termshade bench: the viewer drew nothing in 30 s\n";
    return 1;
  }
  if (options.settleSeconds > 0.0) session.ReadFor(options.settleSeconds, nullptr);
  // Step 2: arrow keys, one frame each (xterm's keypad-mode right arrow).
  std::vector<long> arrowBytes;
  arrowBytes.reserve(static_cast<size_t>(options.arrowPresses));
  const Phase arrows{RealtimeSeconds(), 0.0};
  for (int i = 0; i < options.arrowPresses; ++i) {
    session.Send("\x1bOC");
    arrowBytes.push_back(session.ReadUntilQuiet(100));
  }
  const Phase arrowsDone{arrows.start, RealtimeSeconds()};
  // Step 2b: a held key: many presses queued before the viewer reads any.
  std::string heldKey;
  for (int i = 0; i < options.heldKeyPresses; ++i) heldKey += "\x1bOC";
  const Phase held{RealtimeSeconds(), 0.0};
  session.Send(heldKey);
  const long heldBytes = session.ReadUntilQuiet(300);
  const Phase heldDone{held.start, RealtimeSeconds()};
  // Step 3: the turntable.
  session.Send(" ");
  std::vector<double> arrivals;
  const Phase turntable{RealtimeSeconds(), 0.0};
  const long turntableBytes = session.ReadFor(options.turntableSeconds, &arrivals);
  const Phase turntableDone{turntable.start, RealtimeSeconds()};
  session.Send(" ");
  session.ReadUntilQuiet(200);
  // Step 4: idle, no input.
  const pid_t viewer = ViewerPid(session.Pid(), traced);
  const double cpuBefore = ProcessCpuSeconds(viewer);
  const long idleBytes = session.ReadFor(options.idleSeconds, nullptr);
  const double idleCpu = ProcessCpuSeconds(viewer) - cpuBefore;
  session.Send("q");
  session.ReadUntilQuiet(300);
  session.Wait();

  // Step 5: the report.
  const int turntableFrames = std::max(1, CountBursts(arrivals, 0.015));
  std::printf(
      "termshade bench terminal: %dx%d cells, %s, TERM=xterm-256color, %s, lod %s\n",
      options.widthCells, options.heightCells,
      options.modelPath.empty() ? "demo scene (data/sphere_cone.dat)" : options.modelPath.c_str(),
      ModeText(options).c_str(), options.lod.empty() ? "default (auto)" : options.lod.c_str());
  std::printf("%-38s %12s\n", "measure", "value");
  std::printf("%-38s %12ld\n", "first frame, bytes", firstFrameBytes);
  std::printf("%-38s %12.0f\n", "per arrow key (median), bytes", Median(arrowBytes));
  std::printf("%-38s %12ld\n", "held key, all presses, bytes", heldBytes);
  std::printf("%-38s %12.0f\n", "per turntable frame (mean), bytes",
              static_cast<double>(turntableBytes) / turntableFrames);
  std::printf("%-38s %12.1f\n", "turntable frames per second",
              turntableFrames / options.turntableSeconds);
  // Pacing: the viewer aims at one frame every 40 ms (25 a second).
  const std::vector<double> periods = BurstPeriodsMs(arrivals, 0.015);
  std::printf("%-38s %5.1f %5.1f %5.1f\n", "turntable period median/p90/max, ms",
              Quantile(periods, 0.5), Quantile(periods, 0.9), Quantile(periods, 1.0));
  if (traced) {
    const std::vector<TracedWrite> writes = ReadTrace(logPath);
    long calls = 0, bytes = 0;
    std::vector<double> times;
    WritesIn(writes, arrowsDone, calls, bytes, times);
    std::printf("%-38s %12.2f\n", "write() calls per arrow-key frame",
                static_cast<double>(calls) / std::max(1, options.arrowPresses));
    WritesIn(writes, heldDone, calls, bytes, times);
    std::printf("%-38s %12ld\n", "held key, frames drawn (write calls)", calls);
    WritesIn(writes, turntableDone, calls, bytes, times);
    const int frames = std::max(1, CountBursts(times, 0.015));
    std::printf("%-38s %12.2f\n", "write() calls per turntable frame",
                static_cast<double>(calls) / frames);
  } else {
    std::printf("%-38s %12s\n", "write() calls per frame", "(no strace)");
  }
  std::printf("%-38s %12ld\n", "idle: bytes written", idleBytes);
  std::printf("%-38s %12.3f\n", "idle: CPU seconds", idleCpu);
  std::printf(
      "(over %.0f s without input; turntable %.0f s; %d arrow presses one by one, "
      "%d queued at once)\n",
      options.idleSeconds, options.turntableSeconds, options.arrowPresses, options.heldKeyPresses);
  std::remove(logPath.c_str());
  return 0;
}

}  // namespace termshade
