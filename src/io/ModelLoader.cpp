#include "io/ModelLoader.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <assimp/Importer.hpp>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include "io/DatReader.h"

namespace termshade {
namespace {

std::string LowerExtension(const std::string& path) {
  const size_t dot = path.find_last_of('.');
  const size_t slash = path.find_last_of('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string ext = path.substr(dot);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

Loaded<std::string> ReadWholeFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return LoadError{path, 0, 0, std::string("cannot open: ") + std::strerror(errno)};
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  if (size < 0) return LoadError{path, 0, 0, "cannot read (not a regular file?)"};
  if (static_cast<size_t>(size) > kMaxModelFileBytes) {
    return LoadError{path, 0, 0, "file is larger than 512 MiB"};
  }
  in.seekg(0, std::ios::beg);
  std::string text(static_cast<size_t>(size), '\0');
  if (!in.read(text.data(), size)) return LoadError{path, 0, 0, "cannot read the whole file"};
  return text;
}

void AppendNode(const aiScene& scene, const aiNode& node, const aiMatrix4x4& parent, Mesh& out) {
  const aiMatrix4x4 transform = parent * node.mTransformation;
  for (unsigned m = 0; m < node.mNumMeshes; ++m) {
    const aiMesh& mesh = *scene.mMeshes[node.mMeshes[m]];
    const auto base = static_cast<uint32_t>(out.verticesFile.size());
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
      const aiVector3D p = transform * mesh.mVertices[v];
      out.verticesFile.push_back({p.x, p.y, p.z});
    }
    std::vector<uint32_t> corners;
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      corners.assign(face.mIndices, face.mIndices + face.mNumIndices);
      for (uint32_t& c : corners) c += base;
      if (corners.size() >= 3) {
        out.AddFace(corners);
      } else if (corners.size() == 2) {
        out.segments.push_back({corners[0], corners[1]});
      }
    }
  }
  for (unsigned c = 0; c < node.mNumChildren; ++c) {
    AppendNode(scene, *node.mChildren[c], transform, out);
  }
}

Loaded<Mesh> ImportWithAssimp(const std::string& path, const std::string& bytes) {
  Assimp::Importer importer;
  const std::string ext = LowerExtension(path);
  const aiScene* scene =
      importer.ReadFileFromMemory(bytes.data(), bytes.size(), aiProcess_JoinIdenticalVertices,
                                  ext.size() > 1 ? ext.c_str() + 1 : "");
  if (scene == nullptr || scene->mRootNode == nullptr) {
    return LoadError{path, 0, 0, "cannot import: " + std::string(importer.GetErrorString())};
  }
  Mesh mesh;
  mesh.name = path;
  AppendNode(*scene, *scene->mRootNode, aiMatrix4x4(), mesh);
  if (mesh.FaceCount() == 0) return LoadError{path, 0, 0, "the file holds no polygons"};
  return mesh;
}

}  // namespace

bool UsesImporter(const std::string& path) {
  const std::string ext = LowerExtension(path);
  if (ext.empty() || ext == ".dat") return false;
  Assimp::Importer importer;
  return importer.IsExtensionSupported(ext);
}

Loaded<Mesh> LoadModelFile(const std::string& path, const LoadOptions& /*options*/) {
  Loaded<std::string> bytes = ReadWholeFile(path);
  if (!bytes.Ok()) return bytes.Error();
  if (UsesImporter(path)) return ImportWithAssimp(path, bytes.Value());
  return ParseDat(bytes.Value(), path);
}

}  // namespace termshade
