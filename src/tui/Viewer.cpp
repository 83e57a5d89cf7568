#include "tui/Viewer.h"

#include <curses.h>
#include <langinfo.h>
#include <poll.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <clocale>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <vector>

#include "geometry/LevelOfDetail.h"
#include "geometry/RayBvh.h"
#include "io/load/ExtrasBudget.h"
#include "io/read/LoadError.h"
#include "io/read/LoadOptions.h"
#include "process/HeapPolicy.h"
#include "raster/DetailPick.h"
#include "raster/RayCastStage.h"
#include "raster/Renderer.h"
#include "tui/ClipboardSequence.h"
#include "tui/FramePacer.h"
#include "tui/InputDecoder.h"
#include "tui/LineEditor.h"
#include "tui/LoadJob.h"
#include "tui/MotionFrames.h"
#include "tui/PathCompletion.h"
#include "tui/PromptPath.h"
#include "tui/RetiredJobs.h"
#include "tui/SceneJob.h"
#include "tui/ScreenPainter.h"
#include "tui/StatusFields.h"
#include "tui/StatusLine.h"
#include "tui/TerminalColours.h"
#include "tui/TerminalQueries.h"
#include "tui/TerminalSession.h"
#include "tui/TerminalWriter.h"
#include "tui/ViewCommand.h"
#include "tui/ViewerRecording.h"
#include "tui/ViewerState.h"

namespace termshade {
namespace {

using Clock = std::chrono::steady_clock;

constexpr int kMinCols = 20;
constexpr int kMinRows = 4;
constexpr auto kTurntablePeriod = std::chrono::milliseconds(40);  // at most 25 frames a second
// A terminal that does not answer: how often its output queue is looked at.
constexpr int kOutputQueuePollMs = 10;
// How long answers still in flight are waited for, and read, before the
// terminal goes back to the shell (at q, or Ctrl-Z): else they would reach
// the shell as typed text.
constexpr auto kQuitAnswerWait = std::chrono::milliseconds(3000);
constexpr auto kSuspendAnswerWait = std::chrono::milliseconds(1000);
constexpr int kLoadProgressPollMs = 100;  // how often a load's progress is looked at
// How long the rest of a mouse report that has begun may take to arrive.
constexpr int kReportRestMs = 50;
// How often a sequence cut short is looked at while its rest has not come.
constexpr int kRestGiveUpPollMs = 250;

/// What the terminal's start-up answers may decide: only what no option fixed.
struct AnswerUse {
  bool colour = false;      ///< --color auto: truecolor where the terminal says it has it
  bool background = false;  ///< no --background
  bool cellAspect = false;  ///< no --cell-aspect, and TIOCGWINSZ gave no pixel size
  ColourMode terminalColours = ColourMode::kNone;  ///< the most terminfo and COLORTERM say
};

/// How the event loop ended.
struct LoopOutcome {
  int signalNumber = 0;        ///< the signal that ended it, or 0 (q)
  bool abandonedLoad = false;  ///< a worker was still loading: leave with _Exit
  std::string cancelledStart;  ///< the first model's load cancelled by Esc: its name
};

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

using DetailJob = SceneJob<DetailLevels>;
using HierarchyJob = SceneJob<RayBvh>;

DetailLevels BuildLevels(const Scene& scene, const std::atomic<bool>& cancel) {
  DetailBuildOptions options;
  options.cancel = &cancel;
  return BuildDetailLevels(scene, options);
}

RayBvh BuildHierarchy(const Scene& scene, const std::atomic<bool>& cancel) {
  return BuildRayBvh(scene, &cancel);
}

class EventLoop {
 public:
  EventLoop(ViewerState& state, TerminalSession& session, ViewerRecording* recording,
            AnswerUse answerUse)
      : state_(state),
        session_(session),
        recording_(recording),
        writer_(STDOUT_FILENO),
        input_([&session] { return session.NextKey(); },
               [&session] { return session.NextKeyWithin(kReportRestMs); }),
        answerUse_(answerUse) {}

