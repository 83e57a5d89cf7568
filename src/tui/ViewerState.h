#pragma once

#include <memory>
#include <string>
#include <vector>

#include "geometry/Camera.h"
#include "geometry/LevelOfDetail.h"
#include "geometry/Scene.h"
#include "io/load/ModelLoader.h"
#include "io/read/LoadError.h"
#include "raster/RenderOptions.h"
#include "shade/ColourMode.h"
#include "tui/Viewer.h"
#include "tui/ViewerAction.h"

namespace termshade {

/// Reads a model file, or the embedded demo scene for an empty path.
Loaded<Mesh> LoadViewerMesh(const std::string& path, const LoadOptions& options = {});
/// LoadViewerMesh, then PrepareScene with the up axis when given, else the file's own.
Loaded<Scene> LoadViewerScene(const std::string& path, const LoadOptions& options = {},
                              std::optional<UpAxis> upAxis = {});

/// A model the viewer wants loaded (the event loop loads it on a worker).
struct LoadRequest {
  std::string path;
  /// Which model of the list (n, p); none: a new path to add after the current one (o).
  std::optional<size_t> index;
  /// Set (u): the model shown, prepared again with this up axis; the view stays.
  std::optional<UpAxis> turnTo;
};

/// Everything the viewer shows, changed only through actions: no terminal
/// code here, so it is tested directly.
class ViewerState {
 public:
  /// terminalAspect: the cell aspect the terminal reports (0 if it does not).
  ViewerState(const ViewerOptions& options, double terminalAspect);

  /// Asks for the first model of the list; until one has loaded, a failed
  /// load asks for the next one (a message names the ones skipped).
  void RequestFirst();
  /// RequestFirst, loaded here and now; the error (if none loads) means the
  /// viewer cannot start.
  std::optional<LoadError> LoadFirst();
  /// True once a model is shown.
  bool HasModel() const { return hasModel_; }
  /// Every model of the list failed before one was shown: the first error.
  const std::optional<LoadError>& StartError() const { return startError_; }
  /// Asks for a model by path, to be added to the list after the current one.
  void RequestOpen(const std::string& path);
  /// The load asked for by RequestOpen or n/p, if any; taking it clears it.
  std::optional<LoadRequest> TakeLoadRequest();
  /// Whether a load is asked for and not yet taken.
  bool LoadRequested() const { return pending_.has_value(); }
  /// Applies a finished load: the model is shown, or the current one kept
  /// with the error as the message. A failed n/p still counts as a step, so
  /// the next n moves on past the failed model.
  void FinishLoad(const LoadRequest& request, Loaded<Scene> scene);
  /// RequestOpen, loaded here and now (tests, and no event loop).
  void OpenPath(const std::string& path);
  /// Loads a pending request here and now.
  void RunPendingLoad();

  void Apply(ViewerAction action);
  /// Mouse drag by whole cells: orbit like the arrow keys, one step per cell across
  /// (half a step per cell down, cells being twice as tall).
  void Drag(int deltaCols, int deltaRows);
  /// The turntable, `seconds` on: theta advances by kTurntableRadiansPerSecond
  /// a second (wall-clock time: a slow link gets fewer frames, not a slower turn).
  void TurntableAdvance(double seconds);

