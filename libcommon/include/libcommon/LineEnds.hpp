#pragma once
// Line ends of every kind a text input may come with. Old Mac spreadsheets and editors end a line with
// a carriage return alone: read by std::getline, such a file was one line (a CSV's header took in its
// rows, a scene file named no terrain). Windows' CR LF needs nothing: the readers trim the '\r'.
#include <string>

namespace sylva {

// `text` with each carriage return that no line feed follows turned into a line feed.
std::string withLoneCarriageReturnsAsLineFeeds(std::string text);

}  // namespace sylva
