#include "io/import/module/ConfinedIOSystem.h"

#include <sys/stat.h>

#include <algorithm>
#include <assimp/IOStream.hpp>
#include <cctype>
#include <cstring>
#include <filesystem>
#include <memory>

#include "io/read/RegularFile.h"

namespace termshade {
namespace {

// Read-only bytes in memory, shared by every stream opened on the same file.
class BytesStream : public Assimp::IOStream {
 public:
  BytesStream(std::shared_ptr<const std::string> bytes, const std::atomic<bool>* cancel)
      : bytes_(std::move(bytes)), cancel_(cancel) {}

  size_t Read(void* buffer, size_t size, size_t count) override {
    if (size == 0 || count == 0) return 0;
    if (cancel_ != nullptr && cancel_->load(std::memory_order_relaxed)) return 0;
    const size_t available = (bytes_->size() - position_) / size;
    const size_t items = std::min(count, available);
    std::memcpy(buffer, bytes_->data() + position_, items * size);
    position_ += items * size;
    return items;
  }
  size_t Write(const void* /*buffer*/, size_t /*size*/, size_t /*count*/) override { return 0; }
  aiReturn Seek(size_t offset, aiOrigin origin) override {
    size_t target = 0;
    if (origin == aiOrigin_SET) {
      target = offset;
    } else if (origin == aiOrigin_CUR) {
      target = position_ + offset;
    } else if (origin == aiOrigin_END) {
      if (offset > bytes_->size()) return aiReturn_FAILURE;
      target = bytes_->size() - offset;
    } else {
      return aiReturn_FAILURE;
    }
    if (target > bytes_->size()) return aiReturn_FAILURE;
    position_ = target;
    return aiReturn_SUCCESS;
  }
  size_t Tell() const override { return position_; }
  size_t FileSize() const override { return bytes_->size(); }
  void Flush() override {}

