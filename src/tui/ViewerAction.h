#pragma once

namespace termshade {

/// What a key press or mouse event asks of the viewer, independent of ncurses.
enum class ViewerAction {
  kNone,
  kOrbitLeft,
  kOrbitRight,
  kOrbitUp,
  kOrbitDown,
  kCloser,
  kFarther,
  kResetView,
  kRefit,
  kCycleMethod,
  kCycleShade,
  kCycleGlyphs,
  kToggleColour,
  kToggleLightMode,
  kToggleTurntable,
  kToggleCulling,
  kToggleTextures,
  kCycleUpAxis,
  kOpenFile,
  kNextModel,
  kPreviousModel,
  kToggleHelp,
  kAspectDown,
  kAspectUp,
  kShowRenderCommand,
  kQuit,
};

/// Maps a key (an ASCII code, or one of the named keys below) to its action.
enum class NamedKey { kLeft, kRight, kUp, kDown, kPageUp, kPageDown, kInsert, kDelete, kEscape };
ViewerAction ActionForChar(int ascii);
/// Whether the action moves what is shown (orbit, distance, reset, refit,
/// aspect): frames drawn for it may be cheap on a slow link (MotionFrames).
bool MovesView(ViewerAction action);
ViewerAction ActionForNamedKey(NamedKey key);

}  // namespace termshade