  LoopOutcome Run() {
    LoopOutcome outcome;
    AskTerminal();
    while (!state_.QuitRequested() && !state_.StartError()) {
      StartRequestedLoad();
      if (dirty_ && MayDraw()) {
        TurnTurntable();
        Draw();
      }
      UpdateDetailJob();
      UpdateHierarchyJob();
      // Step 1: sleep until input (the terminal's answer among it), a
      // signal, a finished load, the next turntable frame, a timeout of the
      // answer, or a look at the load's progress.
      int timeoutMs = -1;
      const auto wakeWithin = [&timeoutMs](int ms) {
        if (ms >= 0) timeoutMs = timeoutMs < 0 ? ms : std::min(timeoutMs, ms);
      };
      const auto now = Clock::now();
      if (dirty_) {  // a frame waits for the terminal
        wakeWithin(pacer_.WakeMs(now));
        if (!pacer_.Answering()) wakeWithin(kOutputQueuePollMs);
      } else if (state_.Turntable()) {
        const auto wait =
            std::chrono::ceil<std::chrono::milliseconds>(nextTurntableFrame_ - now).count();
        wakeWithin(static_cast<int>(std::max<long long>(0, wait)));
      }
      wakeWithin(motion_.WakeMs(now, turning_));  // the full frame after cheap ones
      if (job_ || retired_.Count() > 0) wakeWithin(kLoadProgressPollMs);
      if (input_.WaitsForRest()) wakeWithin(kRestGiveUpPollMs);  // to give it up in time
      pollfd fds[5] = {{STDIN_FILENO, POLLIN, 0},
                       {session_.SignalFd(), POLLIN, 0},
                       {job_ ? job_->ReadyFd() : -1, POLLIN, 0},
                       {detailJob_ ? detailJob_->ReadyFd() : -1, POLLIN, 0},
                       {hierarchyJob_ ? hierarchyJob_->ReadyFd() : -1, POLLIN, 0}};
      poll(fds, 5, timeoutMs);
      if (const int signalNumber = HandleSignals(); signalNumber != 0) {
        outcome.signalNumber = signalNumber;
        break;
      }
      if ((fds[0].revents & (POLLHUP | POLLERR | POLLNVAL)) != 0) break;  // terminal gone
      // Step 2: every key that queued up while drawing or waiting for the
      // terminal, applied before one redraw: the next frame shows the newest view.
      input_.SetAnswerDue(pacer_.Answering() && pacer_.RequestsInFlight() > 0);
      for (auto event = input_.Next(); event; event = input_.Next()) HandleInput(*event);
      SettleRecordingTheme();
      if (state_.Turntable() != turning_) {  // space: turning starts (or stops) now
        turning_ = state_.Turntable();
        lastTurn_ = Clock::now();
        nextTurntableFrame_ = lastTurn_;
      }
      // Step 3: a finished load, or news of one still running.
      if (job_ && job_->Finished()) FinishLoad();
      if (job_ && LoadingText() != shownLoadingText_) dirty_ = true;
      UpdateDetailJob();
      UpdateHierarchyJob();
      // Step 4: the turntable, at a capped rate (turned when the frame is drawn).
      if (state_.Turntable() && Clock::now() >= nextTurntableFrame_) dirty_ = true;
      // Step 5: the view rests after cheap frames: the full frame follows.
      if (motion_.FullFrameDue(Clock::now(), turning_)) dirty_ = true;
    }
    AwaitAnswers(kQuitAnswerWait);
    // A worker still loading is asked to stop, and left to end alone if it runs on.
    outcome.abandonedLoad = retired_.Busy() || (job_ && !job_->Stop()) ||
                            (detailJob_ && !detailJob_->Finished()) ||
                            (hierarchyJob_ && !hierarchyJob_->Finished());
    if (cancelledStart_) outcome.cancelledStart = cancelledName_;
    job_.reset();
    detailJob_.reset();
    hierarchyJob_.reset();
    return outcome;
  }

 private:
  // Ahead of the first frame's bytes, in one write: the start-up queries
  // and the DA1 request (whether the terminal answers is known within a
  // round trip, however slow the link). Their answers are read for up to
  // kStartupAnswerWaitMs, the DA1 answer (always the last) ending the wait;
  // keys typed meanwhile are handled after. Answers later than the wait (a
  // slow link) still count until the DA1 answer (HandleInput).
  void AskTerminal() {
    writer_.Send(std::string(kStartupQueries) + std::string(FramePacer::kRequest));
    pacer_.RequestSent(Clock::now(), 0);
    std::vector<InputEvent> early;
    const auto deadline = Clock::now() + std::chrono::milliseconds(kStartupAnswerWaitMs);
    input_.ExpectStartupAnswers();  // late pieces of them stay answers, never keys
    input_.SetAnswerDue(true);
    while (!startupAnswered_) {
      const auto left = std::chrono::ceil<std::chrono::milliseconds>(deadline - Clock::now());
      if (left.count() <= 0) break;
      pollfd fd{STDIN_FILENO, POLLIN, 0};
      if (poll(&fd, 1, static_cast<int>(left.count())) < 0 && errno != EINTR) break;
      if ((fd.revents & (POLLHUP | POLLERR | POLLNVAL)) != 0) break;  // terminal gone
      for (auto event = input_.Next(); event; event = input_.Next()) {
        if (event->reply || event->deviceAnswer) {
          HandleInput(*event);
        } else {
          early.push_back(*event);
        }
      }
    }
    for (const InputEvent& event : early) HandleInput(event);
    SettleRecordingTheme();
  }

