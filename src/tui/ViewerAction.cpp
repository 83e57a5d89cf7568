#include "tui/ViewerAction.h"

namespace termshade {

ViewerAction ActionForChar(int ascii) {
  switch (ascii) {
    case 'h':
      return ViewerAction::kOrbitLeft;
    case 'l':
      return ViewerAction::kOrbitRight;
    case 'k':
      return ViewerAction::kOrbitUp;
    case 'j':
      return ViewerAction::kOrbitDown;
    case '+':
    case '=':
      return ViewerAction::kCloser;
    case '-':
    case '_':
      return ViewerAction::kFarther;
    case 'r':
      return ViewerAction::kResetView;
    case 'f':
      return ViewerAction::kRefit;
    case 'm':
      return ViewerAction::kCycleMethod;
    case 's':
      return ViewerAction::kCycleShade;
    case 'c':
      return ViewerAction::kToggleColour;
    case 'g':
      return ViewerAction::kCycleGlyphs;
    case 'L':
      return ViewerAction::kToggleLightMode;
    case ' ':
      return ViewerAction::kToggleTurntable;
    case 'b':
      return ViewerAction::kToggleCulling;
    case 't':
      return ViewerAction::kToggleTextures;
    case 'u':
      return ViewerAction::kCycleUpAxis;
    case 'o':
      return ViewerAction::kOpenFile;
    case 'n':
      return ViewerAction::kNextModel;
    case 'p':
      return ViewerAction::kPreviousModel;
    case '?':
      return ViewerAction::kToggleHelp;
    case 'a':
      return ViewerAction::kAspectDown;
    case 'A':
      return ViewerAction::kAspectUp;
    case 'y':
      return ViewerAction::kShowRenderCommand;
    case 'q':
    case 'Q':
      return ViewerAction::kQuit;
    default:
      return ViewerAction::kNone;
  }
}

bool MovesView(ViewerAction action) {
  switch (action) {
    case ViewerAction::kOrbitLeft:
    case ViewerAction::kOrbitRight:
    case ViewerAction::kOrbitUp:
    case ViewerAction::kOrbitDown:
    case ViewerAction::kCloser:
    case ViewerAction::kFarther:
    case ViewerAction::kResetView:
    case ViewerAction::kRefit:
    case ViewerAction::kAspectDown:
    case ViewerAction::kAspectUp:
      return true;
    default:
      return false;
  }
}

ViewerAction ActionForNamedKey(NamedKey key) {
  switch (key) {
    case NamedKey::kLeft:
      return ViewerAction::kOrbitLeft;
    case NamedKey::kRight:
      return ViewerAction::kOrbitRight;
    case NamedKey::kUp:
      return ViewerAction::kOrbitUp;
    case NamedKey::kDown:
      return ViewerAction::kOrbitDown;
    case NamedKey::kPageUp:
    case NamedKey::kInsert:
      return ViewerAction::kCloser;
    case NamedKey::kPageDown:
    case NamedKey::kDelete:
      return ViewerAction::kFarther;
    case NamedKey::kEscape:
      return ViewerAction::kNone;
  }
  return ViewerAction::kNone;
}

}  // namespace termshade
