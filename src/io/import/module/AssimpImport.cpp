#include "io/import/module/AssimpImport.h"

#include <assimp/config.h>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/ProgressHandler.hpp>

#include <algorithm>
#include <assimp/Importer.hpp>
#include <cstring>
#include <iostream>
#include <new>
#include <optional>
#include <streambuf>
#include <string>
#include <unordered_map>
#include <vector>

#include "geometry/WeldVertices.h"
#include "io/import/module/ConfinedIOSystem.h"
#include "io/import/module/TextureDecode.h"
#include "io/read/LoadBudget.h"

namespace termshade {
namespace {

// The colour faces take when some faces of a model have a file colour and others not.
constexpr Rgb kNeutralFaceColor{0.8f, 0.8f, 0.8f};

// Some importers write to std::cerr themselves (OpenGEX's parser: "nullptr
// returned by creating DDLNode."), past Assimp's silent default logger. Their
// lines would reach the terminal unescaped and unnamed, so std::cerr writes
// nothing while an import runs (nothing else of ours writes to it meanwhile).
class QuietStandardError {
 public:
  QuietStandardError() : saved_(std::cerr.rdbuf(&discard_)) {}
  QuietStandardError(const QuietStandardError&) = delete;
  QuietStandardError& operator=(const QuietStandardError&) = delete;
  ~QuietStandardError() { std::cerr.rdbuf(saved_); }

 private:
  // Accepts and drops every character.
  class Discard : public std::streambuf {
   protected:
    int_type overflow(int_type c) override { return traits_type::not_eof(c); }
    std::streamsize xsputn(const char* /*s*/, std::streamsize n) override { return n; }
  };
  Discard discard_;
  std::streambuf* saved_;
};

// Reports Assimp's progress and stops the import once the cancel flag is set.
class ProgressReporter : public Assimp::ProgressHandler {
 public:
  explicit ProgressReporter(const LoadOptions& options) : options_(options) {}
  bool Update(float share) override {
    if (options_.progress && share >= 0.0f) options_.progress(std::clamp(share, 0.0f, 1.0f));
    return !(options_.cancel != nullptr && options_.cancel->load(std::memory_order_relaxed));
  }