  // The recording's header takes the background the start-up answers said,
  // once no more of them come (their DA1 answer read, or no longer expected).
  void SettleRecordingTheme() {
    if (recording_ == nullptr || recordingThemeSettled_) return;
    if (answerUse_.background && !startupAnswered_ && input_.ExpectingStartupAnswers()) return;
    recording_->SettleTheme(ThemeFor(state_.Background()));
    recordingThemeSettled_ = true;
  }

  // One answer to the start-up queries, and what the answers say now, where
  // no option decided it.
  void TakeAnswer(const TerminalReply& reply) {
    TakeReply(reply, answers_);
    if (answerUse_.background && answers_.background) state_.SetBackground(*answers_.background);
    if (answerUse_.cellAspect && answers_.cellAspect > 0.0) {
      state_.SetCellAspect(answers_.cellAspect);
    }
    const ColourMode best =
        answers_.directColour ? ColourMode::kTrueColour : answerUse_.terminalColours;
    ColourMode now = state_.Colour();
    if (answerUse_.colour && now != ColourMode::kNone) now = std::max(now, best);
    state_.SetColourModes(now, best);
    dirty_ = true;
  }

  // Whether a frame may go out now: the terminal has answered for the last
  // one (FramePacer); one that does not answer has taken all that was sent.
  bool MayDraw() {
    const auto now = Clock::now();
    // The full frame once the view rests may follow the last cheap one
    // without waiting for its answer: the picture is whole a round trip sooner.
    if (pacer_.Answering() && pacer_.RequestsInFlight() <= 1 && motion_.FullFrameDue(now, turning_))
      return true;
    if (!pacer_.MayDraw(now)) return false;
    return pacer_.Answering() || TerminalSession::OutputQueuedBytes() == 0;
  }

  // The turntable turns by the time since its last frame: as fast on a slow
  // link, with fewer frames.
  void TurnTurntable() {
    if (!turning_) return;
    const auto now = Clock::now();
    state_.TurntableAdvance(std::chrono::duration<double>(now - lastTurn_).count());
    motion_.ViewMoved(now);
    lastTurn_ = now;
    nextTurntableFrame_ = std::max(nextTurntableFrame_ + kTurntablePeriod, now);
  }

  // The frame in grid_, then the request for the terminal's answer, in one write.
  // `full`: what a recording gets instead of grid_ (the full frame of a cheap one).
  void Present(std::optional<std::pair<int, int>> cursor, const ScreenGrid* full = nullptr) {
    if (recording_ != nullptr)
      recording_->Frame(full != nullptr ? *full : grid_, cursor, Clock::now());
    writer_.Present(grid_, cursor, FramePacer::kRequest);
    pacer_.RequestSent(Clock::now(), writer_.LastFrameBytes());
  }

  // Reads the answers still in flight (for up to `limit`), before the shell
  // gets the terminal: keys read meanwhile are dropped.
  void AwaitAnswers(std::chrono::milliseconds limit) {
    if (!pacer_.Answering()) return;
    const auto deadline = Clock::now() + limit;
    while (pacer_.RequestsInFlight() > 0) {
      const auto left = std::chrono::ceil<std::chrono::milliseconds>(deadline - Clock::now());
      if (left.count() <= 0) return;
      pollfd fd{STDIN_FILENO, POLLIN, 0};
      if (poll(&fd, 1, static_cast<int>(left.count())) < 0 && errno != EINTR) return;
      if ((fd.revents & (POLLHUP | POLLERR | POLLNVAL)) != 0) return;  // terminal gone
      input_.SetAnswerDue(true);
      for (auto event = input_.Next(); event; event = input_.Next()) {
        if (event->deviceAnswer) pacer_.AnswerRead(Clock::now());
      }
    }
  }

  // Starts the load the state asked for, unless one is running already.
  void StartRequestedLoad() {
    if (job_ || !state_.LoadRequested()) return;
    // The scene is about to change: its builds stop, and the load waits for them.
    RetireSceneJobs();
    if (retired_.Busy()) return;
    std::optional<LoadRequest> request = state_.TakeLoadRequest();
    if (!request) return;
    jobRequest_ = std::move(*request);
    if (jobRequest_.turnTo) {
      job_ = std::make_unique<LoadJob>(jobRequest_.path, state_.SharedScene(), *jobRequest_.turnTo);
    } else {
      job_ = std::make_unique<LoadJob>(jobRequest_.path, state_.UpAxisOverride(), state_.Limits());
    }
    shownLoadingText_.clear();
    dirty_ = true;
  }

