#pragma once

#include <string>
#include <string_view>

namespace termshade {

/// A word a POSIX shell reads back as `word`: as it is when it holds only
/// letters, digits and `@%+=:,./-_`; else in single quotes (a quote inside
/// as '\''); a word with a control byte or invalid UTF-8 in bash's $'...'
/// with \xHH escapes, so pasting the command never sends a control
/// character to a terminal or a newline to a shell.
std::string ShellQuote(std::string_view word);

}  // namespace termshade