  Camera CameraFor(int widthCells, int heightCells) const;
  const Scene& CurrentScene() const { return *scene_; }
  /// The scene shown, shared with workers that read it (re-preparation, levels of detail).
  const std::shared_ptr<const Scene>& SharedScene() const { return scene_; }
  DetailMode Detail() const { return detail_; }
  /// The current scene's levels of detail, once built (null before, or when off).
  const DetailLevels* Levels() const {
    return detail_ == DetailMode::kAuto ? levels_.get() : nullptr;
  }
  /// True when levels should be built for the scene shown: auto, a big
  /// enough model, none built yet.
  bool WantsLevels() const;
  /// Levels built for `scene`: kept if it is still the one shown.
  void SetLevels(const std::shared_ptr<const Scene>& scene,
                 std::shared_ptr<const DetailLevels> levels);
  const RenderOptions& Render() const { return render_; }
  const ViewParams& View() const { return view_; }
  double CellAspect() const { return cellAspect_; }
  /// The sun's angles (L mode); 0, 0: the default sun.
  double SunAzimuthRadians() const { return sunAzimuth_; }
  double SunElevationRadians() const { return sunElevation_; }
  /// The distance the model is fitted at: the default one until `f` refits.
  double FitRho() const { return fitRho_; }
  /// The file shown ("" for the demo scene).
  const std::string& ModelPath() const { return paths_[current_]; }
  std::string ModelLabel() const;
  size_t ModelCount() const { return paths_.size(); }
  /// The viewer's --up for models it loads; unset: each file's own.
  std::optional<UpAxis> UpAxisOverride() const { return upAxis_; }
  /// The most memory and import time a load may take.
  const LoadLimits& Limits() const { return loadLimits_; }
  /// The colour mode cells are drawn in now (`c` steps it down to kNone).
  ColourMode Colour() const { return colour_; }
  /// The terminal's answers: the mode now and the most `c` cycles back to
  /// (modes from `best` down to kNone; kNone as best means 256).
  void SetColourModes(ColourMode now, ColourMode best);
  /// The terminal's background the shades are made for.
  termshade::Background Background() const { return background_; }
  void SetBackground(termshade::Background background) { background_ = background; }
  /// The cell aspect the terminal said after start-up.
  void SetCellAspect(double aspect) { cellAspect_ = aspect; }
  /// The glyph mode, and whether the terminal's locale can show the modes beyond ASCII.
  void SetGlyphs(GlyphMode mode, bool utf8) {
    render_.glyphs = mode;
    utf8_ = utf8;
  }
  /// Whether the terminal's locale is UTF-8: names and messages keep their UTF-8 then.
  bool Utf8() const { return utf8_; }
  bool LightMode() const { return lightMode_; }
  bool Turntable() const { return turntable_; }
  bool HelpShown() const { return help_; }
  bool QuitRequested() const { return quit_; }
  const std::string& Message() const { return message_; }
  void SetMessage(std::string message) { message_ = std::move(message); }

  static constexpr double kOrbitStepRadians = 0.1;
  static constexpr double kTurntableRadiansPerSecond = 1.0;
  static constexpr double kAspectStep = 0.05;

 private:
  void StepTo(size_t index);
  void ResetView();
  void Orbit(double dTheta, double dPhi);
  void ChangeDistance(double factor);
  void CycleUpAxis();
  void ShowScene(Scene scene);

  std::vector<std::string> paths_;  ///< "" is the demo scene
  size_t current_ = 0;
  size_t stepFrom_ = 0;  ///< where n and p count from: the last model tried
  std::optional<LoadRequest> pending_;
  bool hasModel_ = false;
  std::optional<LoadError> firstError_;  ///< of the models tried before one loaded
  std::optional<LoadError> startError_;
  std::shared_ptr<const Scene> scene_ = std::make_shared<const Scene>();
  std::shared_ptr<const DetailLevels> levels_;  ///< of scene_
  DetailMode detail_ = DetailMode::kAuto;
  ViewParams view_;
  double fitRho_ = 1.0;
  double cellAspect_ = 2.0;
  RenderOptions render_;
  ColourMode colour_ = ColourMode::kNone;
  ColourMode bestColour_ = ColourMode::k256;  ///< where `c` goes after kNone
  termshade::Background background_ = termshade::Background::kDark;
  bool utf8_ = true;
  std::optional<UpAxis> upAxis_;
  LoadLimits loadLimits_;
  double startTheta_ = 0.3;
  double startPhi_ = 1.3;
  bool lightMode_ = false;
  bool turntable_ = false;
  bool help_ = false;
  bool quit_ = false;
  double sunAzimuth_ = 0.0;
  double sunElevation_ = 0.0;
  std::string message_;
};

}  // namespace termshade