  void FinishLoad() {
    Loaded<Scene> scene = job_->Take();
    job_.reset();
    state_.FinishLoad(jobRequest_, std::move(scene));
    ReturnFreedMemory();  // the replaced model's pages, kept for reuse while loading
    dirty_ = true;
  }

  // Levels of detail: built on a worker once the scene's first exact frame is
  // up and no load runs; taken when done; dropped when the scene changed.
  void UpdateDetailJob() {
    if (detailJob_ && detailJob_->ForScene() != state_.SharedScene()) {
      retired_.Keep(std::move(detailJob_));  // a cancelled build may still be running
      ReturnFreedMemory();                   // a finished one held the replaced scene until now
    }
    if (detailJob_ && detailJob_->Finished()) {
      state_.SetLevels(detailJob_->ForScene(), detailJob_->Take());
      detailJob_.reset();
      dirty_ = true;
    }
    if (!detailJob_ && !hierarchyJob_ && MayStartBuild() && framesDrawn_ > 0 &&
        state_.WantsLevels() && !WantsHierarchy()) {
      const std::shared_ptr<const Scene>& scene = state_.SharedScene();
      // Levels beyond the memory budget are not built: the exact frames, said once.
      if (auto reason = ExtraOverBudget("level of detail", EstimateDetailBuildBytes(*scene), *scene,
                                        HeldExtraBytes(*scene), BudgetBytes())) {
        auto none = std::make_shared<DetailLevels>();
        none->skippedBecause = *reason;
        state_.SetLevels(scene, std::move(none));
        state_.SetMessage(std::move(*reason));
        dirty_ = true;
        return;
      }
      detailJob_ = std::make_unique<DetailJob>(scene, BuildLevels);
    }
  }

  size_t BudgetBytes() const { return LoadOptions(state_.Limits()).memoryBudgetBytes; }

  // What the scene's optional structures already hold: its hierarchy and
  // its levels of detail (each level a scene of its own).
  size_t HeldExtraBytes(const Scene& scene) const {
    size_t bytes = scene.hierarchy.Get(scene) ? EstimateRayBvhBytes(scene) : 0;
    if (const DetailLevels* levels = state_.Levels()) {
      for (const DetailLevel& level : levels->levels) bytes += EstimateSceneBytes(level.scene);
    }
    return bytes;
  }

  // Whether the scene's hierarchy is still to be built: frames of this
  // size would cast rays through one, and none was tried for the scene.
  // It comes before the levels of detail (4x to 6x quicker to build):
  // exact frames by rays while the levels are being made, and wherever the
  // view later needs the exact scene (close up).
  bool WantsHierarchy() const {
    const std::shared_ptr<const Scene>& scene = state_.SharedScene();
    return scene && hierarchyTriedFor_.lock() != scene &&
           RayCastStage::WouldCast(*scene, cells_.WidthCells(), cells_.HeightCells(),
                                   frameOptions_);
  }

  // The triangle hierarchy of a big scene (RayCastStage): built on a worker
  // once the first frame is up and no other job runs (before the levels of
  // detail), attached when done (frames of the exact scene then cast rays
  // through it: the same frames, sooner); tried once per scene.
  void UpdateHierarchyJob() {
    const std::shared_ptr<const Scene>& scene = state_.SharedScene();
    if (hierarchyJob_ && hierarchyJob_->ForScene() != scene) {
      retired_.Keep(std::move(hierarchyJob_));  // may still be running
      ReturnFreedMemory();
    }
    if (hierarchyJob_ && hierarchyJob_->Finished()) {
      std::shared_ptr<const RayBvh> bvh = hierarchyJob_->Take();
      hierarchyJob_->ForScene()->hierarchy.Attach(std::move(bvh));
      hierarchyJob_.reset();
    }
    if (!hierarchyJob_ && !detailJob_ && MayStartBuild() && framesDrawn_ > 0 && WantsHierarchy()) {
      hierarchyTriedFor_ = scene;
      // Beyond the memory budget it is not built: the same frames, cast or drawn without it.
      if (!ExtraOverBudget("the ray hierarchy", EstimateRayBvhBytes(*scene), *scene,
                           HeldExtraBytes(*scene), BudgetBytes())) {
        hierarchyJob_ = std::make_unique<HierarchyJob>(scene, BuildHierarchy);
      }
    }
  }

  // No build starts beside a load, one asked for, or a cancelled worker still ending.
  bool MayStartBuild() { return !job_ && !state_.LoadRequested() && !retired_.Busy(); }

  // Stops the scene's background builds (a load will replace the scene); an
  // unfinished hierarchy is tried again if the scene stays.
  void RetireSceneJobs() {
    if (hierarchyJob_ && !hierarchyJob_->Finished()) {
      hierarchyTriedFor_.reset();
      retired_.Keep(std::move(hierarchyJob_));
    }
    if (detailJob_ && !detailJob_->Finished()) retired_.Keep(std::move(detailJob_));
  }

