#include "tui/Viewer.h"

#include <curses.h>
#include <langinfo.h>
#include <poll.h>
#include <unistd.h>

#include <chrono>
#include <clocale>
#include <cstdio>
#include <cstdlib>
#include <iostream>

#include "io/LoadError.h"
#include "raster/Renderer.h"
#include "tui/LineEditor.h"
#include "tui/PathCompletion.h"
#include "tui/PromptPath.h"
#include "tui/ScreenPainter.h"
#include "tui/StatusLine.h"
#include "tui/TerminalSession.h"
#include "tui/TerminalWriter.h"
#include "tui/ViewerState.h"

namespace termshade {
namespace {

using Clock = std::chrono::steady_clock;

constexpr int kMinCols = 20;
constexpr int kMinRows = 4;
constexpr auto kTurntablePeriod = std::chrono::milliseconds(40);  // at most 25 frames a second

std::optional<NamedKey> NamedKeyFor(int key) {
  switch (key) {
    case KEY_LEFT:
      return NamedKey::kLeft;
    case KEY_RIGHT:
      return NamedKey::kRight;
    case KEY_UP:
      return NamedKey::kUp;
    case KEY_DOWN:
      return NamedKey::kDown;
    case KEY_PPAGE:
      return NamedKey::kPageUp;
    case KEY_NPAGE:
      return NamedKey::kPageDown;
    case KEY_IC:
      return NamedKey::kInsert;
    case KEY_DC:
      return NamedKey::kDelete;
    case 27:
      return NamedKey::kEscape;
    default:
      return std::nullopt;
  }
}

std::string HomeDirectory() {
  const char* home = std::getenv("HOME");
  return home != nullptr ? home : "";
}

class EventLoop {
 public:
  EventLoop(ViewerState& state, TerminalSession& session)
      : state_(state), session_(session), writer_(session.Colours(), STDOUT_FILENO) {}

  void Run() {
    auto nextTurntableFrame = Clock::now();
    while (!state_.QuitRequested()) {
      if (dirty_) Draw();
      // Step 1: sleep until input, a signal, or the next turntable frame.
      int timeoutMs = -1;
      if (state_.Turntable()) {
        const auto wait = std::chrono::duration_cast<std::chrono::milliseconds>(nextTurntableFrame -
                                                                                Clock::now());
        timeoutMs = static_cast<int>(std::max<long long>(0, wait.count()));
      }
      pollfd fds[2] = {{STDIN_FILENO, POLLIN, 0}, {session_.SignalFd(), POLLIN, 0}};
      poll(fds, 2, timeoutMs);
      if (!HandleSignals()) return;
      if ((fds[0].revents & (POLLHUP | POLLERR | POLLNVAL)) != 0) return;  // terminal gone
      // Step 2: every key that queued up while drawing, applied before one redraw.
      for (int key = session_.NextKey(); key != ERR; key = session_.NextKey()) HandleKey(key);
      // Step 3: the turntable, at a capped rate.
      if (state_.Turntable() && Clock::now() >= nextTurntableFrame) {
        state_.TurntableStep();
        dirty_ = true;
        nextTurntableFrame = std::max(nextTurntableFrame + kTurntablePeriod, Clock::now());
      }
    }
  }

 private:
  // False when a signal ends the viewer.
  bool HandleSignals() {
    TerminalSession::Signals signals = session_.TakeSignals();
    if (signals.suspend) {
      writer_.Release();
      session_.Suspend();
      signals.terminate = signals.terminate || session_.TakeSignals().terminate;
      signals.resumed = true;
    }
    if (signals.resumed) {  // the shell or another program drew over the screen
      writer_.Invalidate();
      dirty_ = true;
    }
    return !signals.terminate;
  }

  void HandleKey(int key) {
    if (prompting_) {
      HandlePromptKey(key);
      return;
    }
    if (key == KEY_RESIZE) {
      dirty_ = true;
      return;
    }
    if (state_.HelpShown()) {  // any key closes the help
      state_.Apply(ViewerAction::kToggleHelp);
      dirty_ = true;
      return;
    }
    if (key == KEY_MOUSE) {
      HandleMouse();
      return;
    }
    ViewerAction action = ViewerAction::kNone;
    if (const auto named = NamedKeyFor(key)) {
      action = ActionForNamedKey(*named);
      if (*named == NamedKey::kEscape && state_.LightMode())
        action = ViewerAction::kToggleLightMode;
    } else if (key >= 0 && key < 128) {
      action = ActionForChar(key);
    }
    if (action == ViewerAction::kOpenFile) {
      prompting_ = true;
      editor_.Clear();
      completionMatches_ = 1;
    }
    if ((action == ViewerAction::kNextModel || action == ViewerAction::kPreviousModel) &&
        state_.ModelCount() > 1) {
      ShowBusy("loading...");
    }
    if (action != ViewerAction::kNone) {
      state_.SetMessage("");
      state_.Apply(action);
      dirty_ = true;
    }
  }

