#pragma once
// Line ends of every kind a text input may come with. Old Mac spreadsheets and editors end a line with
// a carriage return alone: read by std::getline, such a file was one line (a CSV's header took in its
// rows, a scene file named no terrain). Windows' CR LF needs nothing: the readers trim the '\r'.
#include <string>

namespace sylva {

// `text` with its carriage returns turned into line feeds when it holds no line feed at all (lines
// ended by CR alone); any other text as it is.
std::string withCrOnlyLineEndsAsLineFeeds(std::string text);

}  // namespace sylva
