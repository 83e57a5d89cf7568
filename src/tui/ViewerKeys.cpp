#include "tui/ViewerKeys.h"

#include <algorithm>
#include <array>

namespace termshade {

namespace {

constexpr std::array kKeys{
    ViewerKey{"arrows, h j k l", "orbit (0.1 rad a press)", "hjkl"},
    ViewerKey{"+ - PgUp PgDn", "closer / farther (x0.5 / x2)", "+=-_"},
    ViewerKey{"Insert Delete", "closer / farther", ""},
    ViewerKey{"mouse", "drag orbits, wheel: distance", ""},
    ViewerKey{"r", "reset the view", "r"},
    ViewerKey{"f", "refit the model to the window", "f"},
    ViewerKey{"m", "method: zbuffer painter cull wire auto", "m"},
    ViewerKey{"s", "shading: contrast / lambert", "s"},
    ViewerKey{"b", "back faces: culled / drawn", "b"},
    ViewerKey{"t", "textures: drawn / face colours only", "t"},
    ViewerKey{"u", "up axis: +z +y +x -z -y -x", "u"},
    ViewerKey{"c", "colour mode: next the terminal has", "c"},
    ViewerKey{"g", "glyphs: ramp ascii blocks quadrants sextants braille", "g"},
    ViewerKey{"L", "light mode: arrows move the sun", "L"},
    ViewerKey{"space", "turntable on / off", " "},
    ViewerKey{"a A", "cell aspect - / +", "aA"},
    ViewerKey{"y", "show the render command of this view, copy it (OSC 52)", "y"},
    ViewerKey{"o", "open a model file (Tab completes)", "o"},
    ViewerKey{"n p", "next / previous model", "np"},
    ViewerKey{"Esc", "cancel a load", ""},
    ViewerKey{"?", "this help", "?"},
    ViewerKey{"q Ctrl-C", "quit (Ctrl-Z suspends)", "qQ"},
};

}  // namespace

std::span<const ViewerKey> ViewerKeyTable() {
  return kKeys;
}

std::string FormatViewerKeys(std::string_view indent) {
  size_t keysWidth = 0;
  for (const ViewerKey& key : kKeys) keysWidth = std::max(keysWidth, key.keys.size());
  std::string text;
  for (const ViewerKey& key : kKeys) {
    text.append(indent).append(key.keys);
    text.append(keysWidth + 2 - key.keys.size(), ' ').append(key.does).append("\n");
  }
  return text;
}

}  // namespace termshade
