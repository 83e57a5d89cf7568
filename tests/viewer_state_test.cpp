// The viewer's state machine and status line, without a terminal.
#include <gtest/gtest.h>
#include <unistd.h>
#include <filesystem>
#include <fstream>

#include <clocale>
#include <numbers>

#include "geometry/FitCamera.h"
#include "io/read/LoadError.h"
#include "support/TestSupport.h"
#include "tui/LineEditor.h"
#include "tui/PathCompletion.h"
#include "tui/PromptPath.h"
#include "tui/StatusFields.h"
#include "tui/StatusLine.h"
#include "tui/ViewerState.h"

namespace termshade {
namespace {

ViewerState DemoState() {
  ViewerState state(ViewerOptions{}, 0.0);
  EXPECT_FALSE(state.LoadFirst().has_value());
  return state;
}

TEST(ViewerState, StartsAtTheSpecDefaultsOnTheDemo) {
  const ViewerState state = DemoState();
  EXPECT_EQ(state.ModelLabel(), "demo");
  EXPECT_DOUBLE_EQ(state.View().theta, 0.3);
  EXPECT_DOUBLE_EQ(state.View().phi, 1.3);
  EXPECT_DOUBLE_EQ(state.CellAspect(), 2.0);
  EXPECT_EQ(state.CurrentScene().FaceCount(), 1861U);
}

TEST(ViewerState, TerminalAspectIsUsedUnlessOverridden) {
  EXPECT_DOUBLE_EQ(ViewerState(ViewerOptions{}, 1.8).CellAspect(), 1.8);
  ViewerOptions options;
  options.cellAspect = 2.2;
  EXPECT_DOUBLE_EQ(ViewerState(options, 1.8).CellAspect(), 2.2);
}

TEST(ViewerState, CameraEqualsTheHeadlessFit) {  // render --fit
  const ViewerState state = DemoState();
  const Camera viewer = state.CameraFor(80, 24);
  const Camera headless =
      FitCamera(state.CurrentScene(), state.View(), 80, 24, 2.0, Framing::kOrbit);
  EXPECT_EQ(viewer.projection.d, headless.projection.d);
  EXPECT_EQ(viewer.projection.cx, headless.projection.cx);
}

TEST(ViewerState, OrbitStepsAndPhiLimits) {
  ViewerState state = DemoState();
  state.Apply(ViewerAction::kOrbitRight);
  state.Apply(ViewerAction::kOrbitRight);
  state.Apply(ViewerAction::kOrbitUp);
  EXPECT_NEAR(state.View().theta, 0.5, 1e-12);
  EXPECT_NEAR(state.View().phi, 1.2, 1e-12);
  for (int i = 0; i < 40; ++i) state.Apply(ViewerAction::kOrbitDown);
  EXPECT_DOUBLE_EQ(state.View().phi, std::numbers::pi);
}

TEST(ViewerState, ThetaWrapsIntoOneTurn) {
  ViewerState state = DemoState();
  for (int i = 0; i < 4; ++i) state.Apply(ViewerAction::kOrbitLeft);  // 0.3 - 0.4
  EXPECT_NEAR(state.View().theta, -0.1, 1e-12);
  for (int i = 0; i < 33; ++i) state.Apply(ViewerAction::kOrbitRight);  // past pi
  EXPECT_NEAR(state.View().theta, 3.2 - 2 * std::numbers::pi, 1e-12);
  for (int i = 0; i < 1000; ++i) {
    state.TurntableAdvance(0.04);
    ASSERT_LE(std::fabs(state.View().theta), std::numbers::pi);
  }
}

TEST(ViewerState, DistanceStaysWithinLimits) {
  ViewerState state = DemoState();
  const double start = state.View().rho;
  state.Apply(ViewerAction::kCloser);
  EXPECT_DOUBLE_EQ(state.View().rho, start / 2.0);
  state.Apply(ViewerAction::kCloser);
  EXPECT_DOUBLE_EQ(state.View().rho, start / 3.0);  // clamped at rhoMin = rho / 3
  for (int i = 0; i < 20; ++i) state.Apply(ViewerAction::kFarther);
  EXPECT_DOUBLE_EQ(state.View().rho, 1000.0 * start / 3.0);
  state.Apply(ViewerAction::kResetView);
  EXPECT_DOUBLE_EQ(state.View().rho, start);
}

TEST(ViewerState, LightModeMovesTheSunNotTheEye) {
  ViewerState state = DemoState();
  const Vec3 sunBefore = state.Render().sunEye;
  state.Apply(ViewerAction::kToggleLightMode);
  state.Apply(ViewerAction::kOrbitLeft);
  EXPECT_DOUBLE_EQ(state.View().theta, 0.3);
  EXPECT_GT(Length(state.Render().sunEye - sunBefore), 0.05);
  EXPECT_NEAR(Length(state.Render().sunEye), 1.0, 1e-12);
}

TEST(ViewerState, ModesCycle) {
  ViewerState state = DemoState();
  const Method expected[] = {Method::kPainter, Method::kCull, Method::kWire, Method::kAuto,
                             Method::kZBuffer};
  for (Method method : expected) {
    state.Apply(ViewerAction::kCycleMethod);
    EXPECT_EQ(state.Render().method, method);
  }
  state.Apply(ViewerAction::kCycleShade);
  EXPECT_EQ(state.Render().shade, ShadeMode::kLambert);
}

TEST(ViewerState, CyclingFromAutoWrapsAround) {
  ViewerOptions options;
  options.render.method = Method::kAuto;
  ViewerState state(options, 0.0);
  ASSERT_FALSE(state.LoadFirst().has_value());
  state.Apply(ViewerAction::kCycleMethod);
  EXPECT_EQ(state.Render().method, Method::kZBuffer);
}

TEST(ViewerState, RefitUsesTheCurrentDistance) {
  ViewerState state = DemoState();
  const double before = state.CameraFor(80, 24).projection.d;
  state.Apply(ViewerAction::kFarther);
  EXPECT_EQ(state.CameraFor(80, 24).projection.d, before);  // farther looks smaller
  state.Apply(ViewerAction::kRefit);
  EXPECT_GT(state.CameraFor(80, 24).projection.d, before);  // refit fills the window again
  state.Apply(ViewerAction::kAspectUp);
  EXPECT_DOUBLE_EQ(state.CellAspect(), 2.05);
}

TEST(ViewerState, BadOpenKeepsTheModelAndSaysWhy) {
  ViewerState state = DemoState();
  state.OpenPath(test::SourcePath("tests/models/bad/undefined_vertex.dat"));
  EXPECT_EQ(state.Message(), "undefined_vertex.dat:14:7: vertex 12 is not defined (highest is 9)");
  EXPECT_EQ(state.ModelLabel(), "demo");
  state.OpenPath(test::SourcePath("data/cube.dat"));
  EXPECT_EQ(state.CurrentScene().FaceCount(), 6U);
  state.Apply(ViewerAction::kNextModel);
  state.RunPendingLoad();
  EXPECT_EQ(state.ModelLabel(), "demo [1/2]");
}

TEST(ViewerState, NextAfterAFailedModelMovesOn) {
  ViewerOptions options;
  options.modelPaths = {test::SourcePath("data/cube.dat"),
                        test::SourcePath("tests/models/bad/undefined_vertex.dat"),
                        test::SourcePath("data/wedge.dat")};
  ViewerState state(options, 0.0);
  ASSERT_FALSE(state.LoadFirst().has_value());
  state.Apply(ViewerAction::kNextModel);
  state.RunPendingLoad();
  EXPECT_EQ(state.Message(), "undefined_vertex.dat:14:7: vertex 12 is not defined (highest is 9)");
  EXPECT_NE(state.ModelLabel().find("cube.dat [1/3]"), std::string::npos);  // still shown
  state.Apply(ViewerAction::kNextModel);
  state.RunPendingLoad();
  EXPECT_NE(state.ModelLabel().find("wedge.dat [3/3]"), std::string::npos);
  EXPECT_EQ(state.Message(), "");
  // p from the third skips back over the bad one in two steps as well.
  state.Apply(ViewerAction::kPreviousModel);
  state.RunPendingLoad();
  EXPECT_NE(state.Message().find("undefined_vertex.dat"), std::string::npos);
  state.Apply(ViewerAction::kPreviousModel);
  state.RunPendingLoad();
  EXPECT_NE(state.ModelLabel().find("cube.dat [1/3]"), std::string::npos);
}

TEST(ViewerState, StartsAtTheFirstModelThatLoads) {
  ViewerOptions options;
  options.modelPaths = {test::SourcePath("tests/models/bad/undefined_vertex.dat"),
                        test::SourcePath("data/cube.dat")};
  ViewerState state(options, 0.0);
  ASSERT_FALSE(state.LoadFirst().has_value());
  EXPECT_NE(state.ModelLabel().find("cube.dat [2/2]"), std::string::npos);
  EXPECT_NE(state.Message().find("undefined_vertex.dat:14:7"), std::string::npos);
  ViewerOptions bad;
  bad.modelPaths = {test::SourcePath("tests/models/bad/undefined_vertex.dat")};
  ViewerState none(bad, 0.0);
  EXPECT_TRUE(none.LoadFirst().has_value());
}

TEST(ViewerState, LoadsAreRequestedNotDone) {
  ViewerState state = DemoState();
  state.RequestOpen(test::SourcePath("data/cube.dat"));
  EXPECT_EQ(state.ModelLabel(), "demo");  // nothing loaded until the event loop does it
  const std::optional<LoadRequest> request = state.TakeLoadRequest();
  ASSERT_TRUE(request.has_value());
  EXPECT_FALSE(state.TakeLoadRequest().has_value());
  state.FinishLoad(*request, LoadViewerScene(request->path));
  EXPECT_EQ(state.CurrentScene().FaceCount(), 6U);
  EXPECT_EQ(state.Message().substr(0, 7), "opened ");
}

TEST(ViewerState, CCyclesTheColourModesTheTerminalHas) {
  ViewerOptions options;
  options.colour = ColourMode::k256;
  ViewerState state(options, 0.0);
  // The terminal said it has 24-bit colour: truecolor, 256, 16, mono, again.
  state.SetColourModes(ColourMode::kTrueColour, ColourMode::kTrueColour);
  std::vector<ColourMode> seen;
  for (int i = 0; i < 5; ++i) {
    seen.push_back(state.Colour());
    state.Apply(ViewerAction::kToggleColour);
  }
  EXPECT_EQ(seen,
            (std::vector<ColourMode>{ColourMode::kTrueColour, ColourMode::k256, ColourMode::k16,
                                     ColourMode::kNone, ColourMode::kTrueColour}));
  // A 16-colour terminal: 16, mono, 16; started mono (NO_COLOR): c gives its most.
  state.SetColourModes(ColourMode::kNone, ColourMode::k16);
  state.Apply(ViewerAction::kToggleColour);
  EXPECT_EQ(state.Colour(), ColourMode::k16);
  state.Apply(ViewerAction::kToggleColour);
  EXPECT_EQ(state.Colour(), ColourMode::kNone);
  // A terminal of no colour: c still turns 256 on, as before.
  state.SetColourModes(ColourMode::kNone, ColourMode::kNone);
  state.Apply(ViewerAction::kToggleColour);
  EXPECT_EQ(state.Colour(), ColourMode::k256);
}

TEST(ViewerStatus, NamesTheColourMode) {
  StatusFields fields;
  fields.lead = "bunny.obj";
  fields.colour = "truecolor";
  fields.method = "zbuffer contrast";
  EXPECT_EQ(ComposeViewerStatus(fields, 160).substr(0, 41),
            "bunny.obj | truecolor | zbuffer contrast ");
}

StatusFields SampleFields() {
  StatusFields fields;
  fields.lead = "/home/someone/models/bunny.obj [2/3]";
  fields.view = "theta 0.30 phi 1.30 rho 9.85";
  fields.method = "zbuffer contrast";
  fields.upAxis = "+y";
  fields.vertices = 34834;
  fields.faces = 69451;
  fields.facesVisible = 30712;
  fields.trianglesDrawn = 31000;
  fields.frameMs = 1.25;
  return fields;
}

TEST(ViewerStatus, ShowsEverythingWhenThereIsRoom) {
  EXPECT_EQ(ComposeViewerStatus(SampleFields(), 160),
            "/home/someone/models/bunny.obj [2/3] | zbuffer contrast | up +y | 30712/69451 faces | "
            "31000 tris | 34834 verts   theta 0.30 phi 1.30 rho 9.85 | 1.25 ms | ? help");
}

TEST(ViewerStatus, DropsTheLeastUsefulFieldsFirst) {
  const StatusFields fields = SampleFields();
  // The order fields leave in as the line narrows; each width keeps what
  // the wider one kept minus the next field.
  const std::vector<std::pair<int, std::vector<std::string>>> steps{
      {145, {"verts"}},
      {136, {"verts", " ms"}},
      {124, {"verts", " ms", "tris"}},
      {104, {"verts", " ms", "tris", "faces"}},
      {96, {"verts", " ms", "tris", "faces", "up +y"}},
      {77, {"verts", " ms", "tris", "faces", "up +y", "zbuffer"}},
      {50, {"verts", " ms", "tris", "faces", "up +y", "zbuffer", "theta"}}};
  for (const auto& [width, gone] : steps) {
    const std::string line = ComposeViewerStatus(fields, width);
    EXPECT_EQ(line.size(), static_cast<size_t>(width));
    for (const std::string& field :
         {std::string("verts"), std::string(" ms"), std::string("tris"), std::string("faces"),
          std::string("up +y"), std::string("zbuffer"), std::string("theta")}) {
      const bool dropped = std::find(gone.begin(), gone.end(), field) != gone.end();
      EXPECT_EQ(line.find(field) == std::string::npos, dropped)
          << width << ": " << field << " in '" << line << "'";
    }
    EXPECT_NE(line.find("bunny.obj [2/3]"), std::string::npos) << line;
    EXPECT_EQ(line.substr(line.size() - 6), "? help") << line;
  }
  // Narrower still: the path loses its front, the file name and "? help" stay.
  EXPECT_EQ(ComposeViewerStatus(fields, 40), "...omeone/models/bunny.obj [2/3]  ? help");
}

TEST(ViewerStatus, CountsStayShort) {
  EXPECT_EQ(CompactCount(950), "950");
  EXPECT_EQ(CompactCount(99999), "99999");
  EXPECT_EQ(CompactCount(123456), "123.5k");
  EXPECT_EQ(CompactCount(2100000), "2.1M");
}

TEST(StatusLine, DropsTheLeastImportantSegmentsFirst) {
  const std::vector<StatusSegment> segments{
      {"model.dat", 0, false}, {"zbuffer contrast", 2, false}, {"theta 0.30", 1, true}};
  EXPECT_EQ(ComposeStatusLine(segments, 50), "model.dat | zbuffer contrast            theta 0.30");
  EXPECT_EQ(ComposeStatusLine(segments, 25), "model.dat      theta 0.30");
  EXPECT_EQ(ComposeStatusLine(segments, 6), "model.");
}

TEST(StatusLine, ALongPathLosesItsFrontBeforeOtherSegmentsGo) {
  const std::string path = "/a/very/long/checkout/directory/of/the/project/data/cube.dat [1/2]";
  const std::vector<StatusSegment> segments{
      {path, 0, false, Elision::kFront, 20}, {"zbuffer", 2, false}, {"theta 0.30", 1, true}};
  EXPECT_EQ(ComposeStatusLine(segments, 45), "...t/data/cube.dat [1/2] | zbuffer theta 0.30");
  EXPECT_EQ(ComposeStatusLine(segments, 31), "...ta/cube.dat [1/2] theta 0.30");
  EXPECT_EQ(ComposeStatusLine(segments, 12), "...dat [1/2]");
  EXPECT_EQ(ComposeStatusLine({{path, 0, false, Elision::kFront, 20}}, 200).substr(0, path.size()),
            path);
}

TEST(StatusLine, ElisionKeepsWhatItPromises) {
  EXPECT_EQ(Elide("abcdef", 6, Elision::kFront), "abcdef");
  EXPECT_EQ(Elide("abcdefgh", 6, Elision::kFront), "...fgh");
  EXPECT_EQ(Elide("abcdefgh", 6, Elision::kCutEnd), "abcdef");
  EXPECT_EQ(Elide("abcdefghijklmnop", 11, Elision::kMiddle), "ab...klmnop");
  EXPECT_EQ(Elide("abcdefgh", 2, Elision::kMiddle), "gh");
  EXPECT_EQ(Elide("abcdefgh", 0, Elision::kFront), "");
}

TEST(StatusLine, AMessageKeepsItsFirstWordAndItsEnd) {
  const std::string message = "opened /a/very/long/checkout/directory/of/the/project/data/cube.dat";
  const std::vector<StatusSegment> segments{{message, 0, false, Elision::kMiddle},
                                            {"theta 0.30", 1, true}};
  EXPECT_EQ(ComposeStatusLine(segments, 40), "opened /a...of/the/project/data/cube.dat");
}

// LC_CTYPE set for a test's scope (wcwidth follows it), restored after.
class CtypeLocale {
 public:
  explicit CtypeLocale(const char* name) : old_(std::setlocale(LC_CTYPE, nullptr)) {
    ok_ = std::setlocale(LC_CTYPE, name) != nullptr;
  }
  ~CtypeLocale() { std::setlocale(LC_CTYPE, old_.c_str()); }
  CtypeLocale(const CtypeLocale&) = delete;
  CtypeLocale& operator=(const CtypeLocale&) = delete;
  bool Ok() const { return ok_; }

