// Assimp in the import helper (io/import/IsolatedImport.h): the same meshes as in
// this process, an importer that loops stopped by its processor limit or at
// once by a cancel, one that asks for too much memory refused, and the wire
// between them checked (io/import/ImportWire.h).
#include <signal.h>

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <thread>

#include "io/import/ImportWire.h"
#include "io/import/IsolatedImport.h"
#include "io/import/WholeTransfer.h"
#include "io/load/ModelLoader.h"
#include "support/TestSupport.h"

namespace termshade {
namespace {

using test::SourcePath;

// Assimp 5.2's PLY importer loops forever on a header without end_header (the
// loader refuses such content before the importer sees it; called directly here).
const std::string kLoopingPly = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n";

ImportSource Unnamed(const std::string& name, const std::string& format) {
  ImportSource source;
  source.displayName = name;
  source.importName = "/standard-input." + format;
  source.format = format;
  return source;
}

void ExpectSameMesh(const Mesh& a, const Mesh& b, const std::string& model) {
  EXPECT_EQ(a.name, b.name) << model;
  EXPECT_EQ(a.verticesFile.size(), b.verticesFile.size()) << model;
  for (size_t i = 0; i < std::min(a.verticesFile.size(), b.verticesFile.size()); ++i) {
    ASSERT_TRUE(a.verticesFile[i] == b.verticesFile[i]) << model << " vertex " << i;
  }
  EXPECT_EQ(a.faceCorners, b.faceCorners) << model;
  EXPECT_EQ(a.faceStarts, b.faceStarts) << model;
  EXPECT_EQ(a.edgeHidden, b.edgeHidden) << model;
  EXPECT_EQ(a.segments, b.segments) << model;
  EXPECT_TRUE(a.faceColors == b.faceColors) << model;
  EXPECT_EQ(a.upAxisFile, b.upAxisFile) << model;
}

TEST(IsolatedImport, GivesTheMeshesOfTheImporterInThisProcess) {
  for (const char* model :
       {"tests/models/real/wuson_inside_out.off", "tests/models/real/vase_y_up.gltf",
        "tests/models/good/triangle_external_buffer.gltf", "tests/models/real/spider_y_up.obj",
        "tests/models/good/two_colours_from_mtl.obj", "tests/models/good/vertex_colours.obj"}) {
    LoadOptions inProcess, isolated;
    inProcess.importerOnly = isolated.importerOnly = true;
    inProcess.importInProcess = true;
    int progressCalls = 0;
    isolated.progress = [&](double share) {
      EXPECT_GE(share, 0.0);
      EXPECT_LE(share, 1.0);
      ++progressCalls;
    };
    Loaded<Mesh> expected = LoadModelFile(SourcePath(model), inProcess);
    Loaded<Mesh> got = LoadModelFile(SourcePath(model), isolated);
    ASSERT_TRUE(expected.Ok()) << expected.Error().ToString();
    ASSERT_TRUE(got.Ok()) << got.Error().ToString();
    ExpectSameMesh(got.Value(), expected.Value(), model);
    EXPECT_GT(progressCalls, 0) << model;
  }
}

TEST(IsolatedImport, BadFilesGetTheSameMessages) {
  for (const char* model : {"tests/models/bad/ply_face_index_out_of_range.ply",
                            "tests/models/bad/raw_null_child_node.raw",
                            "tests/models/bad/png_image_without_extension"}) {
    LoadOptions inProcess, isolated;
    inProcess.importerOnly = isolated.importerOnly = true;
    inProcess.importInProcess = true;
    Loaded<Mesh> expected = LoadModelFile(SourcePath(model), inProcess);
    Loaded<Mesh> got = LoadModelFile(SourcePath(model), isolated);
    ASSERT_FALSE(expected.Ok()) << model;
    ASSERT_FALSE(got.Ok()) << model;
    EXPECT_EQ(got.Error().ToString(), expected.Error().ToString());
  }
}

TEST(IsolatedImport, ALoopingImporterIsStoppedByItsProcessorLimit) {
  LoadOptions options;
  options.importCpuSeconds = 1;
  Loaded<Mesh> mesh = ImportWithAssimpIsolated(Unnamed("loop.ply", "ply"), kLoopingPly, options);
  ASSERT_FALSE(mesh.Ok());
  EXPECT_EQ(mesh.Error().ToString(),
            "loop.ply: the importer was stopped after 1 s of processor time without finishing "
            "the file (Assimp may loop on it; --import-seconds or TERMSHADE_IMPORT_SECONDS sets "
            "the limit)");
}

TEST(IsolatedImport, AnEndNobodyCouldReadIsSaidSoNotGuessed) {
  // SIGCHLD ignored: the kernel reaps the helper, and its status is lost.
  struct sigaction ignore {
  }, saved{};
  ignore.sa_handler = SIG_IGN;
  sigaction(SIGCHLD, &ignore, &saved);
  LoadOptions options;
  options.importCpuSeconds = 1;
  Loaded<Mesh> mesh = ImportWithAssimpIsolated(Unnamed("loop.ply", "ply"), kLoopingPly, options);
  sigaction(SIGCHLD, &saved, nullptr);
  ASSERT_FALSE(mesh.Ok());
  EXPECT_EQ(mesh.Error().ToString(),
            "loop.ply: the import helper ended without a result; how it ended could not be read "
            "(does this process ignore SIGCHLD?)");
}

TEST(IsolatedImport, TheProcessorLimitComesFromTheEnvironment) {
  const char* saved = std::getenv("TERMSHADE_IMPORT_SECONDS");
  const std::string kept = saved != nullptr ? saved : "";
  const std::pair<const char*, uint32_t> cases[] = {
      {"5", 5}, {"86400", 86400}, {"86401", 0}, {"0", 0}, {"-3", 0}, {"7s", 0}, {"", 0}};
  for (const auto& [text, seconds] : cases) {
    setenv("TERMSHADE_IMPORT_SECONDS", text, 1);
    EXPECT_EQ(DefaultImportCpuSeconds(), seconds) << text;
    EXPECT_EQ(LoadOptions{}.importCpuSeconds, seconds) << text;
  }
  unsetenv("TERMSHADE_IMPORT_SECONDS");
  EXPECT_EQ(DefaultImportCpuSeconds(), 0U);
  LoadOptions options;
  EXPECT_EQ(ImportLimitsFor(size_t{5} << 20, options).cpuSeconds, 35U);
  options.importCpuSeconds = 3;
  EXPECT_EQ(ImportLimitsFor(size_t{5} << 20, options).cpuSeconds, 3U);
  if (saved != nullptr) setenv("TERMSHADE_IMPORT_SECONDS", kept.c_str(), 1);
}

TEST(IsolatedImport, ACancelStopsALoopingImporter) {
  std::atomic<bool> cancel{false};
  LoadOptions options;
  options.cancel = &cancel;
  options.importCpuSeconds = 600;  // were the cancel lost, the limit's message, ten minutes on
  std::thread canceller([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    cancel = true;
  });
  Loaded<Mesh> mesh = ImportWithAssimpIsolated(Unnamed("loop.ply", "ply"), kLoopingPly, options);
  canceller.join();
  ASSERT_FALSE(mesh.Ok());
  EXPECT_EQ(mesh.Error().ToString(), "loop.ply: loading cancelled");
}

TEST(IsolatedImport, AHelperAskingForTooMuchRunsOutOfMemoryThere) {
  if (kAddressSanitizerBuild) GTEST_SKIP() << "AddressSanitizer builds set no address-space limit";
  // Assimp's Quick3D importer sizes its arrays from the file's counts (the
  // loader checks them first; called directly here): 2.4 GB for 105 bytes.
  const std::string bytes =
      test::ReadFile(SourcePath("tests/models/bad/q3d_vertex_count_beyond_file_size.q3o"));
  ASSERT_FALSE(bytes.empty());
  LoadOptions options;
  options.memoryBudgetBytes = size_t{64} << 20;
  Loaded<Mesh> mesh = ImportWithAssimpIsolated(Unnamed("counts.q3o", "q3o"), bytes, options);
  ASSERT_FALSE(mesh.Ok());
  EXPECT_EQ(mesh.Error().ToString(),
            "counts.q3o: the importer ran out of memory (it may take no more than the memory "
            "budget)");
}

TEST(ImportWire, AMeshCrossesWhole) {
  Mesh mesh;
  mesh.name = "two.obj";
  mesh.verticesFile = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, -0.5}};
  const uint32_t first[] = {0, 1, 2}, second[] = {0, 2, 3};
  const uint8_t hidden[] = {0, 1, 0};
  mesh.AddFace(first, hidden);
  mesh.AddFace(second);
  mesh.segments = {{0, 3}};
  mesh.faceColors = {{0.5F, 0.25F, 1.0F}, {0, 0, 0}};
  mesh.textures = {"maps/wood.png", "*0"};
  mesh.upAxisFile = UpAxis::kPlusY;
  std::string wire;
  const WireSink sink = [&](const void* from, size_t size) {
    wire.append(static_cast<const char*>(from), size);
    return true;
  };
  ASSERT_TRUE(WriteResultFrame(ModuleStatus::kDone, "", mesh, sink));
  size_t at = 1;  // past the frame's kind
  const auto source = [&](void* to, size_t size) {
    if (at + size > wire.size()) return false;
    std::memcpy(to, wire.data() + at, size);
    at += size;
    return true;
  };
  WireReader reader(source, wire.size());
  ModuleStatus status = ModuleStatus::kException;
  std::string text;
  Loaded<Mesh> read = LoadError{};
  ASSERT_TRUE(ReadResultFrame(reader, status, text, read)) << reader.Problem();
  EXPECT_EQ(status, ModuleStatus::kDone);
  ASSERT_TRUE(read.Ok());
  ExpectSameMesh(read.Value(), mesh, "wire");
  EXPECT_EQ(read.Value().textures, mesh.textures);
  // Cut anywhere, it is refused; with a limit below its size, too.
  for (size_t cut = 1; cut + 1 < wire.size(); cut += 7) {
    at = 1;
    WireReader shortReader(
        [&](void* to, size_t size) { return at + size <= cut && source(to, size); }, wire.size());
    EXPECT_FALSE(ReadResultFrame(shortReader, status, text, read)) << cut;
  }
  at = 1;
  WireReader limited(source, wire.size() / 2);
  EXPECT_FALSE(ReadResultFrame(limited, status, text, read));
  EXPECT_FALSE(limited.Problem().empty());
}