  void CancelLoad() {
    const std::string name = LoadName();
    cancelledName_ = name;
    if (!job_->Stop()) retired_.Keep(std::move(job_));
    job_.reset();  // its result, if any, is dropped
    ReturnFreedMemory();
    state_.SetMessage("cancelled loading " + name);
    dirty_ = true;
  }

  std::string LoadName() const {
    const std::string& path = jobRequest_.path;
    return path.empty() ? "demo" : SanitizeForTerminal(path, 4096, state_.Utf8());
  }

  // "loading NAME 37%", as the status line shows it while a worker loads.
  std::string LoadingText() const {
    if (!job_) return "";
    std::string text = jobRequest_.turnTo ? "turning up axis to " +
                                                std::string(UpAxisName(*jobRequest_.turnTo)) + ": "
                       : job_->Preparing() ? "preparing "
                                           : "loading ";
    text += LoadName();
    const double progress = job_->Progress();
    if (!job_->Preparing() && progress >= 0.0) {
      char percent[16];
      std::snprintf(percent, sizeof percent, " %d%%",
                    static_cast<int>(std::min(1.0, progress) * 100.0));
      text += percent;
    }
    text += " (Esc cancels)";
    return text;
  }

  // The signal that ends the viewer, or 0.
  int HandleSignals() {
    TerminalSession::Signals signals = session_.TakeSignals();
    if (signals.suspend) {
      AwaitAnswers(kSuspendAnswerWait);
      writer_.Release();
      session_.Suspend();
      if (signals.terminate == 0) signals.terminate = session_.TakeSignals().terminate;
      signals.resumed = true;
    }
    if (signals.resumed) {  // the shell or another program drew over the screen
      writer_.Invalidate();
      dirty_ = true;
    }
    return signals.terminate;
  }

