#pragma once

#include <assimp/IOSystem.hpp>
#include <atomic>
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>

#include "io/read/LoadError.h"

namespace termshade {

/// Assimp's file access for one model: the model file itself is served from
/// bytes already read, and every file an importer asks for (OBJ mtllib, glTF
/// buffers and images, ...) is opened only if it is a regular file inside the
/// model's folder (after resolving `..` and symbolic links). Relative names
/// resolve against that folder, never the working directory. The first
/// refusal is kept so the loader can name the reference in its message.
class ConfinedIOSystem : public Assimp::IOSystem {
 public:
  /// modelName: the name handed to Assimp's ReadFile; folder: the canonical
  /// folder references must stay in (empty: no reference is allowed, as for
  /// standard input). maxBytes bounds all bytes read, the model's included.
  ConfinedIOSystem(std::string modelName, std::string modelBytes, std::string folder,
                   size_t maxBytes, const std::atomic<bool>* cancel);

  bool Exists(const char* file) const override;
  char getOsSeparator() const override { return '/'; }
  Assimp::IOStream* Open(const char* file, const char* mode) override;
  void Close(Assimp::IOStream* stream) override;

  /// The bytes of a file a model refers to (a texture) by the same rules,
  /// without failing the import: an error with the reason when it is refused
  /// or missing. Counts against the same bytes.
  /// A name that differs from the file's only by case is read as that file
  /// (its name in `readAs`).
  Loaded<std::string> ReadReference(const std::string& name, std::string* readAs = nullptr);

  /// Why the first refused reference was refused ("'../x.bin' leaves the model's folder").
  const std::optional<std::string>& Refusal() const { return refusal_; }

 private:
  // The canonical path of a reference inside the folder, or a reason for refusing it.
  bool Resolve(const std::string& name, std::string& resolved, std::string& reason) const;
  void Refuse(const std::string& name, const std::string& reason);
  // The one entry of the path's folder equal to its file name but for case.
  std::optional<std::string> MatchIgnoringCase(const std::string& path);

  static constexpr size_t kMostListedEntries = 100000;

  std::string modelName_;
  std::shared_ptr<const std::string> modelBytes_;
  std::string folder_;
  size_t bytesLeft_;
  const std::atomic<bool>* cancel_;
  std::optional<std::string> refusal_;
  /// Folders listed for MatchIgnoringCase: lower-case name -> name.
  std::unordered_map<std::string, std::unordered_multimap<std::string, std::string>> listings_;
  size_t entriesListed_ = 0;
};

}  // namespace termshade
