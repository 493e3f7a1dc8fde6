// How input text appears inside error messages. A binary file read by mistake must not put
// control bytes (a NUL cuts the message short in C APIs, an ESC drives the terminal) or a
// megabyte token into the message.
#pragma once
#include <string>
#include <string_view>

namespace tessera {

// `text` with bytes below 0x20, 0x7F and bytes ≥ 0x80 written as \xNN.
std::string printableText(std::string_view text);

// A token as shown in a message: quoted, printable and cut short after 32 bytes ("...").
std::string quotedToken(std::string_view token);

// A string from the input (a JSON name, key or value) as shown in a message: in double quotes,
// printable and cut short after 64 bytes ("...").
std::string quotedString(std::string_view text);

}  // namespace tessera