TEST(ImportWire, ACountBeyondTheLimitIsRefusedBeforeAllocating) {
  std::string wire;
  const WireSink sink = [&](const void* from, size_t size) {
    wire.append(static_cast<const char*>(from), size);
    return true;
  };
  Mesh mesh;
  mesh.verticesFile = {{0, 0, 0}};
  ASSERT_TRUE(WriteResultFrame(ModuleStatus::kDone, "", mesh, sink));
  // The vertex count sits after kind, status, text, flag, name, up axis.
  const size_t countAt = 1 + 4 + 8 + 1 + 8 + 1;
  const uint64_t huge = uint64_t{1} << 60;
  std::memcpy(wire.data() + countAt, &huge, sizeof huge);
  size_t at = 1;
  WireReader reader(
      [&](void* to, size_t size) {
        if (at + size > wire.size()) return false;
        std::memcpy(to, wire.data() + at, size);
        at += size;
        return true;
      },
      uint64_t{1} << 62);
  ModuleStatus status{};
  std::string text;
  Loaded<Mesh> read = LoadError{};
  EXPECT_FALSE(ReadResultFrame(reader, status, text, read));
  EXPECT_EQ(reader.Problem(), "an array longer than allowed");
}

// What the reader says of a mesh's answer (empty: accepted).
std::string WireRefusal(const Mesh& mesh) {
  std::string wire;
  const WireSink sink = [&](const void* from, size_t size) {
    wire.append(static_cast<const char*>(from), size);
    return true;
  };
  EXPECT_TRUE(WriteResultFrame(ModuleStatus::kDone, "", mesh, sink));
  size_t at = 1;
  WireReader reader(
      [&](void* to, size_t size) {
        if (at + size > wire.size()) return false;
        std::memcpy(to, wire.data() + at, size);
        at += size;
        return true;
      },
      wire.size());
  ModuleStatus status{};
  std::string text;
  Loaded<Mesh> read = LoadError{};
  return ReadResultFrame(reader, status, text, read) ? std::string() : reader.Problem();
}

