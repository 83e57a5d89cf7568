#include "SpeedErrorPlot.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

namespace termshade {
namespace {

constexpr std::array<const char*, 10> kColours{"#1f77b4", "#2ca02c", "#17becf", "#d62728",
                                               "#ff7f0e", "#9467bd", "#8c564b", "#e377c2",
                                               "#7f7f7f", "#bcbd22"};

struct Panel {
  double left, top, width, height;
  double xLowLog, xHighLog;  ///< log10 of ms
  double yHigh;
  std::string yLabel;

  double X(double ms) const {
    return left + width * (std::log10(ms) - xLowLog) / (xHighLog - xLowLog);
  }
  double yLow = 0.0;
  double Y(double value) const { return top + height * (1.0 - (value - yLow) / (yHigh - yLow)); }
};

void DrawAxes(std::ostringstream& svg, const Panel& p) {
  svg << "<rect x='" << p.left << "' y='" << p.top << "' width='" << p.width << "' height='"
      << p.height << "' fill='none' stroke='#444'/>\n";
  for (int decade = static_cast<int>(std::ceil(p.xLowLog)); decade <= p.xHighLog; ++decade) {
    const double x = p.X(std::pow(10.0, decade));
    svg << "<line x1='" << x << "' y1='" << p.top << "' x2='" << x << "' y2='" << p.top + p.height
        << "' stroke='#ddd'/><text x='" << x << "' y='" << p.top + p.height + 16
        << "' font-size='11' text-anchor='middle'>" << std::pow(10.0, decade) << "</text>\n";
  }
  for (int i = 0; i <= 4; ++i) {
    const double value = p.yLow + (p.yHigh - p.yLow) * i / 4;
    const double y = p.Y(value);
    svg << "<line x1='" << p.left << "' y1='" << y << "' x2='" << p.left + p.width << "' y2='" << y
        << "' stroke='#eee'/><text x='" << p.left - 6 << "' y='" << y + 4
        << "' font-size='11' text-anchor='end'>" << value << "</text>\n";
  }
  svg << "<text x='" << p.left + p.width / 2 << "' y='" << p.top + p.height + 34
      << "' font-size='12' text-anchor='middle'>median time per frame, ms (log)</text>\n"
      << "<text x='" << p.left - 44 << "' y='" << p.top + p.height / 2
      << "' font-size='12' text-anchor='middle' transform='rotate(-90 " << p.left - 44 << ' '
      << p.top + p.height / 2 << ")'>" << p.yLabel << "</text>\n";
}

double LogLow(double ms) {
  return std::floor(std::log10(std::max(ms, 1e-4)));
}
double LogHigh(double ms) {
  return std::ceil(std::log10(std::max(ms, 1e-3)));
}

}  // namespace

void WriteSpeedFidelityPlot(const std::vector<FidelityPoint>& points, const std::string& machine,
                            const std::string& path) {
  std::map<std::string, size_t> modeColour;
  double lowMs = 1e9, highMs = 1e-9, lowSsim = 1.0;
  for (const FidelityPoint& p : points) {
    modeColour.try_emplace(p.mode, modeColour.size() % kColours.size());
    lowMs = std::min(lowMs, p.medianMs);
    highMs = std::max(highMs, p.medianMs);
    lowSsim = std::min(lowSsim, p.ssim);
  }
  Panel panel{70, 50, 700, 420, LogLow(lowMs), LogHigh(highMs), 1.0, "blurred SSIM (1 = exact)"};
  panel.yLow = std::floor(std::max(0.0, lowSsim) * 10) / 10;
  std::ostringstream svg;
  svg << "<svg xmlns='http://www.w3.org/2000/svg' width='1000' height='540' "
         "font-family='sans-serif'>\n"
      << "<rect width='1000' height='540' fill='white'/>\n"
      << "<text x='20' y='24' font-size='15'>termshade: speed against fidelity, each point one "
         "glyph mode on one scene (160x48 cells). "
      << machine << "</text>\n";
  DrawAxes(svg, panel);
  for (const FidelityPoint& p : points) {
    // Colour modes filled, mono modes as rings.
    const bool colour = p.mode.find("colour") != std::string::npos;
    const char* c = kColours[modeColour[p.mode] / 2 % kColours.size()];
    svg << "<circle cx='" << panel.X(p.medianMs) << "' cy='" << panel.Y(p.ssim) << "' r='4' "
        << (colour ? "fill='" + std::string(c) + "'"
                   : "fill='none' stroke='" + std::string(c) + "'")
        << "><title>" << p.mode << " / " << p.scene << "</title></circle>\n";
  }
  int row = 0;
  for (const auto& [mode, colour] : modeColour) {
    const int y = 60 + 18 * row++;
    const char* c = kColours[colour / 2 % kColours.size()];
    const bool filled = mode.find("colour") != std::string::npos;
    svg << "<circle cx='800' cy='" << y - 4 << "' r='5' "
        << (filled ? "fill='" + std::string(c) + "'"
                   : "fill='none' stroke='" + std::string(c) + "'")
        << "/><text x='812' y='" << y << "' font-size='12'>" << mode << "</text>\n";
  }
  svg << "</svg>\n";
  std::ofstream(path) << svg.str();
}

void WriteSpeedErrorPlot(const std::vector<PlotPoint>& points, const std::string& machine,
                         const std::string& path) {
  std::map<std::string, size_t> methodColour;
  double lowMs = 1e9, highMs = 1e-9, highFace = 0.0, highShade = 0.0;
  for (const PlotPoint& p : points) {
    methodColour.try_emplace(p.method, methodColour.size() % kColours.size());
    lowMs = std::min(lowMs, p.medianMs);
    highMs = std::max(highMs, p.medianMs);
    highFace = std::max(highFace, 100.0 * p.faceError);
    highShade = std::max(highShade, p.shadeErrorLevels);
  }
  auto roundUp = [](double v) {
    const double step = std::pow(10.0, std::floor(std::log10(std::max(v, 1e-3))));
    return std::ceil(v / step) * step;
  };
  const double xLow = LogLow(lowMs), xHigh = LogHigh(highMs);
  const Panel facePanel{
      70, 50, 420, 320, xLow, xHigh, roundUp(std::max(highFace, 0.1)), "face error, % of cells"};
  const Panel shadePanel{570,
                         50,
                         420,
                         320,
                         xLow,
                         xHigh,
                         roundUp(std::max(highShade, 0.1)),
                         "shade error, RMS ramp levels"};
  std::ostringstream svg;
  svg << "<svg xmlns='http://www.w3.org/2000/svg' width='1300' height='440' "
         "font-family='sans-serif'>\n"
      << "<rect width='1300' height='440' fill='white'/>\n"
      << "<text x='20' y='24' font-size='15'>termshade: speed against error, each point one method "
         "on one scene (160x48 cells). "
      << machine << "</text>\n";
  DrawAxes(svg, facePanel);
  DrawAxes(svg, shadePanel);
  for (const PlotPoint& p : points) {
    const char* colour = kColours[methodColour[p.method]];
    if (p.faceError >= 0) {
      svg << "<circle cx='" << facePanel.X(p.medianMs) << "' cy='" << facePanel.Y(100 * p.faceError)
          << "' r='4' fill='" << colour << "' fill-opacity='0.8'><title>" << p.method << " / "
          << p.scene << "</title></circle>\n";
    }
    svg << "<circle cx='" << shadePanel.X(p.medianMs) << "' cy='"
        << shadePanel.Y(p.shadeErrorLevels) << "' r='4' fill='" << colour
        << "' fill-opacity='0.8'><title>" << p.method << " / " << p.scene << "</title></circle>\n";
  }
  int row = 0;
  for (const auto& [method, colour] : methodColour) {
    const int y = 60 + 18 * row++;
    svg << "<circle cx='1030' cy='" << y - 4 << "' r='5' fill='" << kColours[colour]
        << "'/><text x='1042' y='" << y << "' font-size='12'>" << method << "</text>\n";
  }
  svg << "</svg>\n";
  std::ofstream(path) << svg.str();
}

}  // namespace termshade