 private:
  const LoadOptions& options_;
};

// A mesh placed in the model: which one, and the node transform that places it.
struct PlacedMesh {
  const aiMesh* mesh = nullptr;
  aiMatrix4x4 transform;
};

// Every mesh reference of the node tree, depth first, skipping null entries.
std::vector<PlacedMesh> PlacedMeshes(const aiScene& scene) {
  std::vector<PlacedMesh> placed;
  std::vector<std::pair<const aiNode*, aiMatrix4x4>> stack{{scene.mRootNode, aiMatrix4x4()}};
  while (!stack.empty()) {
    const auto [node, parent] = stack.back();
    stack.pop_back();
    const aiMatrix4x4 transform = parent * node->mTransformation;
    for (unsigned m = 0; m < node->mNumMeshes && node->mMeshes != nullptr; ++m) {
      const unsigned index = node->mMeshes[m];
      if (index < scene.mNumMeshes && scene.mMeshes[index] != nullptr) {
        placed.push_back({scene.mMeshes[index], transform});
      }
    }
    for (unsigned c = node->mNumChildren; c-- > 0 && node->mChildren != nullptr;) {
      if (node->mChildren[c] != nullptr) stack.emplace_back(node->mChildren[c], transform);
    }
  }
  return placed;
}

// The material's colour when the file gave one (not Assimp's default material).
std::optional<Rgb> FileMaterialColor(const aiScene& scene, unsigned materialIndex) {
  if (materialIndex >= scene.mNumMaterials || scene.mMaterials[materialIndex] == nullptr) {
    return std::nullopt;
  }
  const aiMaterial& material = *scene.mMaterials[materialIndex];
  // Importers make up a material where the file has none: named
  // AI_DEFAULT_MATERIAL_NAME (OBJ, STL), or unnamed with a diffuse colour
  // only (PLY, OFF). A glTF material may be unnamed but has a base colour.
  aiString name;
  const bool named = material.Get(AI_MATKEY_NAME, name) == aiReturn_SUCCESS && name.length > 0;
  if (named && std::strcmp(name.C_Str(), AI_DEFAULT_MATERIAL_NAME) == 0) return std::nullopt;
  aiColor4D color;
  if (material.Get(AI_MATKEY_BASE_COLOR, color) != aiReturn_SUCCESS &&
      (!named || material.Get(AI_MATKEY_COLOR_DIFFUSE, color) != aiReturn_SUCCESS)) {
    return std::nullopt;
  }
  return Rgb{std::clamp(color.r, 0.0f, 1.0f), std::clamp(color.g, 0.0f, 1.0f),
             std::clamp(color.b, 0.0f, 1.0f)};
}

// Vertex colours averaged over a face's corners.
Rgb MeanVertexColor(const aiMesh& mesh, const aiFace& face) {
  float sum[3] = {0, 0, 0};
  for (unsigned i = 0; i < face.mNumIndices; ++i) {
    const aiColor4D& c = mesh.mColors[0][face.mIndices[i]];
    sum[0] += c.r;
    sum[1] += c.g;
    sum[2] += c.b;
  }
  const auto n = static_cast<float>(std::max(face.mNumIndices, 1u));
  return Rgb{std::clamp(sum[0] / n, 0.0f, 1.0f), std::clamp(sum[1] / n, 0.0f, 1.0f),
             std::clamp(sum[2] / n, 0.0f, 1.0f)};
}

// The base-colour texture a material names (glTF's base colour, else the
// diffuse map), as the file writes it; empty when it names none.
std::string MaterialTexture(const aiScene& scene, unsigned materialIndex) {
  if (materialIndex >= scene.mNumMaterials || scene.mMaterials[materialIndex] == nullptr) return {};
  const aiMaterial& material = *scene.mMaterials[materialIndex];
  aiString path;
  for (const aiTextureType type : {aiTextureType_BASE_COLOR, aiTextureType_DIFFUSE}) {
    if (material.GetTextureCount(type) > 0 &&
        material.GetTexture(type, 0, &path) == aiReturn_SUCCESS && path.length > 0) {
      return std::string(path.C_Str(), std::min<size_t>(path.length, kMaxTextureNameBytes));
    }
  }
  return {};
}

// The texture index of a placed mesh's material (kNoTexture: none, or past
// kMaxTextures), each name listed once in first-use order (a map: a hostile
// file may place 100,000 meshes over thousands of materials).
uint32_t TextureIndex(const aiScene& scene, const aiMesh& mesh,
                      std::unordered_map<std::string, uint32_t>& indexOf, Mesh& out) {
  std::string texture = MaterialTexture(scene, mesh.mMaterialIndex);
  if (texture.empty()) return kNoTexture;
  if (const auto at = indexOf.find(texture); at != indexOf.end()) return at->second;
  if (out.textures.size() >= kMaxTextures) return kNoTexture;
  const auto index = static_cast<uint32_t>(out.textures.size());
  indexOf.emplace(texture, index);
  out.textures.push_back(std::move(texture));
  return index;
}

// The texture coordinates of a corner (channel 0; none: the origin).
std::array<float, 2> CornerUv(const aiMesh& mesh, unsigned vertex) {
  if (!mesh.HasTextureCoords(0)) return {0.0F, 0.0F};
  const aiVector3D& uv = mesh.mTextureCoords[0][vertex];
  return {uv.x, uv.y};
}

// Builds our mesh: polygons kept, two-corner faces as segments, then vertices
// welded by exact position (importers such as OBJ's give every corner its own
// vertex; texture coordinates stay a corner's own).
Mesh BuildMesh(const aiScene& scene, const std::vector<PlacedMesh>& placed) {
  Mesh out;
  std::vector<uint32_t> corners;
  std::unordered_map<std::string, uint32_t> textureIndexOf;
  std::vector<std::optional<Rgb>> colors;
  std::vector<uint32_t> faceTextures;
  std::vector<std::array<float, 2>> cornerUvs;
  bool anyColor = false, anyTexture = false;
  for (const PlacedMesh& item : placed) {
    const aiMesh& mesh = *item.mesh;
    if (mesh.mVertices == nullptr || mesh.mFaces == nullptr) continue;
    const auto base = static_cast<uint32_t>(out.verticesFile.size());
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
      const aiVector3D p = item.transform * mesh.mVertices[v];
      out.verticesFile.push_back({p.x, p.y, p.z});
    }
    const bool vertexColors = mesh.HasVertexColors(0);
    // A texture is drawn only where the corners have coordinates into it.
    const uint32_t texture = TextureIndex(scene, mesh, textureIndexOf, out);
    const bool textured = texture != kNoTexture && mesh.HasTextureCoords(0);
    anyTexture = anyTexture || textured;
    // A textured face's colour multiplies its texture: white when the file gives none.
    std::optional<Rgb> materialColor = FileMaterialColor(scene, mesh.mMaterialIndex);
    if (textured && !materialColor) materialColor = Rgb{1.0F, 1.0F, 1.0F};
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      if (face.mIndices == nullptr) continue;
      corners.clear();
      for (unsigned i = 0; i < face.mNumIndices; ++i) {
        if (face.mIndices[i] < mesh.mNumVertices) corners.push_back(base + face.mIndices[i]);
      }
      if (corners.size() >= 3 && corners.size() == face.mNumIndices) {
        out.AddFace(corners);
        std::optional<Rgb> color = vertexColors ? MeanVertexColor(mesh, face) : materialColor;
        anyColor = anyColor || color.has_value();
        colors.push_back(color);
        // Coordinates only from the first textured mesh on (the faces before it: none).
        if (anyTexture) {
          faceTextures.resize(colors.size() - 1, kNoTexture);
          cornerUvs.resize(out.faceCorners.size() - face.mNumIndices, std::array<float, 2>{});
          faceTextures.push_back(textured ? texture : kNoTexture);
          for (unsigned i = 0; i < face.mNumIndices; ++i) {
            cornerUvs.push_back(CornerUv(mesh, face.mIndices[i]));
          }
        }
      } else if (corners.size() == 2) {
        out.segments.push_back({corners[0], corners[1]});
      }
    }
  }
  if (anyColor) {
    out.faceColors.reserve(colors.size());
    for (const auto& color : colors) out.faceColors.push_back(color.value_or(kNeutralFaceColor));
  }
  if (anyTexture) {
    out.faceTextures = std::move(faceTextures);
    out.cornerUvs = std::move(cornerUvs);
  }
  WeldExactPositions(out);
  return out;
}