 private:
  std::string old_;
  bool ok_ = false;
};

TEST(TerminalText, AUtf8TerminalKeepsShownCodePointsAndEscapesTheRest) {
  CtypeLocale utf8("C.UTF-8");
  if (!utf8.Ok()) GTEST_SKIP() << "no C.UTF-8 locale";
  const std::string name =
      "/m/\xC3\xBC"
      "ber/\xD0\xBC\xD0\xBE\xD0\xB4.obj";  // /m/über/мод.obj
  EXPECT_EQ(SanitizeForTerminal(name, 200, true), name);
  EXPECT_EQ(SanitizeForTerminal(name, 200, false),
            "/m/\\xC3\\xBCber/\\xD0\\xBC\\xD0\\xBE\\xD0\\xB4.obj");
  // A wide CJK glyph stays (two cells); C1 CSI, right-to-left override,
  // zero-width space, a lone combining accent, a cut sequence and a stray
  // continuation byte: escaped byte by byte.
  EXPECT_EQ(SanitizeForTerminal("a\xC2\x9B"
                                "31m",
                                200, true),
            "a\\xC2\\x9B31m");
  EXPECT_EQ(SanitizeForTerminal("x\xE2\x80\xAEy", 200, true), "x\\xE2\\x80\\xAEy");
  EXPECT_EQ(SanitizeForTerminal("\xE2\x80\x8B", 200, true), "\\xE2\\x80\\x8B");
  EXPECT_EQ(SanitizeForTerminal("\xE6\xA8\xA1", 200, true), "\xE6\xA8\xA1");
  EXPECT_EQ(SanitizeForTerminal("e\xCC\x81", 200, true), "e\\xCC\\x81");
  EXPECT_EQ(SanitizeForTerminal("\xC3", 200, true), "\\xC3");
  EXPECT_EQ(SanitizeForTerminal("\xBC\x1B[2J", 200, true), "\\xBC\\x1B[2J");
  // Idempotent, as messages are escaped more than once on their way.
  const std::string once = SanitizeForTerminal("\xC3\xBC\xE2\x80\xAE\x07", 200, true);
  EXPECT_EQ(SanitizeForTerminal(once, 200, true), once);
}

TEST(TerminalText, TheCLocaleEscapesEverythingBeyondAscii) {
  CtypeLocale c("C");
  ASSERT_TRUE(c.Ok());
  EXPECT_EQ(SanitizeForTerminal("\xC3\xBC", 200, true), "\\xC3\\xBC");
}

TEST(StatusLine, WideCodePointsTakeTwoCellsAndAreNeverHalved) {
  CtypeLocale utf8("C.UTF-8");
  if (!utf8.Ok()) GTEST_SKIP() << "no C.UTF-8 locale";
  const std::string name = "\xE6\xA8\xA1\xE5\x9E\x8B.obj";  // 模型.obj, 8 cells
  EXPECT_EQ(ComposeStatusLine({{name, 0, false}, {"? help", 1, true}}, 16), name + "  ? help");
  EXPECT_EQ(Elide(name, 6, Elision::kCutEnd), "\xE6\xA8\xA1\xE5\x9E\x8B.o");
  EXPECT_EQ(Elide(name, 3, Elision::kCutEnd), "\xE6\xA8\xA1");  // not half of the second
  EXPECT_EQ(Elide(name, 7, Elision::kFront), "....obj");
  EXPECT_EQ(Elide("abcd" + name.substr(0, 6), 7, Elision::kFront), "..." + name.substr(0, 6));
}

TEST(StatusLine, Utf8TakesOneCellPerCodePoint) {
  const std::string name =
      "\xD0\xBC\xD0\xBE\xD0\xB4\xD0\xB5\xD0\xBB\xD1\x8C.obj";  // модель.obj, 10 cells
  EXPECT_EQ(ComposeStatusLine({{name, 0, false}, {"? help", 1, true}}, 18), name + "  ? help");
  EXPECT_EQ(Elide(name, 8, Elision::kFront), "...\xD1\x8C.obj");
  EXPECT_EQ(Elide(name, 3, Elision::kCutEnd), "\xD0\xBC\xD0\xBE\xD0\xB4");
  EXPECT_EQ(Elide(name, 9, Elision::kMiddle), "\xD0\xBC...\xD1\x8C.obj");
}

void Type(LineEditor& editor, std::string_view bytes) {
  for (char c : bytes) editor.InsertByte(static_cast<unsigned char>(c));
}

TEST(LineEditor, EditsAndRefusesControlCharacters) {
  LineEditor editor;
  Type(editor, "cub.dat");
  editor.Home();
  for (int i = 0; i < 3; ++i) editor.Right();
  Type(editor, "e\x1b\x7f\xC2\x9B");  // ESC, DEL and the C1 CSI are dropped
  editor.End();
  editor.Backspace();
  EXPECT_EQ(editor.Text(), "cube.da");
}

TEST(LineEditor, AssemblesUtf8AndCountsCodePoints) {
  LineEditor editor;
  Type(editor, "caf\xC3\xA9/\xE2\x96\x91.dat");  // café/░.dat
  EXPECT_EQ(editor.Text(), "caf\xC3\xA9/\xE2\x96\x91.dat");
  EXPECT_EQ(editor.Cursor(), 10U);
  editor.Home();
  for (int i = 0; i < 4; ++i) editor.Right();
  editor.Backspace();  // the e-acute, both of its bytes
  EXPECT_EQ(editor.Text(), "caf/\xE2\x96\x91.dat");
  // Broken sequences leave nothing behind: a lone continuation byte, a lead
  // byte cut short by ASCII, an overlong form.
  editor.End();
  Type(editor, "\x80\xE2\x96x\xC0\xAF");
  EXPECT_EQ(editor.Text(), "caf/\xE2\x96\x91.datx");
}

// A completed file name keeps the bytes typing would drop (the file must
// open), shown as '?' and given back as they were; typing still drops them.
TEST(LineEditor, CompletedNamesKeepControlAndInvalidBytes) {
  LineEditor editor;
  const std::string name = "evil\x1b[31mRED\x1b]0;pwned\x07 caf\xC3\xA9 \xFF\xC3.obj";
  editor.SetText(name);
  EXPECT_EQ(editor.Text(), name);
  EXPECT_EQ(editor.Cursor(), editor.CodePoints().size());
  size_t raw = 0;
  for (const char32_t c : editor.CodePoints()) raw += LineEditor::IsRawByte(c) ? 1 : 0;
  EXPECT_EQ(raw, 5U);  // two ESC, BEL, 0xFF and the cut-short 0xC3
  Type(editor, "\x1b");
  EXPECT_EQ(editor.Text(), name);
  editor.Backspace();  // the last code point, '.obj''s j
  EXPECT_EQ(editor.Text(), name.substr(0, name.size() - 1));
}

TEST(PromptPath, TrimsUnquotesAndExpandsHome) {
  EXPECT_EQ(PromptPath("  data/cube.dat \t", "/home/ann"), "data/cube.dat");
  EXPECT_EQ(PromptPath("'/tmp/my models/cube.dat' ", "/home/ann"), "/tmp/my models/cube.dat");
  EXPECT_EQ(PromptPath("\"/tmp/a.obj\"", "/home/ann"), "/tmp/a.obj");
  EXPECT_EQ(PromptPath("'unbalanced.dat", "/home/ann"), "'unbalanced.dat");
  EXPECT_EQ(PromptPath("~/models/a.dat", "/home/ann"), "/home/ann/models/a.dat");
  EXPECT_EQ(PromptPath("~", "/home/ann"), "/home/ann");
  EXPECT_EQ(PromptPath("~bob/a.dat", "/home/ann"), "~bob/a.dat");  // other users' homes: as typed
  EXPECT_EQ(PromptPath("~/a.dat", ""), "~/a.dat");                 // no HOME: as typed
  EXPECT_EQ(PromptPath("   ", "/home/ann"), "");
}

// A scratch directory with a few models, removed afterwards.
class PathCompletionTest : public testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("termshade-complete-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir_ / "models");
    for (const char* name : {"cube.dat", "cone.dat", "models/wedge.dat", ".hidden.dat"}) {
      std::ofstream(dir_ / name) << "1 0 0 0\n";
    }
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string Dir() const { return dir_.string(); }
  std::filesystem::path dir_;
};

TEST_F(PathCompletionTest, ExtendsByWhatTheMatchesShare) {
  EXPECT_EQ(CompletePath(Dir() + "/cu", "").text, Dir() + "/cube.dat");
  EXPECT_EQ(CompletePath(Dir() + "/cu", "").matches, 1);
  const PathCompletion two = CompletePath(Dir() + "/c", "");
  EXPECT_EQ(two.text, Dir() + "/c");  // cube.dat and cone.dat share only the c
  EXPECT_EQ(two.matches, 2);
  EXPECT_EQ(CompletePath(Dir() + "/co", "").text, Dir() + "/cone.dat");
  EXPECT_EQ(CompletePath(Dir() + "/mo", "").text, Dir() + "/models/");
  EXPECT_EQ(CompletePath(Dir() + "/models/", "").text, Dir() + "/models/wedge.dat");
  EXPECT_EQ(CompletePath(Dir() + "/x", "").matches, 0);
  EXPECT_EQ(CompletePath(Dir() + "/nothing/x", "").matches, 0);
}

TEST_F(PathCompletionTest, HiddenNamesOnlyWhenAsked) {
  EXPECT_EQ(CompletePath(Dir() + "/", "").matches, 3);  // cube, cone, models
  EXPECT_EQ(CompletePath(Dir() + "/.h", "").text, Dir() + "/.hidden.dat");
}

TEST_F(PathCompletionTest, KeepsTheHomeAsTyped) {
  EXPECT_EQ(CompletePath("~/cu", Dir()).text, "~/cube.dat");
  std::string quoted(1, '\'');  // built by appending: GCC 12 warns (-Wrestrict) on "'" + string
  quoted += Dir() + "/cu";
  EXPECT_EQ(CompletePath(quoted, "").matches, 0);  // quoted: left alone
}

}  // namespace
}  // namespace termshade

