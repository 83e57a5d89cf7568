// Model files mapped instead of read: the same bytes and the same mesh as
// read() and as Assimp, and a file that shrinks under its mapping gives a
// clean error, never SIGBUS.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include "geometry/Scene.h"
#include "io/load/FileBytesLoader.h"
#include "io/load/ModelLoader.h"
#include "io/read/BinaryStlReader.h"
#include "io/read/FileBytes.h"
#include "io/read/FileMapGuard.h"
#include "io/read/ObjReader.h"
#include "io/read/OwnReaders.h"
#include "io/scenes/SceneGenerators.h"
#include "io/write/MeshExport.h"
#include "support/TestSupport.h"

namespace termshade {
namespace {

namespace fs = std::filesystem;

const auto kAnySize = [](size_t) -> std::optional<std::string> { return std::nullopt; };

bool SameMesh(const Mesh& a, const Mesh& b) {
  return a.faceCorners == b.faceCorners && a.faceStarts == b.faceStarts &&
         a.upAxisFile == b.upAxisFile && a.verticesFile.size() == b.verticesFile.size() &&
         std::memcmp(a.verticesFile.data(), b.verticesFile.data(),
                     a.verticesFile.size() * sizeof(Vec3)) == 0;
}

TEST(FileBytes, MappedBytesAreTheFile) {
  const test::ScratchFolder folder("termshade-file-bytes");
  const std::string bytes = ExportMesh(GenerateTriangleSphere(2000), ExportFormat::kStl);
  const std::string path = folder.Write("sphere.stl", bytes);
  Loaded<FileBytes> mapped = FileBytes::MapRegularFile(path, kAnySize);
  ASSERT_TRUE(mapped.Ok());
  EXPECT_TRUE(mapped.Value().Mapped());
  EXPECT_EQ(mapped.Value().View(), bytes);
  // Pages handed back read as the file again.
  mapped.Value().Release(0, bytes.size());
  EXPECT_EQ(mapped.Value().View(), bytes);
  EXPECT_FALSE(mapped.Value().Shrank());
  EXPECT_EQ(mapped.Value().TakeString(), bytes);
  EXPECT_EQ(mapped.Value().Size(), 0U);
}

// CopyOut gives the bytes View gives, mapped (pread) or held, in any
// pieces; past the end it gives zeros and marks the bytes Shrank.
TEST(FileBytes, CopyOutGivesTheBytesAndZerosPastTheEnd) {
  const test::ScratchFolder folder("termshade-file-bytes");
  const std::string bytes = ExportMesh(GenerateTriangleSphere(2000), ExportFormat::kStl);
  const std::string path = folder.Write("copied.stl", bytes);
  Loaded<FileBytes> mapped = FileBytes::MapRegularFile(path, kAnySize);
  ASSERT_TRUE(mapped.Ok() && mapped.Value().Mapped());
  FileBytes held(bytes);
  const FileBytes* files[] = {&mapped.Value(), &held};
  for (const FileBytes* file : files) {
    std::string copied(bytes.size(), '?');
    for (size_t at = 0; at < bytes.size(); at += 777) {
      file->CopyOut(at, std::min<size_t>(777, bytes.size() - at), copied.data() + at);
    }
    EXPECT_EQ(copied, bytes) << file->Mapped();
    EXPECT_FALSE(file->Shrank()) << file->Mapped();
    std::string tail(100, '?');
    file->CopyOut(bytes.size() - 50, 100, tail.data());
    EXPECT_EQ(tail, bytes.substr(bytes.size() - 50) + std::string(50, '\0')) << file->Mapped();
    EXPECT_TRUE(file->Shrank()) << file->Mapped();
  }
}

TEST(FileBytes, EmptyFilesAndFoldersAreReadNotMapped) {
  const test::ScratchFolder folder("termshade-file-bytes");
  Loaded<FileBytes> empty = FileBytes::MapRegularFile(folder.Write("empty.stl", ""), kAnySize);
  ASSERT_TRUE(empty.Ok());
  EXPECT_EQ(empty.Value().Size(), 0U);
  Loaded<FileBytes> dir = FileBytes::MapRegularFile(fs::temp_directory_path().string(), kAnySize);
  ASSERT_FALSE(dir.Ok());
  EXPECT_NE(dir.Error().message.find("folder"), std::string::npos);
}

// Every format our readers take, from a mapping, equals the read() path and
// the importer's mesh.
TEST(FileBytes, MappedLoadGivesTheSameMeshAsReadAndAsAssimp) {
  const test::ScratchFolder folder("termshade-file-bytes");
  const Mesh sphere = GenerateTriangleSphere(20'000);
  for (const auto& [format, exportFormat] :
       {std::pair{"obj", ExportFormat::kObj}, std::pair{"stl", ExportFormat::kStl},
        std::pair{"ply", ExportFormat::kPly}}) {
    const std::string bytes = ExportMesh(sphere, exportFormat);
    const std::string path = folder.Write(std::string("sphere.") + format, bytes);
    Loaded<Mesh> mapped = LoadModelFile(path);
    LoadOptions fromString;
    fromString.formatHint = format;
    Loaded<Mesh> read = LoadModelBytes(bytes, path, fromString);
    LoadOptions reference;
    reference.importerOnly = true;
    Loaded<Mesh> imported = LoadModelFile(path, reference);
    ASSERT_TRUE(mapped.Ok() && read.Ok() && imported.Ok()) << format;
    EXPECT_TRUE(SameMesh(mapped.Value(), read.Value())) << format;
    const Scene a = PrepareScene(std::move(mapped.Value()));
    const Scene b = PrepareScene(std::move(imported.Value()));
    EXPECT_EQ(test::RenderFrame(a, 0.3, 1.3, 60, 20, RenderOptions{}).Text(),
              test::RenderFrame(b, 0.3, 1.3, 60, 20, RenderOptions{}).Text())
        << format;
  }
}

// The file cut to half its size after it was mapped: the reader sees zeros
// past the new end instead of SIGBUS (PLY, read through the mapping), or a
// short pread (binary STL), and the load is refused.
TEST(FileBytes, FileShrunkUnderTheMappingIsACleanError) {
  const test::ScratchFolder folder("termshade-file-bytes");
  const std::string bytes = ExportMesh(GenerateTriangleSphere(20'000), ExportFormat::kStl);
  for (const char* name : {"cut.stl", "cut_loader.stl"}) {
    const std::string path = folder.Write(name, bytes);
    Loaded<FileBytes> mapped = FileBytes::MapRegularFile(path, kAnySize);
    ASSERT_TRUE(mapped.Ok());
    ASSERT_TRUE(mapped.Value().Mapped());
    ASSERT_EQ(truncate(path.c_str(), static_cast<off_t>(bytes.size() / 2)), 0);
    if (std::string(name) == "cut.stl") {
      FileBytes& file = mapped.Value();
      auto read = ReadWithOwnReader(file.View(), "stl", path, size_t{1} << 30, &file);
      EXPECT_TRUE(read.has_value());
      EXPECT_TRUE(file.Shrank());
    } else {
      Loaded<Mesh> mesh = LoadModelFileBytes(std::move(mapped.Value()), path);
      ASSERT_FALSE(mesh.Ok());
      EXPECT_NE(mesh.Error().ToString().find("cut_loader.stl: the file changed while it was "
                                             "read, or a part of it could not be read"),
                std::string::npos)
          << mesh.Error().ToString();
    }
  }
  const std::string ply = ExportMesh(GenerateTriangleSphere(20'000), ExportFormat::kPly);
  const std::string path = folder.Write("cut_loader.ply", ply);
  Loaded<FileBytes> mapped = FileBytes::MapRegularFile(path, kAnySize);
  ASSERT_TRUE(mapped.Ok() && mapped.Value().Mapped());
  ASSERT_EQ(truncate(path.c_str(), static_cast<off_t>(ply.size() / 2)), 0);
  Loaded<Mesh> mesh = LoadModelFileBytes(std::move(mapped.Value()), path);
  ASSERT_FALSE(mesh.Ok());
  EXPECT_NE(mesh.Error().ToString().find("cut_loader.ply: the file changed while it was read, or "
                                         "a part of it could not be read"),
            std::string::npos)
      << mesh.Error().ToString();
}

// The same on the load threads: a STL welded in 4 runs and an OBJ read in 4
// chunks, cut so that the runs and chunks past the cut fault on threads the
// reader started (a fault blocked there would end the process).
TEST(FileBytes, FileShrunkUnderTheMappingOnLoadThreadsIsACleanError) {
  const test::ScratchFolder folder("termshade-file-bytes");
  const Mesh sphere = GenerateTriangleSphere(20'000);
  const std::string stl = ExportMesh(sphere, ExportFormat::kStl);
  const std::string obj = ExportMesh(sphere, ExportFormat::kObj);
  {
    const std::string path = folder.Write("cut_parts.stl", stl);
    Loaded<FileBytes> mapped = FileBytes::MapRegularFile(path, kAnySize);
    ASSERT_TRUE(mapped.Ok() && mapped.Value().Mapped());
    ASSERT_EQ(truncate(path.c_str(), static_cast<off_t>(stl.size() / 2)), 0);
    FileBytes& file = mapped.Value();
    [[maybe_unused]] Loaded<Mesh> read = ReadBinaryStlInParts(file.View(), path, 4, &file);
    EXPECT_TRUE(file.Shrank());
  }
  {
    // Cut past the last chunk's start: the chunk boundaries are found in the
    // file's bytes, the lost pages first read by the last chunk's thread.
    const std::string path = folder.Write("cut_chunks.obj", obj);
    Loaded<FileBytes> mapped = FileBytes::MapRegularFile(path, kAnySize);
    ASSERT_TRUE(mapped.Ok() && mapped.Value().Mapped());
    ASSERT_EQ(truncate(path.c_str(), static_cast<off_t>(obj.size() / 10 * 8)), 0);
    FileBytes& file = mapped.Value();
    std::optional<Loaded<Mesh>> read =
        ReadObjInChunks(file.View(), path, size_t{1} << 30, 4, &file);
    EXPECT_TRUE(file.Shrank());
    ASSERT_TRUE(read.has_value());
    EXPECT_FALSE(read->Ok());
  }
}

// Changes that raise no SIGBUS: the file cut inside its last page, and a
// rewrite that keeps the size (its times change): the load is refused.
TEST(FileBytes, FileChangedWithoutLosingAPageIsAnError) {
  const test::ScratchFolder folder("termshade-file-bytes");
  const Mesh sphere = GenerateTriangleSphere(20'000);
  const auto pageBytes = static_cast<size_t>(sysconf(_SC_PAGESIZE));
  for (const auto& [name, format] : {std::pair{"cut_in_page.stl", ExportFormat::kStl},
                                     std::pair{"cut_in_page.obj", ExportFormat::kObj},
                                     std::pair{"cut_in_page.ply", ExportFormat::kPly}}) {
    const std::string bytes = ExportMesh(sphere, format);
    constexpr size_t kCut = 10;
    ASSERT_GT(bytes.size() % pageBytes, kCut) << name;  // the last page stays
    const std::string path = folder.Write(name, bytes);
    Loaded<FileBytes> mapped = FileBytes::MapRegularFile(path, kAnySize);
    ASSERT_TRUE(mapped.Ok() && mapped.Value().Mapped());
    ASSERT_EQ(truncate(path.c_str(), static_cast<off_t>(bytes.size() - kCut)), 0);
    Loaded<Mesh> mesh = LoadModelFileBytes(std::move(mapped.Value()), path);
    ASSERT_FALSE(mesh.Ok()) << name;
    const std::string expected = std::string(name) + ": the file changed while it was read";
    EXPECT_NE(mesh.Error().ToString().find(expected), std::string::npos) << mesh.Error().ToString();
  }
  const std::string bytes = ExportMesh(sphere, ExportFormat::kStl);
  const std::string path = folder.Write("rewritten.stl", bytes);
  Loaded<FileBytes> mapped = FileBytes::MapRegularFile(path, kAnySize);
  ASSERT_TRUE(mapped.Ok() && mapped.Value().Mapped());
  const timespec older[2] = {{1'000'000'000, 0}, {1'000'000'000, 0}};
  ASSERT_EQ(utimensat(AT_FDCWD, path.c_str(), older, 0), 0);
  Loaded<Mesh> mesh = LoadModelFileBytes(std::move(mapped.Value()), path);
  ASSERT_FALSE(mesh.Ok());
  EXPECT_NE(mesh.Error().ToString().find("rewritten.stl: the file changed while it was read"),
            std::string::npos)
      << mesh.Error().ToString();
}

// Writes bytes at the start of a mapping's private first page: what the
// next read of that page sees until the page is handed back.
bool WriteIntoFirstPage(FileBytes& file, std::string_view bytes) {
  void* firstPage = const_cast<char*>(file.View().data());
  const auto pageBytes = static_cast<size_t>(sysconf(_SC_PAGESIZE));
  if (mprotect(firstPage, pageBytes, PROT_READ | PROT_WRITE) != 0) return false;
  std::memcpy(firstPage, bytes.data(), bytes.size());
  return mprotect(firstPage, pageBytes, PROT_READ) == 0;
}

// An OBJ whose first page reads differently in the two passes (the page,
// written to in the private mapping, holds an extra face line for the counts;
// the counting pass hands it back, so the geometry pass reads the file's
// comment there): fewer entries than counted are an error, never merged.
TEST(FileBytes, ObjThatLosesAFaceBetweenThePassesIsAnError) {
  const test::ScratchFolder folder("termshade-file-bytes");
  const std::string body = ExportMesh(GenerateTriangleSphere(300'000), ExportFormat::kObj);
  ASSERT_GT(body.size(), size_t{5} << 20);  // past the first pass's 4 MiB hand-back
  const std::string path = folder.Write("changed.obj", "#" + std::string(15, ' ') + "\n" + body);
  Loaded<FileBytes> mapped = FileBytes::MapRegularFile(path, kAnySize);
  ASSERT_TRUE(mapped.Ok() && mapped.Value().Mapped());
  FileBytes& file = mapped.Value();
  ASSERT_TRUE(WriteIntoFirstPage(file, "f 1 2 3"));
  std::optional<Loaded<Mesh>> read = ReadObjInChunks(file.View(), path, size_t{1} << 30, 1, &file);
  ASSERT_TRUE(read.has_value());
  ASSERT_FALSE(read->Ok());
  EXPECT_NE(read->Error().ToString().find("changed.obj: the file changed while it was read"),
            std::string::npos)
      << read->Error().ToString();
}

// The other way round: the first pass reads a comment where the file has a
// vertex, so the geometry pass finds one vertex more than was counted: the
// write past the counts is refused at its line, never made.
TEST(FileBytes, ObjThatGainsAVertexBetweenThePassesIsAnError) {
  const test::ScratchFolder folder("termshade-file-bytes");
  const std::string body = ExportMesh(GenerateTriangleSphere(300'000), ExportFormat::kObj);
  const std::string path = folder.Write("gained.obj", "v 0 0 0\n" + body);
  Loaded<FileBytes> mapped = FileBytes::MapRegularFile(path, kAnySize);
  ASSERT_TRUE(mapped.Ok() && mapped.Value().Mapped());
  FileBytes& file = mapped.Value();
  ASSERT_TRUE(WriteIntoFirstPage(file, "#"));
  std::optional<Loaded<Mesh>> read = ReadObjInChunks(file.View(), path, size_t{1} << 30, 1, &file);
  ASSERT_TRUE(read.has_value());
  ASSERT_FALSE(read->Ok());
  const std::string message = read->Error().ToString();
  EXPECT_NE(message.find("gained.obj:"), std::string::npos) << message;
  EXPECT_NE(message.find(":1: the file changed while it was read"), std::string::npos) << message;
}

// A SIGBUS outside every watched mapping still ends the process (by the
// signal, or by the handler that was there before, such as a sanitizer's).
TEST(FileBytesDeathTest, ForeignBusErrorsStillEndTheProcess) {
  const test::ScratchFolder folder("termshade-file-bytes");
  const std::string path = folder.Write("foreign.bin", std::string(1 << 16, 'x'));
  EXPECT_DEATH(
      {
        const int watch = WatchMappedRange(nullptr, 0);  // installs the handler
        StopWatchingMappedRange(watch);
        std::FILE* file = std::fopen(path.c_str(), "rb");
        void* mapped = mmap(nullptr, 1 << 16, PROT_READ, MAP_PRIVATE, fileno(file), 0);
        [[maybe_unused]] const int cut = truncate(path.c_str(), 0);
        const volatile char* bytes = static_cast<const char*>(mapped);
        [[maybe_unused]] const char byte = bytes[100];
        std::exit(0);
      },
      "");
}

// A SIGBUS sent to the process (kill, raise), not a fault, is no watched
// page's: with the default action before the guard, it still ends the
// process; ignored before the guard, it stays ignored and the guard stays.
TEST(FileBytesDeathTest, SentBusErrorsKeepThePreviousAction) {
  EXPECT_DEATH(
      {
        signal(SIGBUS, SIG_DFL);
        StopWatchingMappedRange(WatchMappedRange(nullptr, 0));  // installs the guard
        raise(SIGBUS);
        std::exit(0);
      },
      "");
  EXPECT_EXIT(
      {
        signal(SIGBUS, SIG_IGN);
        StopWatchingMappedRange(WatchMappedRange(nullptr, 0));
        raise(SIGBUS);
        struct sigaction after {};
        sigaction(SIGBUS, nullptr, &after);
        std::exit(after.sa_handler == SIG_DFL ? 1 : 0);
      },
      testing::ExitedWithCode(0), "");
}

}  // namespace
}  // namespace termshade
