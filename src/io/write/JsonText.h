#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace termshade {

/// text as a JSON string (quotes, backslashes and control bytes escaped;
/// UTF-8 passed through).
void AppendJsonText(std::string_view text, std::string& out);
/// The bytes AppendJsonText makes of text, less the two quotes.
size_t JsonTextLength(std::string_view text);

}  // namespace termshade
