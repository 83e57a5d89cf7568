#include "tui/ViewerState.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geometry/FitCamera.h"
#include "io/load/ModelLoader.h"
#include "io/read/DatReader.h"
#include "io/scenes/DemoScene.h"

namespace termshade {
namespace {

// The status line has one row: name the file by its last path component.
std::string StatusLineError(LoadError error, bool keepUtf8) {
  const size_t slash = error.file.find_last_of('/');
  if (slash != std::string::npos) error.file = error.file.substr(slash + 1);
  return error.ToString(keepUtf8);
}

// An azimuth within [-pi, pi]: orbiting for a long time shows "theta -2.90", not "theta 1234.56".
double WrapRadians(double angle) {
  return std::remainder(angle, 2 * std::numbers::pi);
}

}  // namespace

Loaded<Mesh> LoadViewerMesh(const std::string& path, const LoadOptions& options) {
  return path.empty() ? ParseDat(DemoSceneText(), std::string(kDemoSceneName))
                      : LoadModelFile(path, options);
}

Loaded<Scene> LoadViewerScene(const std::string& path, const LoadOptions& options,
                              std::optional<UpAxis> upAxis) {
  Loaded<Mesh> mesh = LoadViewerMesh(path, options);
  if (!mesh.Ok()) return mesh.Error();
  return PrepareScene(std::move(mesh.Value()), upAxis);
}

ViewerState::ViewerState(const ViewerOptions& options, double terminalAspect)
    : paths_(options.modelPaths),
      render_(options.render),
      background_(options.background.value_or(termshade::Background::kDark)),
      upAxis_(options.upAxis),
      loadLimits_(options.loadLimits),
      startTheta_(options.theta),
      startPhi_(options.phi) {
  render_.keepDepth = false;  // the screen shows glyphs only
  detail_ = options.detail;
  if (paths_.empty()) paths_.emplace_back();
  cellAspect_ = options.cellAspect.value_or(terminalAspect > 0.0 ? terminalAspect : 2.0);
  SetColourModes(options.colour == ColourMode::kAuto ? ColourMode::kNone : options.colour,
                 options.colour);
}

void ViewerState::SetColourModes(ColourMode now, ColourMode best) {
  colour_ = now == ColourMode::kAuto ? ColourMode::kNone : now;
  bestColour_ = std::max(best == ColourMode::kAuto ? ColourMode::kNone : best, colour_);
  if (bestColour_ == ColourMode::kNone) bestColour_ = ColourMode::k256;
}

void ViewerState::RequestFirst() {
  pending_ = LoadRequest{paths_.front(), 0, std::nullopt};
}

std::optional<LoadError> ViewerState::LoadFirst() {
  RequestFirst();
  while (pending_) RunPendingLoad();
  return startError_;
}

void ViewerState::RequestOpen(const std::string& path) {
  pending_ = LoadRequest{path, std::nullopt, std::nullopt};
}

std::optional<LoadRequest> ViewerState::TakeLoadRequest() {
  std::optional<LoadRequest> request = std::move(pending_);
  pending_.reset();
  return request;
}

void ViewerState::FinishLoad(const LoadRequest& request, Loaded<Scene> scene) {
  if (request.turnTo) {  // u: the model shown, turned; the view stays
    if (!scene.Ok()) {
      message_ = StatusLineError(scene.Error(), utf8_);
      return;
    }
    ShowScene(std::move(scene.Value()));
    message_ = "up axis " + std::string(UpAxisName(*request.turnTo));
    return;
  }
  if (request.index && *request.index >= paths_.size()) return;
  if (!scene.Ok() && !hasModel_ && request.index) {  // starting: on to the next model
    if (!firstError_) firstError_ = scene.Error();
    message_ = StatusLineError(scene.Error(), utf8_);
    const size_t next = *request.index + 1;
    if (next < paths_.size()) {
      pending_ = LoadRequest{paths_[next], next, std::nullopt};
    } else {
      startError_ = firstError_;
    }
    return;
  }
  if (!scene.Ok()) {
    message_ = StatusLineError(scene.Error(), utf8_);
    if (request.index) stepFrom_ = *request.index;  // the next n goes on from here
    return;
  }
  if (request.index) {
    current_ = *request.index;
    if (hasModel_ || !firstError_) message_.clear();  // keep what was skipped on the way
  } else {
    paths_.insert(paths_.begin() + static_cast<std::ptrdiff_t>(current_ + 1), request.path);
    current_ += 1;
  }
  stepFrom_ = current_;
  ShowScene(std::move(scene.Value()));
  hasModel_ = true;
  ResetView();
  if (!request.index) message_ = "opened " + ModelLabel();
}

void ViewerState::OpenPath(const std::string& path) {
  RequestOpen(path);
  RunPendingLoad();
}

void ViewerState::RunPendingLoad() {
  const std::optional<LoadRequest> request = TakeLoadRequest();
  if (!request) return;
  if (request->turnTo) {
    FinishLoad(*request, PrepareScene(scene_->SourceMesh(), *request->turnTo));
  } else {
    FinishLoad(*request, LoadViewerScene(request->path, {}, upAxis_));
  }
}

void ViewerState::ShowScene(Scene scene) {
  scene_ = std::make_shared<const Scene>(std::move(scene));
  levels_.reset();
}

bool ViewerState::WantsLevels() const {
  return hasModel_ && detail_ == DetailMode::kAuto && !levels_ &&
         scene_->triangles.size() >= DetailBuildOptions{}.minSourceTriangles;
}

void ViewerState::SetLevels(const std::shared_ptr<const Scene>& scene,
                            std::shared_ptr<const DetailLevels> levels) {
  if (scene == scene_) levels_ = std::move(levels);
}

void ViewerState::StepTo(size_t index) {
  if (index == current_) {  // back where it started: nothing to load
    stepFrom_ = current_;
    message_.clear();
    return;
  }
  pending_ = LoadRequest{paths_[index], index, std::nullopt};
}

void ViewerState::ResetView() {
  view_ = DefaultView(scene_->diagonalModelUnits);
  view_.theta = startTheta_;
  view_.phi = startPhi_;
  fitRho_ = view_.rho;
  sunAzimuth_ = sunElevation_ = 0.0;
  render_.sunEye = SunFromAngles(0.0, 0.0);
}

void ViewerState::Orbit(double dTheta, double dPhi) {
  if (lightMode_) {
    sunAzimuth_ = WrapRadians(sunAzimuth_ + dTheta);
    sunElevation_ += dPhi;
    render_.sunEye = SunFromAngles(sunAzimuth_, sunElevation_);
    return;
  }
  view_.theta = WrapRadians(view_.theta + dTheta);
  view_.phi = std::clamp(view_.phi + dPhi, 0.0, std::numbers::pi);
}

void ViewerState::ChangeDistance(double factor) {
  const ViewLimits limits = LimitsForDiagonal(scene_->diagonalModelUnits);
  view_.rho = std::clamp(view_.rho * factor, limits.rhoMin, limits.rhoMax);
}

// The next axis of the cycle, for this model only, prepared on the event
// loop's worker; the view stays (turning by an axis permutation keeps the
// bounding box's diagonal and the sphere, so the distances; the width's
// cylinder, and so d, follow the new up axis).
void ViewerState::CycleUpAxis() {
  if (!hasModel_) return;
  pending_ = LoadRequest{paths_[current_], current_, NextUpAxis(scene_->upAxis)};
}

void ViewerState::Apply(ViewerAction action) {
  switch (action) {
    case ViewerAction::kNone:
      break;
    case ViewerAction::kOrbitLeft:
      Orbit(-kOrbitStepRadians, 0.0);
      break;
    case ViewerAction::kOrbitRight:
      Orbit(kOrbitStepRadians, 0.0);
      break;
    case ViewerAction::kOrbitUp:
      Orbit(0.0, -kOrbitStepRadians);
      break;
    case ViewerAction::kOrbitDown:
      Orbit(0.0, kOrbitStepRadians);
      break;
    case ViewerAction::kCloser:
      ChangeDistance(0.5);
      break;
    case ViewerAction::kFarther:
      ChangeDistance(2.0);
      break;
    case ViewerAction::kResetView:
      ResetView();
      break;
    case ViewerAction::kRefit:
      fitRho_ = view_.rho;
      break;
    case ViewerAction::kCycleMethod: {
      static constexpr Method kOrder[] = {Method::kZBuffer, Method::kPainter, Method::kCull,
                                          Method::kWire, Method::kAuto};
      const auto at = std::find(std::begin(kOrder), std::end(kOrder), render_.method);
      const bool last = at == std::end(kOrder) || at + 1 == std::end(kOrder);
      render_.method = last ? kOrder[0] : *(at + 1);
      break;
    }
    case ViewerAction::kCycleShade:
      render_.shade =
          render_.shade == ShadeMode::kContrast ? ShadeMode::kLambert : ShadeMode::kContrast;
      break;
    case ViewerAction::kCycleGlyphs:  // modes beyond ASCII only where the locale shows them
      do {
        render_.glyphs = NextGlyphMode(render_.glyphs);
      } while (!utf8_ && NeedsUtf8(render_.glyphs));
      break;
    case ViewerAction::kToggleColour:  // from the most the terminal has down to none
      colour_ = colour_ == ColourMode::kNone
                    ? bestColour_
                    : static_cast<ColourMode>(static_cast<int>(colour_) - 1);
      break;
    case ViewerAction::kToggleLightMode:
      lightMode_ = !lightMode_;
      break;
    case ViewerAction::kToggleTurntable:
      turntable_ = !turntable_;
      break;
    case ViewerAction::kToggleCulling:
      render_.cullBackFaces = !render_.cullBackFaces;
      break;
    case ViewerAction::kToggleTextures:
      render_.textures = !render_.textures;
      break;
    case ViewerAction::kCycleUpAxis:
      CycleUpAxis();
      break;
    case ViewerAction::kOpenFile:
      break;  // the event loop owns the prompt
    case ViewerAction::kNextModel:
      StepTo((stepFrom_ + 1) % paths_.size());
      break;
    case ViewerAction::kPreviousModel:
      StepTo((stepFrom_ + paths_.size() - 1) % paths_.size());
      break;
    case ViewerAction::kToggleHelp:
      help_ = !help_;
      break;
    case ViewerAction::kAspectDown:
      cellAspect_ = std::max(0.5, cellAspect_ - kAspectStep);
      break;
    case ViewerAction::kAspectUp:
      cellAspect_ = std::min(4.0, cellAspect_ + kAspectStep);
      break;
    case ViewerAction::kShowRenderCommand:  // the event loop composes it: it knows the frame
      break;
    case ViewerAction::kQuit:
      quit_ = true;
      break;
  }
}

void ViewerState::Drag(int deltaCols, int deltaRows) {
  Orbit(-kOrbitStepRadians * deltaCols, -0.5 * kOrbitStepRadians * deltaRows * cellAspect_);
}

void ViewerState::TurntableAdvance(double seconds) {
  view_.theta = WrapRadians(view_.theta + kTurntableRadiansPerSecond * seconds);
}

Camera ViewerState::CameraFor(int widthCells, int heightCells) const {
  return FitCameraAt(*scene_, view_, fitRho_, widthCells, heightCells, cellAspect_,
                     Framing::kOrbit);
}

std::string ViewerState::ModelLabel() const {
  const std::string& path = paths_[current_];
  std::string label =
      path.empty() ? std::string(kDemoSceneName) : SanitizeForTerminal(path, 4096, utf8_);
  if (paths_.size() > 1) {
    label += " [" + std::to_string(current_ + 1) + "/" + std::to_string(paths_.size()) + "]";
  }
  return label;
}

}  // namespace termshade
