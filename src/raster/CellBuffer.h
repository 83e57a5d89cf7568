#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace termshade {

/// What a frame shows, cell by cell (row-major): the glyph (a code point), the 1-based face
/// seen at the cell's sample (0 = background) and its shade level (-1 = none).
/// The one buffer that both text dumps and the terminal screen are made from.
///
/// Colours come as (face, intensity) pairs, so one mapping from face colour and
/// intensity serves both: the foreground (the glyph's ink: FaceNumber, Level,
/// Intensity) and the background (BackFaceNumber, BackLevel, BackIntensity;
/// face 0 = the terminal's background). Single-sample frames have no background
/// face; the glyph modes with two colours (SPEC 11) fill it. With several samples
/// a cell's FaceNumber is the foreground's face: the one most of its inked samples show.
class CellBuffer {
 public:
  CellBuffer() = default;
  CellBuffer(int widthCells, int heightCells) { Resize(widthCells, heightCells); }

  /// Resizes and clears; keeps capacity so a frame loop does not allocate.
  void Resize(int widthCells, int heightCells);
  /// The same for a buffer of samples that only the glyph stage reads: face
  /// numbers alone (the other fields stay empty, and nothing shades them).
  void ResizeFacesOnly(int widthCells, int heightCells);
  bool FacesOnly() const { return facesOnly_; }
  void Clear();

  int WidthCells() const { return widthCells_; }
  int HeightCells() const { return heightCells_; }
  size_t Index(int col, int row) const { return static_cast<size_t>(row) * widthCells_ + col; }

  char32_t Glyph(int col, int row) const { return glyphs_[Index(col, row)]; }
  uint32_t FaceNumber(int col, int row) const { return faceNumbers_[Index(col, row)]; }
  int16_t Level(int col, int row) const { return levels_[Index(col, row)]; }
  /// Foreground intensity, 0..255 (255 = intensity 1).
  uint8_t Intensity(int col, int row) const { return intensities_[Index(col, row)]; }
  uint32_t BackFaceNumber(int col, int row) const { return backFaceNumbers_[Index(col, row)]; }
  int16_t BackLevel(int col, int row) const { return backLevels_[Index(col, row)]; }
  uint8_t BackIntensity(int col, int row) const { return backIntensities_[Index(col, row)]; }

  std::vector<char32_t>& Glyphs() { return glyphs_; }
  std::vector<uint32_t>& FaceNumbers() { return faceNumbers_; }
  std::vector<int16_t>& Levels() { return levels_; }
  const std::vector<char32_t>& Glyphs() const { return glyphs_; }
  const std::vector<uint32_t>& FaceNumbers() const { return faceNumbers_; }
  const std::vector<int16_t>& Levels() const { return levels_; }
  std::vector<uint8_t>& Intensities() { return intensities_; }
  const std::vector<uint8_t>& Intensities() const { return intensities_; }
  std::vector<uint32_t>& BackFaceNumbers() { return backFaceNumbers_; }
  std::vector<int16_t>& BackLevels() { return backLevels_; }
  std::vector<uint8_t>& BackIntensities() { return backIntensities_; }
  const std::vector<uint32_t>& BackFaceNumbers() const { return backFaceNumbers_; }
  const std::vector<int16_t>& BackLevels() const { return backLevels_; }
  const std::vector<uint8_t>& BackIntensities() const { return backIntensities_; }

  /// A cell's texture colour (albedo) for its foreground and its background:
  /// 0 when the face colour serves, else PackAlbedo's value (shade/CellColour.h). Kept only once a
  /// frame has textured faces (UseAlbedos); every cell 0 otherwise.
  uint32_t ForeAlbedo(int col, int row) const {
    return foreAlbedos_.empty() ? 0 : foreAlbedos_[Index(col, row)];
  }
  uint32_t BackAlbedo(int col, int row) const {
    return backAlbedos_.empty() ? 0 : backAlbedos_[Index(col, row)];
  }
  /// Makes room for the albedos (all 0) until the next Resize.
  void UseAlbedos();
  /// Back to face colours alone.
  void DropAlbedos() {
    foreAlbedos_.clear();
    backAlbedos_.clear();
  }
  bool HasAlbedos() const { return !foreAlbedos_.empty(); }
  std::vector<uint32_t>& ForeAlbedos() { return foreAlbedos_; }
  std::vector<uint32_t>& BackAlbedos() { return backAlbedos_; }

  /// Row r as UTF-8 text, exactly WidthCells() characters.
  std::string RowText(int row) const;

 private:
  int widthCells_ = 0;
  int heightCells_ = 0;
  bool facesOnly_ = false;
  std::vector<char32_t> glyphs_;
  std::vector<uint32_t> faceNumbers_;
  std::vector<int16_t> levels_;
  std::vector<uint8_t> intensities_;
  std::vector<uint32_t> backFaceNumbers_;
  std::vector<int16_t> backLevels_;
  std::vector<uint8_t> backIntensities_;
  std::vector<uint32_t> foreAlbedos_;
  std::vector<uint32_t> backAlbedos_;
};

}  // namespace termshade