TEST(ImportWire, TextureNamesBeyondTheLimitsAreRefused) {
  const auto refusal = [](const std::vector<std::string>& textures) {
    Mesh mesh;
    mesh.verticesFile = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    const uint32_t face[] = {0, 1, 2};
    mesh.AddFace(face);
    mesh.textures = textures;
    return WireRefusal(mesh);
  };
  EXPECT_EQ(refusal({"wood.png"}), "");
  EXPECT_EQ(refusal({std::string("a.png\0/../../x", 14)}), "a texture name with a NUL byte");
  EXPECT_EQ(refusal({""}), "an empty texture name");
  EXPECT_EQ(refusal({std::string(kMaxTextureNameBytes + 1, 'x')}), "a text longer than allowed");
  EXPECT_EQ(refusal(std::vector<std::string>(kMaxTextures + 1, "t.png")),
            "more texture names than allowed");
}

TEST(ImportWire, MeshesThatNoLoaderMakesAreNamed) {
  Mesh mesh;
  mesh.verticesFile = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const uint32_t corners[] = {0, 1, 2};
  mesh.AddFace(corners);
  EXPECT_EQ(MeshWireProblem(mesh), "");
  Mesh past = mesh;
  past.faceCorners[2] = 3;
  EXPECT_EQ(MeshWireProblem(past), "a corner past the vertices");
  Mesh starts = mesh;
  starts.faceStarts = {0, 4};
  EXPECT_EQ(MeshWireProblem(starts), "face starts that do not cover the corners");
  Mesh order = mesh;
  order.faceStarts = {0, 3, 1, 3};
  EXPECT_EQ(MeshWireProblem(order), "face starts out of order");
  Mesh none = mesh;
  none.faceCorners.clear();
  none.edgeHidden.clear();
  none.faceStarts = {0};
  EXPECT_EQ(MeshWireProblem(none), "no face");
  Mesh two = mesh;
  two.faceStarts = {0, 2, 3};
  EXPECT_EQ(MeshWireProblem(two), "a face of fewer than 3 corners");
  Mesh line = mesh;
  line.segments = {{0, 7}};
  EXPECT_EQ(MeshWireProblem(line), "a line past the vertices");
  Mesh flags = mesh;
  flags.edgeHidden.pop_back();
  EXPECT_EQ(MeshWireProblem(flags), "edge flags not one a corner");
  Mesh colours = mesh;
  colours.faceColors = {{}, {}};
  EXPECT_EQ(MeshWireProblem(colours), "face colours not one a face");
}