// Each texture's image: embedded ("*N", or a name the file embeds) or a file
// inside the model's folder, decoded here in the import helper, all of them
// within a quarter of the memory budget. A texture that cannot be read keeps
// its reason; the model loads without it.
void DecodeTextures(const aiScene& scene, ConfinedIOSystem& files, size_t memoryBudgetBytes,
                    Mesh& mesh) {
  size_t bytesLeft = memoryBudgetBytes / 4;
  std::vector<uint8_t> used(mesh.textures.size(), 0);
  for (const uint32_t texture : mesh.faceTextures) {
    if (texture != kNoTexture) used[texture] = 1;
  }
  mesh.textureImages.clear();
  for (size_t index = 0; index < mesh.textures.size(); ++index) {
    const std::string& name = mesh.textures[index];
    TextureImage image;
    if (used[index] == 0) {
      image.problem = "no face has coordinates into it";
    } else if (const aiTexture* embedded = scene.GetEmbeddedTexture(name.c_str());
               embedded != nullptr) {
      if (embedded->pcData == nullptr) {
        image.problem = "an embedded image without data";
      } else if (embedded->mHeight == 0) {
        image = DecodeTexture(
            std::string_view(reinterpret_cast<const char*>(embedded->pcData), embedded->mWidth),
            bytesLeft);
      } else {
        image = TextureFromBgra(reinterpret_cast<const uint8_t*>(embedded->pcData),
                                embedded->mWidth, embedded->mHeight, bytesLeft);
      }
    } else if (name.front() == '*') {
      image.problem = "no such embedded image";
    } else {
      std::string path = name;
      std::replace(path.begin(), path.end(), '\\', '/');  // names written on Windows
      std::string readAs;
      Loaded<std::string> bytes = files.ReadReference(path, &readAs);
      // A path from the author's machine ("D:/art/wood.jpg"): the file beside the model.
      if (const size_t slash = path.rfind('/');
          !bytes.Ok() && slash != std::string::npos && slash + 1 < path.size()) {
        readAs = path.substr(slash + 1);
        if (Loaded<std::string> beside = files.ReadReference(readAs, &readAs); beside.Ok()) {
          bytes = std::move(beside);
        } else {
          readAs.clear();
        }
      }
      image = bytes.Ok() ? DecodeTexture(bytes.Value(), bytesLeft)
                         : TextureImage{0, 0, {}, bytes.Error().message, {}};
      if (bytes.Ok()) image.readAs = readAs;
    }
    bytesLeft -= std::min(bytesLeft, image.srgbTexels.size());
    mesh.textureImages.push_back(std::move(image));
  }
}