  void HandlePromptKey(int key) {
    completionMatches_ = 1;
    switch (key) {
      case 27:
        prompting_ = false;
        break;
      case '\r':
      case '\n':
      case KEY_ENTER:
        prompting_ = false;
        if (const std::string path = PromptPath(editor_.Text(), HomeDirectory()); !path.empty()) {
          ShowBusy("loading " + SanitizeForTerminal(path, 4096));
          state_.OpenPath(path);
        }
        break;
      case KEY_BACKSPACE:
      case 127:
      case 8:
        editor_.Backspace();
        break;
      case KEY_DC:
        editor_.Delete();
        break;
      case KEY_LEFT:
        editor_.Left();
        break;
      case KEY_RIGHT:
        editor_.Right();
        break;
      case KEY_HOME:
      case 1:
        editor_.Home();
        break;
      case KEY_END:
      case 5:
        editor_.End();
        break;
      case 21:
        editor_.Clear();
        break;
      case '\t': {
        const PathCompletion completion = CompletePath(editor_.Text(), HomeDirectory());
        editor_.SetText(completion.text);
        completionMatches_ = completion.matches;
        dirty_ = true;
        return;  // the hint stays until the next key
      }
      case KEY_RESIZE:
        break;
      default:
        if (key >= 0 && key < 0x100) editor_.InsertByte(static_cast<unsigned char>(key));
    }
    dirty_ = true;
  }

  void HandleMouse() {
    MEVENT event{};
    if (getmouse(&event) != OK) return;
    if ((event.bstate & BUTTON4_PRESSED) != 0) state_.Apply(ViewerAction::kCloser);
    if ((event.bstate & BUTTON5_PRESSED) != 0) state_.Apply(ViewerAction::kFarther);
    if ((event.bstate & BUTTON1_PRESSED) != 0) {
      dragging_ = true;
      dragCol_ = event.x;
      dragRow_ = event.y;
    } else if (dragging_ && (event.bstate & (REPORT_MOUSE_POSITION | BUTTON1_RELEASED)) != 0) {
      state_.Drag(event.x - dragCol_, event.y - dragRow_);
      dragCol_ = event.x;
      dragRow_ = event.y;
      if ((event.bstate & BUTTON1_RELEASED) != 0) dragging_ = false;
    }
    dirty_ = true;
  }

  // A terminal that would scroll on its bottom-right cell gets one cell less.
  static int StatusCols(int cols) {
    return TerminalWriter::BottomRightWritable() ? cols : cols - 1;
  }

  // Puts what over the status line at once: loading a big model takes a while.
  void ShowBusy(const std::string& what) {
    const int cols = grid_.WidthCells(), rows = grid_.HeightCells();
    if (cols < kMinCols || rows < kMinRows) return;
    painter_.PaintStatus(ComposeStatusLine({{what, 0, false, Elision::kMiddle}}, StatusCols(cols)),
                         grid_);
    writer_.Present(grid_, state_.Colour(), state_.Render().ramp.LevelCount(), std::nullopt);
  }

  void Draw() {
    dirty_ = false;
    const int cols = TerminalSession::WidthCells(), rows = TerminalSession::HeightCells();
    grid_.Resize(cols, rows);
    const int levelCount = state_.Render().ramp.LevelCount();
    if (cols < kMinCols || rows < kMinRows) {
      painter_.PaintTooSmall(grid_);
      writer_.Present(grid_, false, levelCount, std::nullopt);
      return;
    }
    // Step 1: the frame, through the one shared pipeline.
    const int frameRows = rows - 1;
    cells_.Resize(cols, frameRows);
    depth_.Resize(cols, frameRows);
    const auto start = Clock::now();
    const RenderStats stats = renderer_.Render(
        state_.CurrentScene(), state_.CameraFor(cols, frameRows), state_.Render(), depth_, cells_);
    const double frameMs = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    painter_.PaintFrame(cells_, grid_);
    // Step 2: overlays and the status line, then one write of what changed.
    if (state_.HelpShown()) painter_.PaintHelp(grid_);
    std::optional<std::pair<int, int>> cursor;
    if (prompting_) {
      // After Tab: how many names matched, when not exactly one.
      const std::string label = completionMatches_ == 1 ? "open: "
                                : completionMatches_ == 0
                                    ? "open (no match): "
                                    : "open (" + std::to_string(completionMatches_) + " matches): ";
      cursor = painter_.PaintPrompt(label, editor_, grid_);
    } else {
      painter_.PaintStatus(StatusText(stats, frameMs, StatusCols(cols)), grid_);
    }
    writer_.Present(grid_, state_.Colour(), levelCount, cursor);
  }

