#pragma once

#include <string>
#include <vector>

#include "geometry/Camera.h"
#include "geometry/Scene.h"
#include "io/LoadError.h"
#include "raster/RenderOptions.h"
#include "tui/Viewer.h"
#include "tui/ViewerAction.h"

namespace termshade {

/// Loads a model file, or the embedded demo scene for an empty path; the up
/// axis is upAxis when given, else the file's own.
Loaded<Scene> LoadViewerScene(const std::string& path, std::optional<UpAxis> upAxis = {});

/// Everything the viewer shows, changed only through actions: no terminal
/// code here, so it is tested directly.
class ViewerState {
 public:
  /// terminalAspect: the cell aspect the terminal reports (0 if it does not).
  ViewerState(const ViewerOptions& options, double terminalAspect);

  /// Opens the first model; the error (if any) means the viewer cannot start.
  std::optional<LoadError> LoadFirst();
  /// Opens a model by path and adds it to the list; on failure keeps the current one.
  void OpenPath(const std::string& path);

  void Apply(ViewerAction action);
  /// Mouse drag by whole cells: orbit like the arrow keys, one step per cell across
  /// (half a step per cell down, cells being twice as tall).
  void Drag(int deltaCols, int deltaRows);
  /// One turntable frame: theta advances by kTurntableStepRadians.
  void TurntableStep();

  Camera CameraFor(int widthCells, int heightCells) const;
  const Scene& CurrentScene() const { return scene_; }
  const RenderOptions& Render() const { return render_; }
  const ViewParams& View() const { return view_; }
  double CellAspect() const { return cellAspect_; }
  std::string ModelLabel() const;
  size_t ModelCount() const { return paths_.size(); }
  bool Colour() const { return colour_; }
  bool LightMode() const { return lightMode_; }
  bool Turntable() const { return turntable_; }
  bool HelpShown() const { return help_; }
  bool QuitRequested() const { return quit_; }
  const std::string& Message() const { return message_; }
  void SetMessage(std::string message) { message_ = std::move(message); }

  static constexpr double kOrbitStepRadians = 0.1;
  static constexpr double kTurntableStepRadians = 0.04;
  static constexpr double kAspectStep = 0.05;

 private:
  void SwitchTo(size_t index);
  void ResetView();
  void Orbit(double dTheta, double dPhi);
  void ChangeDistance(double factor);
  void CycleUpAxis();

  std::vector<std::string> paths_;  ///< "" is the demo scene
  size_t current_ = 0;
  Scene scene_;
  ViewParams view_;
  double fitRho_ = 1.0;
  double cellAspect_ = 2.0;
  RenderOptions render_;
  std::optional<UpAxis> upAxis_;
  double startTheta_ = 0.3;
  double startPhi_ = 1.3;
  bool colour_ = true;
  bool lightMode_ = false;
  bool turntable_ = false;
  bool help_ = false;
  bool quit_ = false;
  double sunAzimuth_ = 0.0;
  double sunElevation_ = 0.0;
  std::string message_;
};

}  // namespace termshade