TEST(ImportWire, TexturedMeshesOutOfShapeAreRefused) {
  Mesh mesh;
  mesh.verticesFile = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const uint32_t face[] = {0, 1, 2};
  mesh.AddFace(face);
  mesh.textures = {"wood.png"};
  mesh.textureImages = {TextureImage{2, 1, {1, 2, 3, 4, 5, 6}, "", ""}};
  mesh.faceTextures = {0};
  mesh.cornerUvs = {{0, 0}, {1, 0}, {0, 1}};
  EXPECT_EQ(WireRefusal(mesh), "");
  Mesh unfilled = mesh;
  unfilled.textureImages[0].srgbTexels.pop_back();
  EXPECT_EQ(WireRefusal(unfilled), "a texture image whose texels do not fill it");
  Mesh large = mesh;
  large.textureImages[0] = TextureImage{kMaxTextureSideTexels + 1, 1, {}, "", ""};
  large.textureImages[0].srgbTexels.resize(size_t{kMaxTextureSideTexels + 1} * 3);
  EXPECT_EQ(WireRefusal(large), "a texture image larger than allowed");
  Mesh extraImage = mesh;
  extraImage.textureImages.push_back(mesh.textureImages[0]);
  EXPECT_EQ(WireRefusal(extraImage), "texture images not one a name");
  Mesh pastNames = mesh;
  pastNames.faceTextures = {1};
  EXPECT_EQ(WireRefusal(pastNames), "a face texture past the names");
  Mesh shortUvs = mesh;
  shortUvs.cornerUvs.pop_back();
  EXPECT_EQ(WireRefusal(shortUvs), "texture coordinates not one a corner of a textured mesh");
  Mesh faces = mesh;
  faces.faceTextures = {0, 0};
  EXPECT_EQ(WireRefusal(faces), "face textures not one a face");
}

}  // namespace
}  // namespace termshade