  void HandleInput(const InputEvent& event) {
    if (event.reply) {  // the start-up queries' answers; any other is dropped
      if (!startupAnswered_) TakeAnswer(*event.reply);
      return;
    }
    if (event.deviceAnswer) {
      startupAnswered_ = true;
      pacer_.AnswerRead(Clock::now());
      motion_.RoundTripMeasured(pacer_.LastRoundTripSeconds());
      return;
    }
    if (!event.mouse) {
      HandleKey(event.key);
      return;
    }
    if (prompting_) return;    // never typed into the prompt
    if (state_.HelpShown()) {  // any key or button closes the help
      state_.Apply(ViewerAction::kToggleHelp);
      dirty_ = true;
      return;
    }
    HandleMouse(*event.mouse);
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
    ViewerAction action = ViewerAction::kNone;
    if (const auto named = NamedKeyFor(key)) {
      action = ActionForNamedKey(*named);
      if (*named == NamedKey::kEscape && state_.LightMode()) {
        action = ViewerAction::kToggleLightMode;
      } else if (*named == NamedKey::kEscape && job_) {
        CancelLoad();
        if (!state_.HasModel()) {  // nothing to show: the viewer ends
          cancelledStart_ = true;
          state_.Apply(ViewerAction::kQuit);
        }
        return;
      }
    } else if (key >= 0 && key < 128) {
      action = ActionForChar(key);
    }
    const bool loads = action == ViewerAction::kOpenFile || action == ViewerAction::kNextModel ||
                       action == ViewerAction::kPreviousModel ||
                       action == ViewerAction::kCycleUpAxis;
    if (loads && job_) {  // one load at a time
      state_.SetMessage("still loading " + LoadName() + " (Esc cancels)");
      dirty_ = true;
      return;
    }
    if (action == ViewerAction::kOpenFile) {
      prompting_ = true;
      editor_.Clear();
      completionMatches_ = 1;
    }
    if (MovesView(action)) motion_.ViewMoved(Clock::now());
    if (action != ViewerAction::kNone) {
      state_.SetMessage("");
      state_.Apply(action);
      dirty_ = true;
    }
    if (action == ViewerAction::kShowRenderCommand) ShowRenderCommand();
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
          state_.SetMessage("");
          state_.RequestOpen(path);
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

  // Wheel: distance; the left button dragged: orbit, by the cells moved
  // since the last report (motion reports come while it is held).
  void HandleMouse(const MouseReport& report) {
    using Kind = MouseReport::Kind;
    motion_.ViewMoved(Clock::now());
    if (report.kind == Kind::kWheelUp) state_.Apply(ViewerAction::kCloser);
    if (report.kind == Kind::kWheelDown) state_.Apply(ViewerAction::kFarther);
    if (report.kind == Kind::kPress && report.button == 0) {
      dragging_ = true;
      dragCol_ = report.col;
      dragRow_ = report.row;
    } else if (dragging_ && (report.kind == Kind::kMotion || report.kind == Kind::kRelease)) {
      state_.Drag(report.col - dragCol_, report.row - dragRow_);
      dragCol_ = report.col;
      dragRow_ = report.row;
      if (report.kind == Kind::kRelease) dragging_ = false;
    }
    dirty_ = true;
  }

  // y: the `termshade render` command of the view shown, on the status line
  // and, by OSC 52, on the clipboard where the terminal allows it.
  void ShowRenderCommand() {
    if (!state_.HasModel()) return;
    const std::string& path = state_.ModelPath();
    if (path.empty()) {
      state_.SetMessage("the demo scene has no file for render: open a model (o)");
      return;
    }
    const Scene& scene = state_.CurrentScene();
    ViewToReproduce shown;
    std::error_code error;
    const std::filesystem::path absolute = std::filesystem::absolute(path, error);
    shown.modelPath = error ? path : absolute.string();
    shown.widthCells = TerminalSession::WidthCells();
    shown.heightCells = TerminalSession::HeightCells() - 1;
    shown.view = state_.View();
    shown.cellAspect = state_.CellAspect();
    shown.upAxis = scene.upAxis;
    shown.render = state_.Render();
    shown.colour = state_.Colour();
    shown.background = state_.Background();
    shown.sunAzimuthRadians = state_.SunAzimuthRadians();
    shown.sunElevationRadians = state_.SunElevationRadians();
    shown.levelOfDetail = lastDetailLevel_ > 0;
    // f fits the model at the distance of the moment.
    if (state_.FitRho() != DefaultView(scene.diagonalModelUnits).rho)
      shown.fitRho = state_.FitRho();
    const std::string command = RenderCommandFor(shown);
    writer_.Send(ClipboardSequence(command));
    state_.SetMessage(command);
  }

  // A terminal that would scroll on its bottom-right cell gets one cell less.
  static int StatusCols(int cols) {
    return TerminalWriter::BottomRightWritable() ? cols : cols - 1;
  }

  void Draw() {
    dirty_ = false;
    const int cols = TerminalSession::WidthCells(), rows = TerminalSession::HeightCells();
    grid_.Resize(cols, rows);
    motion_.FrameDrawn(false);
    if (cols < kMinCols || rows < kMinRows) {
      painter_.PaintTooSmall(grid_);
      Present(std::nullopt);
      return;
    }
    if (!state_.HasModel()) {  // the first model is loading: only the status line
      grid_.Clear();
      shownLoadingText_ = LoadingText();
      painter_.PaintStatus(
          ComposeStatusLine({{shownLoadingText_, 0, false, Elision::kMiddle}, {"? help", 1, true}},
                            StatusCols(cols)),
          grid_);
      Present(std::nullopt);
      return;
    }
    // Step 1: the frame, through the one shared pipeline.
    const int frameRows = rows - 1;
    cells_.Resize(cols, frameRows);
    depth_.Resize(cols, frameRows);
    const auto start = Clock::now();
    frameOptions_ = state_.Render();  // assigned in place: no allocation in a steady loop
    // With colour, the cells as the ansi dump draws them (one cell buffer,
    // many outputs): fg and bg in the block modes, shape-matched ascii.
    frameOptions_.twoColour = state_.Colour() != ColourMode::kNone;
    frameOptions_.background = state_.Background();
    const Camera camera = state_.CameraFor(cols, frameRows);
    const DetailPick pick =
        PickDetail(state_.Levels(), state_.CurrentScene(), camera, frameOptions_);
    const RenderStats stats = renderer_.Render(*pick.scene, camera, frameOptions_, depth_, cells_);
    lastDetailLevel_ = pick.level;
    const double frameMs = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    ++framesDrawn_;
    // On a slow link, while the view moves: the 256-colour palette and a few
    // shades (MotionFrames); the full frame follows once the view rests.
    const bool cheap =
        state_.Colour() != ColourMode::kNone && motion_.Cheap(Clock::now(), turning_);
    motion_.FrameDrawn(cheap);
    // Step 2: overlays and the status line, then one write of what changed.
    const std::string status =
        prompting_ ? std::string() : StatusText(stats, pick, frameMs, StatusCols(cols));
    const auto cursor = Compose(*pick.scene, status, cheap, grid_);
    // A recording gets the full frame, never a cheap one.
    if (cheap && recording_ != nullptr) {
      recordGrid_.Resize(cols, rows);
      Compose(*pick.scene, status, false, recordGrid_);
      Present(cursor, &recordGrid_);
      return;
    }
    Present(cursor);
  }

  // The frame in cells_ with its colours (cheap: MotionFrames'), the help
  // overlay, and the prompt or the status line, into grid; where the cursor goes.
  std::optional<std::pair<int, int>> Compose(const Scene& drawn, const std::string& status,
                                             bool cheap, ScreenGrid& grid) {
    const int levelCount = state_.Render().ramp.LevelCount();
    // Cheap frames: the 256 colours, or the terminal's fewer.
    const ColourMode mode = cheap ? std::min(ColourMode::k256, state_.Colour()) : state_.Colour();
    CellColourMap colours(drawn.source.faceColors, levelCount, mode, state_.Background());
    painter_.PaintFrame(cells_, colours, grid, levelCount, cheap ? MotionFrames::kMotionLevels : 0);
    if (state_.HelpShown()) painter_.PaintHelp(grid);
    if (!prompting_) {
      painter_.PaintStatus(status, grid);
      return std::nullopt;
    }
    // After Tab: how many names matched, when not exactly one.
    const std::string label = completionMatches_ == 1 ? "open: "
                              : completionMatches_ == 0
                                  ? "open (no match): "
                                  : "open (" + std::to_string(completionMatches_) + " matches): ";
    return painter_.PaintPrompt(label, editor_, grid);
  }

  // The status line: what is loading, a message or the model, then the
  // view, the help hint and what the frame holds (StatusFields).
  std::string StatusText(const RenderStats& stats, const DetailPick& pick, double frameMs,
                         int cols) {
    const ViewParams& view = state_.View();
    const RenderOptions& render = state_.Render();
    const Scene& scene = state_.CurrentScene();
    StatusFields fields;
    char viewText[96];
    std::snprintf(viewText, sizeof viewText, "theta %.2f phi %.2f rho %.3g", view.theta, view.phi,
                  view.rho);
    fields.view = viewText;
    fields.method = std::string(MethodName(render.method)) + " " +
                    std::string(ShadeModeName(render.shade)) +
                    (render.cullBackFaces ? "" : " 2-sided") +
                    (scene.textures.Any() && state_.Colour() != ColourMode::kNone
                         ? (render.textures ? " textured" : " untextured")
                         : "");
    fields.upAxis = std::string(UpAxisName(scene.upAxis));
    fields.vertices = scene.verticesWorld.size();
    fields.faces = scene.FaceCount();
    fields.facesVisible = stats.facesVisible;
    fields.trianglesDrawn = stats.trianglesDrawn;
    fields.frameMs = frameMs;
    // A load in progress first, then a message (shown whole if it can be),
    // else the model's path, which gives way to the view.
    shownLoadingText_ = LoadingText();
    fields.lead = shownLoadingText_;
    fields.leadIsModel = false;
    if (fields.lead.empty())
      fields.lead = SanitizeForTerminal(state_.Message(), 4096, state_.Utf8());
    if (fields.lead.empty()) {
      fields.lead =
          state_.LightMode() ? "LIGHT: arrows move the sun, L or Esc ends" : state_.ModelLabel();
      fields.leadIsModel = !state_.LightMode();
    }
    fields.glyphs = std::string(GlyphModeName(render.glyphs));
    fields.colour = state_.Colour() == ColourMode::kNone
                        ? std::string("mono")
                        : std::string(ColourModeName(state_.Colour()));
    if (pick.level > 0) {  // "lod 2/4 30.8k": the level drawn, of how many, its triangles
      fields.detail = "lod " + std::to_string(pick.level) + "/" +
                      std::to_string(state_.Levels()->levels.size()) + " " +
                      CompactCount(pick.scene->triangles.size());
    }
    return ComposeViewerStatus(fields, cols);
  }

  ViewerState& state_;
  TerminalSession& session_;
  ViewerRecording* recording_;  ///< --record, or null
  ScreenGrid recordGrid_;       ///< the full frame for the recording, when the screen's is cheap
  ScreenPainter painter_;
  TerminalWriter writer_;
  FramePacer pacer_;
  MotionFrames motion_;                   ///< cheaper frames while moving on a slow link
  bool turning_ = false;                  ///< the turntable was on at the last look
  Clock::time_point lastTurn_;            ///< when the turntable last turned
  Clock::time_point nextTurntableFrame_;  ///< its next frame is due
  ScreenGrid grid_;
  Renderer renderer_;
  RenderOptions frameOptions_;  ///< the state's options with the screen's colours
  CellBuffer cells_;
  DepthBuffer depth_;
  LineEditor editor_;
  std::unique_ptr<LoadJob> job_;                  ///< the load running on a worker, if any
  std::unique_ptr<DetailJob> detailJob_;          ///< levels of detail being built, if any
  std::unique_ptr<HierarchyJob> hierarchyJob_;    ///< the scene's hierarchy being built, if any
  std::weak_ptr<const Scene> hierarchyTriedFor_;  ///< the scene a hierarchy was last built for
  RetiredJobs retired_;                           ///< cancelled jobs whose workers may still run
  long framesDrawn_ = 0;
  int lastDetailLevel_ = 0;  ///< the level of detail the last frame drew (0: exact)
  LoadRequest jobRequest_;
  std::string shownLoadingText_;  ///< what the status line last said of it
  int completionMatches_ = 1;     ///< names the last Tab matched (1: no hint)
  bool cancelledStart_ = false;   ///< Esc while the first model loaded
  std::string cancelledName_;     ///< what the last Esc cancelled
  bool prompting_ = false;
  bool dirty_ = true;
  InputDecoder input_;
  AnswerUse answerUse_;
  TerminalAnswers answers_;             ///< what the start-up queries' answers said
  bool startupAnswered_ = false;        ///< the first DA1 answer came: no more of them
  bool recordingThemeSettled_ = false;  ///< the recording's header has its theme
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
  effective.colour = ResolveColourMode(options.colour);
  if (!effective.background) {
    const char* colorFgBg = std::getenv("COLORFGBG");
    effective.background = BackgroundFromColorFgBg(colorFgBg != nullptr ? colorFgBg : "");
  }
  ViewerState state(effective, TerminalSession::ReportedCellAspect());
  std::setlocale(LC_ALL, "");
  const std::string codeset = nl_langinfo(CODESET);
  if (!options.render.ramp.IsAscii() && codeset != "UTF-8") {
    std::cerr << "termshade: the ramp has characters beyond ASCII, which need a UTF-8 locale "
                 "(this one is "
              << SanitizeForTerminal(codeset) << "); try LANG=C.UTF-8\n";
    return 2;
  }
  // --record: the file is made before the terminal is taken, so a path that
  // cannot be written is said on the shell.
  std::optional<ViewerRecording> recording;
  std::optional<std::string> recordError;
  if (!options.recordPath.empty()) {
    recording.emplace(options.recordPath);
    if (const auto problem =
            recording->Open(ThemeFor(effective.background.value_or(Background::kDark)))) {
      std::cerr << "termshade: --record " << SanitizeForTerminal(options.recordPath) << ": "
                << SanitizeForTerminal(*problem) << "\n";
      return 1;
    }
  }
  LoopOutcome outcome;
  {
    TerminalSession session;
    if (!session.Ok()) {
      std::cerr << "termshade: cannot start the terminal interface for TERM="
                << SanitizeForTerminal(std::getenv("TERM") != nullptr ? std::getenv("TERM") : "")
                << "\n";
      return 2;
    }
    // The glyph mode: as asked, else what this terminal shows best.
    const bool utf8 = codeset == "UTF-8";
    const char* term = std::getenv("TERM");
    const char* termProgram = std::getenv("TERM_PROGRAM");
    state.SetGlyphs(options.glyphs.value_or(PickGlyphMode(
                        utf8, effective.colour != ColourMode::kNone, term != nullptr ? term : "",
                        termProgram != nullptr ? termProgram : "")),
                    utf8);
    // The first model loads on the worker too: the screen says so at once.
    state.RequestFirst();
    AnswerUse answerUse;
    answerUse.colour = options.colour == ColourMode::kAuto;
    answerUse.background = !options.background;
    answerUse.cellAspect = !options.cellAspect && TerminalSession::ReportedCellAspect() == 0.0;
    answerUse.terminalColours = DetectTerminalColourMode();
    EventLoop loop(state, session, recording ? &*recording : nullptr, answerUse);
    outcome = loop.Run();
    if (recording) recordError = recording->Finish(std::chrono::steady_clock::now());
  }  // the terminal is given back here
  if (recordError) {
    std::cerr << "termshade: --record " << SanitizeForTerminal(options.recordPath) << ": "
              << SanitizeForTerminal(*recordError) << "\n";
  }
  // Killed: the signal's own exit status (128 + N), as a shell expects.
  if (outcome.signalNumber != 0) return TerminalSession::ReRaise(outcome.signalNumber);
  int code = 0;
  if (const auto& error = state.StartError()) {  // no model could be shown
    std::cerr << error->ToString() << "\n";
    code = 1;
  } else if (!outcome.cancelledStart.empty()) {
    std::cerr << "termshade: cancelled loading " << outcome.cancelledStart << "\n";
    code = 1;
  }
  if (recordError) code = 1;    // the recording was not made
  if (outcome.abandonedLoad) {  // no static destructors under a running importer
    std::cerr.flush();
    std::fflush(nullptr);
    std::_Exit(code);
  }
  return code;
}

}  // namespace termshade
