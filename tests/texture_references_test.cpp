// Where a model's texture names point (io/load/TextureReferences.h): found
// only inside the model's folder, nothing outside it looked up.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "io/load/TextureReferences.h"

namespace termshade {
namespace {

namespace fs = std::filesystem;

class TextureFolder : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string pattern = (fs::temp_directory_path() / "termshade-tex-XXXXXX").string();
    ASSERT_NE(mkdtemp(pattern.data()), nullptr);
    root_ = pattern;
    fs::create_directories(root_ / "model" / "maps");
    std::ofstream(root_ / "model" / "maps" / "wood.png") << "PNG";
    std::ofstream(root_ / "secret.png") << "PNG";
    fs::create_symlink(root_ / "secret.png", root_ / "model" / "link.png");
    fs::create_directories(root_ / "model" / "folder.png");
    model_ = (root_ / "model" / "m.obj").string();
  }
  void TearDown() override { fs::remove_all(root_); }

  TextureWhere Where(const std::string& name) const {
    const auto found = LocateTextures({name}, model_);
    return found.empty() ? TextureWhere::kMissing : found.front().where;
  }

  fs::path root_;
  std::string model_;
};

TEST_F(TextureFolder, FilesInsideTheFolderAreFoundAsWrittenOnAnySystem) {
  EXPECT_EQ(Where("maps/wood.png"), TextureWhere::kInFolder);
  EXPECT_EQ(Where(".\\maps\\wood.png"), TextureWhere::kInFolder);  // written on Windows
  EXPECT_EQ(Where("maps/../maps/wood.png"), TextureWhere::kInFolder);
  EXPECT_EQ(Where("maps/stone.png"), TextureWhere::kMissing);
  EXPECT_EQ(Where("folder.png"), TextureWhere::kMissing);  // not a regular file
}

TEST_F(TextureFolder, NamesLeavingTheFolderAreNotLookedAt) {
  EXPECT_EQ(Where("../secret.png"), TextureWhere::kOutsideFolder);
  EXPECT_EQ(Where("link.png"), TextureWhere::kOutsideFolder);  // a link out
  EXPECT_EQ(Where((root_ / "secret.png").string()), TextureWhere::kOutsideFolder);
  EXPECT_EQ(Where("C:\\textures\\wood.png"), TextureWhere::kOutsideFolder);
  EXPECT_EQ(Where("file:///etc/passwd"), TextureWhere::kUri);
  EXPECT_EQ(Where("http://example.com/t.png"), TextureWhere::kUri);
}

TEST_F(TextureFolder, EmbeddedAndStandardInput) {
  EXPECT_EQ(Where("*0"), TextureWhere::kEmbedded);
  EXPECT_EQ(LocateTextures({"maps/wood.png"}, "-").front().where, TextureWhere::kNoFolder);
  EXPECT_TRUE(LocateTextures({""}, model_).empty());
}

}  // namespace
}  // namespace termshade
