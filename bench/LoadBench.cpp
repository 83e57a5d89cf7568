#include "LoadBench.h"

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>

#include "FrameTiming.h"
#include "Statistics.h"
#include "geometry/FitCamera.h"
#include "io/load/ModelLoader.h"
#include "io/scenes/SceneGenerators.h"
#include "io/write/MeshExport.h"
#include "raster/Renderer.h"

namespace termshade {
namespace {

using Clock = std::chrono::steady_clock;

/// One run of `termshade render FILE` in a child process.
// The --readers value for Assimp run in the bench's own process, not in its helper.
constexpr const char* kAssimpInProcess = "assimp-in-process";

struct ChildRun {
  bool ok = false;
  double wallSeconds = 0.0;
  double cpuSeconds = 0.0;
  double peakMegabytes = 0.0;
};

ChildRun RunRenderChild(const LoadBenchOptions& options, const std::string& modelPath,
                        const std::string& reader) {
  const std::string size =
      std::to_string(options.widthCells) + "x" + std::to_string(options.heightCells);
  const Clock::time_point start = Clock::now();
  const pid_t pid = fork();
  if (pid == 0) {
    const int devNull = open("/dev/null", O_WRONLY);
    if (devNull >= 0) dup2(devNull, STDOUT_FILENO);
    execl(options.executablePath.c_str(), options.executablePath.c_str(), "render",
          modelPath.c_str(), "--size", size.c_str(), "--reader", reader.c_str(),
          static_cast<char*>(nullptr));
    _exit(127);
  }
  ChildRun run;
  if (pid < 0) return run;
  int status = 0;
  rusage usage{};
  if (wait4(pid, &status, 0, &usage) != pid) return run;
  run.wallSeconds = std::chrono::duration<double>(Clock::now() - start).count();
  run.cpuSeconds = static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
                   static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec) * 1e-6;
  run.peakMegabytes = static_cast<double>(usage.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB
  run.ok = WIFEXITED(status) && WEXITSTATUS(status) == 0;
  return run;
}

/// Where the time of one load goes, in this process: reading the file into a
/// mesh, preparing the scene, and the first frame (cold caches, first
/// allocations), plus the median frame of a turntable after it.
struct Phases {
  bool ok = false;
  double readSeconds = 0.0;
  double prepareSeconds = 0.0;
  double firstFrameMs = 0.0;
  double frameMs = 0.0;
};

double SecondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

Phases MeasurePhases(const LoadBenchOptions& options, const std::string& modelPath,
                     const std::string& reader) {
  Phases phases;
  LoadOptions load;
  load.importerOnly = reader == "assimp" || reader == kAssimpInProcess;
  load.importInProcess = reader == kAssimpInProcess;
  Clock::time_point start = Clock::now();
  Loaded<Mesh> mesh = LoadModelFile(modelPath, load);
  if (!mesh.Ok()) return phases;
  phases.readSeconds = SecondsSince(start);
  start = Clock::now();
  const Scene scene = PrepareScene(std::move(mesh.Value()));
  phases.prepareSeconds = SecondsSince(start);
  DepthBuffer depth;
  CellBuffer cells;
  depth.Resize(options.widthCells, options.heightCells);
  cells.Resize(options.widthCells, options.heightCells);
  RenderOptions render;
  render.keepDepth = false;
  Renderer renderer;
  const Camera camera = FitCamera(scene, DefaultView(scene.diagonalModelUnits), options.widthCells,
                                  options.heightCells, 2.0);
  start = Clock::now();
  renderer.Render(scene, camera, render, depth, cells);
  phases.firstFrameMs = SecondsSince(start) * 1e3;
  phases.frameMs = MedianTurntableFrameMs(scene, options.widthCells, options.heightCells);
  phases.ok = true;
  return phases;
}

/// Runs work() in a forked child and gives back the value it returns (a
/// trivially copyable struct), or nullopt when the child failed. The bench
/// process itself stays small: a child inherits its parent's resident size
/// as the start of its peak (ru_maxrss survives fork and exec), so big
/// allocations here would show in every child's peak.
template <typename Result, typename Work>
std::optional<Result> InChild(Work work) {
  int fds[2];
  if (pipe(fds) != 0) return std::nullopt;
  const pid_t pid = fork();
  if (pid == 0) {
    close(fds[0]);
    const Result result = work();
    const bool written = write(fds[1], &result, sizeof result) == sizeof result;
    _exit(written ? 0 : 1);
  }
  close(fds[1]);
  Result result{};
  const bool got = pid > 0 && read(fds[0], &result, sizeof result) == sizeof result;
  close(fds[0]);
  int status = 0;
  if (pid > 0) waitpid(pid, &status, 0);
  if (!got || !WIFEXITED(status) || WEXITSTATUS(status) != 0) return std::nullopt;
  return result;
}

std::string WriteModel(const std::string& directory, size_t triangles, const std::string& format) {
  std::string path = directory + "/sphere-" + std::to_string(triangles) + "." + format;
  std::error_code error;
  if (std::filesystem::is_regular_file(path, error)) return path;
  const Mesh mesh = GenerateTriangleSphere(triangles);
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << ExportMesh(mesh, *ExportFormatFromPath(path));
  return out ? path : std::string();
}

}  // namespace

int RunLoadBench(const LoadBenchOptions& options) {
  std::string directory = options.directory;
  if (directory.empty()) {
    directory = (std::filesystem::temp_directory_path() / "termshade-bench-load").string();
  }
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error) {
    std::cerr << "termshade bench load: cannot create the models' folder: " << error.message()
              << "\n";
    return 1;
  }
  std::printf(
      "| model | reader | file MB | load + first frame, wall s | CPU s | peak MB | read s | "
      "prepare s | first frame ms | frame ms, %dx%d |\n",
      options.widthCells, options.heightCells);
  std::printf("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n");
  for (const size_t triangles : options.triangleCounts) {
    for (const std::string& format : options.formats) {
      const std::string path = directory + "/sphere-" + std::to_string(triangles) + "." + format;
      const auto written =
          InChild<bool>([&] { return !WriteModel(directory, triangles, format).empty(); });
      if (!written.value_or(false)) {
        std::cerr << "termshade bench load: cannot write a model into the models' folder\n";
        return 1;
      }
      // Readers take turns within each repeat, so both see the same machine.
      const size_t readerCount = options.readers.size();
      std::vector<std::vector<double>> wall(readerCount), cpu(readerCount), peak(readerCount),
          read(readerCount);
      std::vector<bool> failed(readerCount, false);
      for (int r = 0; r < options.repeats; ++r) {
        for (size_t k = 0; k < readerCount; ++k) {
          if (failed[k]) continue;
          const std::string& reader = options.readers[k];
          const auto phases = InChild<Phases>([&] {
            Phases measured;
            LoadOptions load;
            load.importerOnly = reader != "auto";
            load.importInProcess = reader == kAssimpInProcess;
            const Clock::time_point start = Clock::now();
            measured.ok = LoadModelFile(path, load).Ok();
            measured.readSeconds = SecondsSince(start);
            return measured;
          });
          failed[k] = !phases || !phases->ok;
          if (failed[k]) continue;
          read[k].push_back(phases->readSeconds);
          if (reader == kAssimpInProcess) continue;  // render has no such reader
          const ChildRun run = RunRenderChild(options, path, reader);
          failed[k] = !run.ok;  // e.g. over the memory budget: reported in the row
          wall[k].push_back(run.wallSeconds);
          cpu[k].push_back(run.cpuSeconds);
          peak[k].push_back(run.peakMegabytes);
        }
      }
      const double fileMb =
          static_cast<double>(std::filesystem::file_size(path, error)) / (1024.0 * 1024.0);
      for (size_t k = 0; k < readerCount; ++k) {
        const std::string model = std::to_string(triangles / 1000) + "k triangles, " + format;
        const Phases phases =
            failed[k] ? Phases{} : InChild<Phases>([&] {
                                     return MeasurePhases(options, path, options.readers[k]);
                                   }).value_or(Phases{});
        if (failed[k] || !phases.ok) {
          std::printf("| %s | %s | %.0f | failed (see the message above) | | | | | | |\n",
                      model.c_str(), options.readers[k].c_str(), fileMb);
          continue;
        }
        if (wall[k].empty()) {
          std::printf("| %s | %s | %.0f | - | - | - | %.3f | %.2f | %.1f | %.2f |\n", model.c_str(),
                      options.readers[k].c_str(), fileMb, Median(read[k]), phases.prepareSeconds,
                      phases.firstFrameMs, phases.frameMs);
          continue;
        }
        std::printf("| %s | %s | %.0f | %.2f | %.2f | %.0f | %.3f | %.2f | %.1f | %.2f |\n",
                    model.c_str(), options.readers[k].c_str(), fileMb, Median(wall[k]),
                    Median(cpu[k]), Median(peak[k]), Median(read[k]), phases.prepareSeconds,
                    phases.firstFrameMs, phases.frameMs);
      }
      std::fflush(stdout);
    }
  }
  std::printf(
      "\nwall, CPU and peak: medians of %d runs of `termshade render MODEL --size %dx%d --reader "
      "R` (a child process each); read: median of as many loads in-process (assimp: the import "
      "in its helper process; assimp-in-process: in this one, as the fuzzers run it, which render "
      "cannot); prepare and first frame: one load in-process; frame: median of 20 frames "
      "in-process; models in %s\n",
      options.repeats, options.widthCells, options.heightCells, directory.c_str());
  return 0;
}

}  // namespace termshade