// What the file says is up: COLLADA's <up_axis>, FBX's UpAxis metadata, else the format's
// convention.
UpAxis FileUpAxis(const aiScene& scene, const std::string& format, const std::string& colladaUp) {
  if (format == "stl") return UpAxis::kPlusZ;
  if (colladaUp == "Z_UP") return UpAxis::kPlusZ;
  if (colladaUp == "X_UP") return UpAxis::kPlusX;
  int32_t axis = -1, sign = 1;
  if (scene.mMetaData != nullptr && scene.mMetaData->Get("UpAxis", axis)) {
    scene.mMetaData->Get("UpAxisSign", sign);
    static constexpr UpAxis kPlus[3] = {UpAxis::kPlusX, UpAxis::kPlusY, UpAxis::kPlusZ};
    static constexpr UpAxis kMinus[3] = {UpAxis::kMinusX, UpAxis::kMinusY, UpAxis::kMinusZ};
    if (axis >= 0 && axis <= 2) return sign < 0 ? kMinus[axis] : kPlus[axis];
  }
  return UpAxis::kPlusY;
}

// COLLADA's <up_axis> text (X_UP, Y_UP or Z_UP), read from the file's bytes,
// since Assimp is told not to turn the model itself.
std::string ColladaUpAxis(const std::string& bytes) {
  const size_t start = bytes.find("<up_axis>");
  if (start == std::string::npos) return "";
  const size_t from = start + std::strlen("<up_axis>");
  const size_t end = bytes.find('<', from);
  if (end == std::string::npos || end - from > 64) return "";
  std::string text = bytes.substr(from, end - from);
  text.erase(std::remove_if(text.begin(), text.end(),
                            [](unsigned char c) { return std::isspace(c) != 0; }),
             text.end());
  return text;
}

// Assimp's reason, made readable: its internal names replaced, nothing empty.
std::string ImporterMessage(const std::string& raw, const ImportSource& source) {
  std::string text = raw;
  for (size_t at = text.find(source.importName);
       at != std::string::npos && !source.importName.empty();
       at = text.find(source.importName, at)) {
    text.replace(at, source.importName.size(), source.displayName);
    at += source.displayName.size();
  }
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  if (text.rfind("No suitable reader found", 0) == 0 || text.rfind("Unable to open file", 0) == 0) {
    return "not a model file (no importer recognises its content)";
  }
  if (text.empty()) return "the importer rejected the file without giving a reason";
  // Assimp catches what its importers throw, std::bad_alloc too.
  if (text == "std::bad_alloc") {
    return "the importer ran out of memory (it may take no more than the memory budget)";
  }
  return "cannot import: " + text;
}

}  // namespace

