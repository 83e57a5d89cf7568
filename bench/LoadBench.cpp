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

#include "FrameTiming.h"
#include "Statistics.h"
#include "geometry/FitCamera.h"
#include "io/MeshExport.h"
#include "io/ModelLoader.h"
#include "io/SceneGenerators.h"
#include "raster/Renderer.h"

namespace termshade {
namespace {

using Clock = std::chrono::steady_clock;

/// One run of `termshade render FILE` in a child process.
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

/// Median frame time of a turntable at the bench's size, in this process.
double MedianFrameMs(const LoadBenchOptions& options, const std::string& modelPath) {
  Loaded<Mesh> mesh = LoadModelFile(modelPath);
  if (!mesh.Ok()) return -1.0;
  return MedianTurntableFrameMs(PrepareScene(std::move(mesh.Value())), options.widthCells,
                                options.heightCells);
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
      "| model | reader | file MB | load + first frame, wall s | CPU s | peak MB | frame ms, %dx%d "
      "|\n",
      options.widthCells, options.heightCells);
  std::printf("| --- | --- | --- | --- | --- | --- | --- |\n");
  for (const size_t triangles : options.triangleCounts) {
    for (const std::string& format : options.formats) {
      const std::string path = WriteModel(directory, triangles, format);
      if (path.empty()) {
        std::cerr << "termshade bench load: cannot write a model into the models' folder\n";
        return 1;
      }
      // Readers take turns within each repeat, so both see the same machine.
      const size_t readerCount = options.readers.size();
      std::vector<std::vector<double>> wall(readerCount), cpu(readerCount), peak(readerCount);
      for (int r = 0; r < options.repeats; ++r) {
        for (size_t k = 0; k < readerCount; ++k) {
          const ChildRun run = RunRenderChild(options, path, options.readers[k]);
          if (!run.ok) {
            std::cerr << "termshade bench load: rendering " << path << " failed\n";
            return 1;
          }
          wall[k].push_back(run.wallSeconds);
          cpu[k].push_back(run.cpuSeconds);
          peak[k].push_back(run.peakMegabytes);
        }
      }
      const double fileMb =
          static_cast<double>(std::filesystem::file_size(path, error)) / (1024.0 * 1024.0);
      const double frameMs = MedianFrameMs(options, path);
      for (size_t k = 0; k < readerCount; ++k) {
        std::printf("| %zuk triangles, %s | %s | %.0f | %.2f | %.2f | %.0f | %.2f |\n",
                    triangles / 1000, format.c_str(), options.readers[k].c_str(), fileMb,
                    Median(wall[k]), Median(cpu[k]), Median(peak[k]), frameMs);
      }
      std::fflush(stdout);
    }
  }
  std::printf(
      "\nmedians of %d runs of `termshade render MODEL --size %dx%d --reader R` (a child process "
      "each) and of 20 frames in-process; models in %s\n",
      options.repeats, options.widthCells, options.heightCells, directory.c_str());
  return 0;
}

}  // namespace termshade