namespace termshade {
namespace {

TEST(ViewerState, UpKeyCyclesTheAxisAndKeepsTheView) {
  ViewerOptions options;
  options.modelPaths = {test::SourcePath("tests/models/real/spider_z_up_binary.stl")};
  options.theta = 0.5;
  ViewerState state(options, 0.0);
  ASSERT_FALSE(state.LoadFirst().has_value());
  EXPECT_DOUBLE_EQ(state.View().theta, 0.5);
  state.Apply(ViewerAction::kOrbitRight);
  const ViewParams view = state.View();
  const double diagonal = state.CurrentScene().diagonalModelUnits;
  EXPECT_EQ(state.CurrentScene().upAxis, UpAxis::kPlusZ);
  EXPECT_EQ(ActionForChar('u'), ViewerAction::kCycleUpAxis);
  state.Apply(ViewerAction::kCycleUpAxis);
  // Asked for, prepared on the event loop's worker: the scene shown stays until then.
  EXPECT_EQ(state.CurrentScene().upAxis, UpAxis::kPlusZ);
  const std::optional<LoadRequest> request = state.TakeLoadRequest();
  ASSERT_TRUE(request.has_value());
  ASSERT_TRUE(request->turnTo.has_value());
  EXPECT_EQ(*request->turnTo, UpAxis::kPlusY);
  state.FinishLoad(*request, PrepareScene(state.CurrentScene().SourceMesh(), *request->turnTo));
  EXPECT_EQ(state.CurrentScene().upAxis, UpAxis::kPlusY);
  EXPECT_EQ(state.Message(), "up axis +y");
  EXPECT_EQ(state.View().theta, view.theta);
  EXPECT_EQ(state.View().rho, view.rho);
  EXPECT_DOUBLE_EQ(state.CurrentScene().diagonalModelUnits, diagonal);
  // The same scene as preparing the file with --up y.
  const Scene expected =
      PrepareScene(test::LoadMesh("tests/models/real/spider_z_up_binary.stl"), UpAxis::kPlusY);
  EXPECT_EQ(state.CurrentScene().verticesWorld.size(), expected.verticesWorld.size());
  for (size_t v = 0; v < expected.verticesWorld.size(); ++v) {
    ASSERT_EQ(state.CurrentScene().verticesWorld[v], expected.verticesWorld[v]);
  }
  for (int i = 0; i < 6; ++i) {
    state.Apply(ViewerAction::kCycleUpAxis);
    state.RunPendingLoad();
  }
  EXPECT_EQ(state.CurrentScene().upAxis, UpAxis::kPlusY);  // six presses: round the cycle
}

TEST(ViewerState, UpOptionAppliesToEveryModel) {
  ViewerOptions options;
  options.upAxis = UpAxis::kMinusX;
  ViewerState state(options, 0.0);
  ASSERT_FALSE(state.LoadFirst().has_value());
  EXPECT_EQ(state.CurrentScene().upAxis, UpAxis::kMinusX);
  EXPECT_TRUE(state.CurrentScene().upAxisOverridden);
}

}  // namespace
}  // namespace termshade