std::string AssimpExtensionPatterns() {
  std::string list;
  Assimp::Importer().GetExtensionList(list);
  return list;
}

Loaded<Mesh> RunAssimpImport(const ImportSource& source, std::string bytes,
                             const LoadOptions& options) {
  const auto fail = [&](std::string message) {
    return LoadError{source.displayName, 0, 0, std::move(message)};
  };
  const std::string colladaUp =
      source.format == "dae" || source.format == "xml" || source.format.empty()
          ? ColladaUpAxis(bytes.substr(0, 1 << 16))
          : "";
  // Step 1: the importer, with our file access and progress; the importer owns both.
  Assimp::Importer importer;
  auto* files = new ConfinedIOSystem(source.importName, std::move(bytes), source.folder,
                                     options.memoryBudgetBytes, options.cancel);
  importer.SetIOHandler(files);
  importer.SetProgressHandler(new ProgressReporter(options));
  importer.SetPropertyBool(AI_CONFIG_IMPORT_COLLADA_IGNORE_UP_DIRECTION, true);
  const aiScene* scene = nullptr;
  {
    const QuietStandardError quiet;
    scene = importer.ReadFile(source.importName, aiProcess_ValidateDataStructure);
  }
  if (options.cancel != nullptr && options.cancel->load()) return fail("loading cancelled");
  if (files->Refusal()) return fail(*files->Refusal());
  if (scene == nullptr || scene->mRootNode == nullptr) {
    return fail(ImporterMessage(importer.GetErrorString(), source));
  }
  // Step 2: the size of the mesh against the budget, before building it.
  const std::vector<PlacedMesh> placed = PlacedMeshes(*scene);
  double vertices = 0, corners = 0, faces = 0, texturedCorners = 0;
  for (const PlacedMesh& item : placed) {
    vertices += item.mesh->mNumVertices;
    faces += item.mesh->mNumFaces;
    double meshCorners = 0;
    for (unsigned f = 0; f < item.mesh->mNumFaces && item.mesh->mFaces != nullptr; ++f) {
      meshCorners += item.mesh->mFaces[f].mNumIndices;
    }
    corners += meshCorners;
    if (item.mesh->HasTextureCoords(0)) texturedCorners += meshCorners;
  }
  if (vertices >= 4e9 || corners >= 4e9) {
    return fail("the model has more than 4 billion vertices or corners");
  }
  // (Texture coordinates: 8 bytes a corner, and a face's texture, when any has them.)
  const auto needed = static_cast<double>(EstimateMeshBytes(static_cast<size_t>(vertices),
                                                            static_cast<size_t>(corners),
                                                            static_cast<size_t>(faces))) +
                      (texturedCorners > 0 ? 8.0 * corners + 4.0 * faces : 0.0);
  if (needed > static_cast<double>(options.memoryBudgetBytes)) {
    return fail(OverBudgetMessage(needed, options.memoryBudgetBytes));
  }
  // Step 3: our mesh.
  Mesh mesh = BuildMesh(*scene, placed);
  // Step 4: the images of the textures the faces use.
  if (!mesh.faceTextures.empty()) DecodeTextures(*scene, *files, options.memoryBudgetBytes, mesh);
  if (options.cancel != nullptr && options.cancel->load()) return fail("loading cancelled");
  mesh.name = source.displayName;
  mesh.upAxisFile = FileUpAxis(*scene, source.format, colladaUp);
  if (mesh.FaceCount() == 0) return fail("the file holds no polygons");
  return mesh;
}

}  // namespace termshade
