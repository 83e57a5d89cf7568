#include "io/write/FrameDiff.h"

#include <algorithm>
#include <cstdio>
#include <optional>

#include "shade/Utf8.h"

namespace termshade {
namespace {

constexpr const char* kMarkOn = "\x1b[1;7;31m";
constexpr const char* kMarkOff = "\x1b[0m";

std::vector<char32_t> Cells(const std::string& row) {
  auto decoded = DecodeUtf8(row);
  if (decoded) return std::move(*decoded);
  return std::vector<char32_t>(row.begin(), row.end());  // not UTF-8: byte by byte, escaped below
}

// A cell as the terminal may be sent it: a control or format character
// (escape sequences in a golden made by hand) as '?', so no such byte
// reaches the terminal and the columns stay aligned.
char32_t ShownCell(char32_t cell) {
  return IsControlOrFormat(cell) ? U'?' : cell;
}

// One frame row, `width` cells (padded with blanks), marked cells highlighted.
std::string ShownRow(const std::string& row, const uint8_t* marks, int width, bool colour) {
  const std::vector<char32_t> cells = Cells(row);
  std::string out;
  for (int c = 0; c < width; ++c) {
    const char32_t cell = c < static_cast<int>(cells.size()) ? cells[static_cast<size_t>(c)] : U' ';
    const bool marked = marks != nullptr && marks[c] != 0;
    if (marked && colour) out += kMarkOn;
    AppendUtf8(out, ShownCell(cell));
    if (marked && colour) out += kMarkOff;
  }
  return out;
}

std::string Padded(std::string text, size_t width) {
  if (text.size() < width) text.append(width - text.size(), ' ');
  return text;
}

std::vector<std::string> SplitRows(std::string_view text) {
  std::vector<std::string> rows;
  size_t start = 0;
  while (start < text.size()) {
    const size_t end = std::min(text.find('\n', start), text.size());
    rows.emplace_back(text.substr(start, end - start));
    start = end + 1;
  }
  return rows;
}

}  // namespace

std::string SideBySideFrameDiff(const std::vector<std::string>& goldenRows,
                                const std::vector<std::string>& actualRows,
                                const std::vector<uint8_t>& marked, int widthCells, bool colour) {
  const int rows = static_cast<int>(std::max(goldenRows.size(), actualRows.size()));
  const auto rowMarked = [&](int row) {
    const size_t begin = static_cast<size_t>(row) * widthCells;
    if (begin + widthCells > marked.size()) return false;
    return std::any_of(marked.begin() + begin, marked.begin() + begin + widthCells,
                       [](uint8_t m) { return m != 0; });
  };
  std::vector<uint8_t> shown(static_cast<size_t>(rows), 0);
  for (int row = 0; row < rows; ++row) {
    if (!rowMarked(row)) continue;
    for (int r = std::max(0, row - 1); r <= std::min(rows - 1, row + 1); ++r) shown[r] = 1;
  }
  const std::string blankRow;
  std::string out = "       " + Padded("golden", static_cast<size_t>(widthCells) + 4) + "actual\n";
  bool gap = false, printed = false;
  for (int row = 0; row < rows; ++row) {
    if (shown[row] == 0) {
      gap = true;
      continue;
    }
    if (gap && printed) out += "    ...\n";
    gap = false;
    printed = true;
    const uint8_t* marks =
        rowMarked(row) ? marked.data() + static_cast<size_t>(row) * widthCells : nullptr;
    const auto rowOf = [&](const std::vector<std::string>& frame) -> const std::string& {
      return row < static_cast<int>(frame.size()) ? frame[row] : blankRow;
    };
    char number[16];
    std::snprintf(number, sizeof number, "%5d ", row + 1);
    out += number;
    out += '|' + ShownRow(rowOf(goldenRows), marks, widthCells, colour) + "|  |" +
           ShownRow(rowOf(actualRows), marks, widthCells, colour) + "|\n";
    if (marks != nullptr && !colour) {
      std::string carets;
      for (int c = 0; c < widthCells; ++c) carets += marks[c] != 0 ? '^' : ' ';
      out += "       " + carets + "    " + carets + "\n";
    }
  }
  return out;
}

TextFrameDifference CompareTextFrames(std::string_view golden, std::string_view actual,
                                      bool colour) {
  TextFrameDifference result;
  const std::vector<std::string> goldenRows = SplitRows(golden), actualRows = SplitRows(actual);
  const size_t rows = std::max(goldenRows.size(), actualRows.size());
  std::vector<std::vector<char32_t>> g, a;
  size_t width = 0;
  for (size_t row = 0; row < rows; ++row) {
    g.push_back(row < goldenRows.size() ? Cells(goldenRows[row]) : std::vector<char32_t>{});
    a.push_back(row < actualRows.size() ? Cells(actualRows[row]) : std::vector<char32_t>{});
    width = std::max({width, g.back().size(), a.back().size()});
    if (g.back().size() != a.back().size()) result.sameShape = false;
  }
  std::vector<uint8_t> marked(rows * width, 0);
  for (size_t row = 0; row < rows; ++row) {
    for (size_t c = 0; c < width; ++c) {
      const auto at = [c](const std::vector<char32_t>& cells) {
        return c < cells.size() ? std::optional(cells[c]) : std::nullopt;
      };
      if (at(g[row]) == at(a[row])) continue;
      marked[row * width + c] = 1;
      ++result.differingCells;
    }
  }
  if (golden != actual && result.differingCells == 0) {  // line ends alone differ
    result.differingCells = 1;
    result.sameShape = false;
  }
  if (result.differingCells > 0) {
    result.diff =
        SideBySideFrameDiff(goldenRows, actualRows, marked, static_cast<int>(width), colour);
  }
  return result;
}

}  // namespace termshade
