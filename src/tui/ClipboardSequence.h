#pragma once

#include <string>
#include <string_view>

namespace termshade {

/// OSC 52, which asks the terminal to put `text` on the clipboard:
/// ESC ] 52 ; c ; BASE64 BEL. Terminals that do not allow it ignore it;
/// tmux takes it as a paste buffer with `set-clipboard on`.
std::string ClipboardSequence(std::string_view text);

/// Standard base64 (RFC 4648, with padding).
std::string Base64(std::string_view bytes);

}  // namespace termshade