  // The status line, most important first: the message or model, the view,
  // the help hint, the method, what was drawn, the frame time.
  std::string StatusText(const RenderStats& stats, double frameMs, int cols) const {
    constexpr int kLeadMinCells = 32;  // a long path keeps its tail: file name and [i/n]
    const ViewParams& view = state_.View();
    const RenderOptions& render = state_.Render();
    char viewText[96], drawnText[96], timeText[32];
    std::snprintf(viewText, sizeof viewText, "theta %.2f phi %.2f rho %.3g", view.theta, view.phi,
                  view.rho);
    std::snprintf(drawnText, sizeof drawnText, "%d/%zu faces %d tris", stats.facesVisible,
                  state_.CurrentScene().FaceCount(), stats.trianglesDrawn);
    std::snprintf(timeText, sizeof timeText, "%.2f ms", frameMs);
    const std::string upText = "up " + std::string(UpAxisName(state_.CurrentScene().upAxis));
    // A message is shown whole if it can be; the model's path gives way to the view.
    StatusSegment lead{SanitizeForTerminal(state_.Message(), 4096), 0, false, Elision::kMiddle};
    if (lead.text.empty()) {
      lead.text =
          state_.LightMode() ? "LIGHT: arrows move the sun, L or Esc ends" : state_.ModelLabel();
      lead.elision = Elision::kFront;
      lead.minWidthCells = kLeadMinCells;
    }
    const std::string method = std::string(MethodName(render.method)) + " " +
                               std::string(ShadeModeName(render.shade)) +
                               (render.cullBackFaces ? "" : " 2-sided");
    return ComposeStatusLine({lead,
                              {method, 3, false},
                              {drawnText, 4, false},
                              {upText, 4, false},
                              {viewText, 1, true},
                              {timeText, 5, true},
                              {"? help", 2, true}},
                             cols);
  }

  ViewerState& state_;
  TerminalSession& session_;
  ScreenPainter painter_;
  TerminalWriter writer_;
  ScreenGrid grid_;
  Renderer renderer_;
  CellBuffer cells_;
  DepthBuffer depth_;
  LineEditor editor_;
  int completionMatches_ = 1;  ///< names the last Tab matched (1: no hint)
  bool prompting_ = false;
  bool dirty_ = true;
  bool dragging_ = false;
  int dragCol_ = 0;
  int dragRow_ = 0;
};

}  // namespace

int RunViewer(const ViewerOptions& options) {
  if (const auto problem = TerminalProblem()) {
    std::cerr << "termshade: " << *problem
              << ".\nFor frames without a terminal use: termshade render MODEL [options]\n";
    return 2;
  }
  ViewerOptions effective = options;
  const char* noColour = std::getenv("NO_COLOR");
  if (noColour != nullptr && *noColour != '\0') effective.monochrome = true;
  ViewerState state(effective, TerminalSession::ReportedCellAspect());
  if (const auto error = state.LoadFirst()) {
    std::cerr << error->ToString() << "\n";
    return 1;
  }
  std::setlocale(LC_ALL, "");
  const std::string codeset = nl_langinfo(CODESET);
  if (!options.render.ramp.IsAscii() && codeset != "UTF-8") {
    std::cerr << "termshade: the ramp has characters beyond ASCII, which need a UTF-8 locale "
                 "(this one is "
              << SanitizeForTerminal(codeset) << "); try LANG=C.UTF-8\n";
    return 2;
  }
  TerminalSession session;
  if (!session.Ok()) {
    std::cerr << "termshade: cannot start the terminal interface for TERM="
              << SanitizeForTerminal(std::getenv("TERM") != nullptr ? std::getenv("TERM") : "")
              << "\n";
    return 2;
  }
  EventLoop loop(state, session);
  loop.Run();
  return 0;
}

}  // namespace termshade