 private:
  std::shared_ptr<const std::string> bytes_;
  const std::atomic<bool>* cancel_;
  size_t position_ = 0;
};

bool IsInside(const std::string& path, const std::string& folder) {
  if (folder == "/") return true;
  return path == folder ||
         (path.size() > folder.size() && path.compare(0, folder.size(), folder) == 0 &&
          path[folder.size()] == '/');
}

}  // namespace

ConfinedIOSystem::ConfinedIOSystem(std::string modelName, std::string modelBytes,
                                   std::string folder, size_t maxBytes,
                                   const std::atomic<bool>* cancel)
    : modelName_(std::move(modelName)),
      modelBytes_(std::make_shared<const std::string>(std::move(modelBytes))),
      folder_(std::move(folder)),
      bytesLeft_(maxBytes > modelBytes_->size() ? maxBytes - modelBytes_->size() : 0),
      cancel_(cancel) {}

bool ConfinedIOSystem::Resolve(const std::string& name, std::string& resolved,
                               std::string& reason) const {
  // Step 1: names that are not paths in a folder at all.
  if (name.empty()) {
    reason = "an empty file name";
    return false;
  }
  if (name.rfind("file:", 0) == 0 || name.find("://") != std::string::npos) {
    reason = "a URI; only files inside the model's folder are read";
    return false;
  }
  if (folder_.empty()) {
    reason = "a reference to another file, and a model read from standard input has no folder";
    return false;
  }
  // Importers glue a reference onto the model's folder: "/m//etc/passwd" is
  // the absolute "/etc/passwd" when that exists outside; Assimp's own retries
  // build "/m//x.bin" for "/m/x.bin" too.
  std::string path = name;
  if (path.size() > folder_.size() + 2 && path.compare(0, folder_.size(), folder_) == 0 &&
      path.compare(folder_.size(), 2, "//") == 0) {
    path.erase(0, folder_.size() + 1);
    struct stat info {};
    if (!IsInside(path, folder_) && stat(path.c_str(), &info) == 0) {
      reason = "an absolute path; references must be relative to the model's folder";
      return false;
    }
    path.erase(0, 1);
  }
  // Step 2: where it really is, symbolic links and '..' resolved.
  const std::filesystem::path candidate =
      path.front() == '/' ? std::filesystem::path(path) : std::filesystem::path(folder_) / path;
  std::error_code error;
  const std::filesystem::path canonical = std::filesystem::weakly_canonical(candidate, error);
  if (error) {
    reason = "a path that cannot be resolved (" + error.message() + ")";
    return false;
  }
  resolved = canonical.string();
  if (!IsInside(resolved, folder_)) {
    const bool underFolder = path.compare(0, folder_.size() + 1, folder_ + "/") == 0;
    reason = path.front() == '/' && !underFolder ? "an absolute path outside the model's folder"
                                                 : "a path that leaves the model's folder";
    return false;
  }
  return true;
}

void ConfinedIOSystem::Refuse(const std::string& name, const std::string& reason) {
  if (refusal_) return;
  // Name the reference as the file wrote it, without the folder an importer put before it.
  std::string shown = name;
  if (!folder_.empty() && shown.compare(0, folder_.size() + 1, folder_ + "/") == 0) {
    shown.erase(0, folder_.size() + 1);
  }
  refusal_ = "refused to read '" + SanitizeForTerminal(shown) + "': " + reason;
}

bool ConfinedIOSystem::Exists(const char* file) const {
  if (file == nullptr) return false;
  if (modelName_ == file) return true;
  std::string resolved, reason;
  if (!Resolve(file, resolved, reason)) {
    const_cast<ConfinedIOSystem*>(this)->Refuse(file, reason);  // Exists is const in Assimp
    return false;
  }
  struct stat info {};
  return stat(resolved.c_str(), &info) == 0;
}

Assimp::IOStream* ConfinedIOSystem::Open(const char* file, const char* mode) {
  if (file == nullptr || mode == nullptr) return nullptr;
  if (std::strchr(mode, 'w') != nullptr || std::strchr(mode, 'a') != nullptr ||
      std::strchr(mode, '+') != nullptr) {
    return nullptr;  // a loader never writes
  }
  if (modelName_ == file) return new BytesStream(modelBytes_, cancel_);
  std::string resolved, reason;
  if (!Resolve(file, resolved, reason)) {
    Refuse(file, reason);
    return nullptr;
  }
  struct stat info {};
  if (stat(resolved.c_str(), &info) != 0) return nullptr;  // missing: the importer decides
  const auto refuseSize = [this](size_t size) -> std::optional<std::string> {
    if (size <= bytesLeft_) return std::nullopt;
    return "it is " + FormatBytes(static_cast<double>(size)) +
           ", more than the memory budget leaves for it";
  };
  Loaded<std::string> bytes = ReadRegularFile(resolved, refuseSize, cancel_);
  if (!bytes.Ok()) {
    Refuse(file, bytes.Error().message);
    return nullptr;
  }
  bytesLeft_ -= bytes.Value().size();
  return new BytesStream(std::make_shared<const std::string>(std::move(bytes.Value())), cancel_);
}

Loaded<std::string> ConfinedIOSystem::ReadReference(const std::string& name, std::string* readAs) {
  const auto refuse = [&name](const std::string& reason) { return LoadError{name, 0, 0, reason}; };
  std::string resolved, reason;
  if (!Resolve(name, resolved, reason)) return refuse(reason);
  struct stat info {};
  if (stat(resolved.c_str(), &info) != 0) {
    // A name written "TEST.PNG" for "test.png" (Windows tools): that entry,
    // resolved and checked again (it may be a link out of the folder).
    const std::optional<std::string> match = MatchIgnoringCase(resolved);
    if (!match || !Resolve(*match, resolved, reason)) {
      return refuse(match ? reason : "no such file in the model's folder");
    }
    if (readAs != nullptr) *readAs = std::filesystem::path(*match).filename().string();
  }
  const auto refuseSize = [this](size_t size) -> std::optional<std::string> {
    if (size <= bytesLeft_) return std::nullopt;
    return "it is " + FormatBytes(static_cast<double>(size)) +
           ", more than the memory budget leaves for it";
  };
  // (The bytes are decoded and freed at once: not kept against the budget.)
  return ReadRegularFile(resolved, refuseSize, cancel_);
}

std::optional<std::string> ConfinedIOSystem::MatchIgnoringCase(const std::string& path) {
  const auto lower = [](std::string text) {
    for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return text;
  };
  const std::filesystem::path wanted(path);
  const std::string folder = wanted.parent_path().string();
  // Each folder listed once an import, all of them at most kMostListedEntries entries.
  auto listed = listings_.find(folder);
  if (listed == listings_.end()) {
    std::unordered_multimap<std::string, std::string> names;
    std::error_code error;
    for (std::filesystem::directory_iterator entry(folder, error), end;
         !error && entry != end && entriesListed_ < kMostListedEntries; entry.increment(error)) {
      if (cancel_ != nullptr && cancel_->load(std::memory_order_relaxed)) break;
      ++entriesListed_;
      const std::string name = entry->path().filename().string();
      names.emplace(lower(name), name);
    }
    listed = listings_.emplace(folder, std::move(names)).first;
  }
  const auto [first, last] = listed->second.equal_range(lower(wanted.filename().string()));
  if (first == last || std::next(first) != last) return std::nullopt;  // none, or several
  return (std::filesystem::path(folder) / first->second).string();
}

void ConfinedIOSystem::Close(Assimp::IOStream* stream) {
  delete stream;
}

}  // namespace termshade
