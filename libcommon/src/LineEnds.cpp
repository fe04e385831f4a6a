#include "libcommon/LineEnds.hpp"

namespace sylva {

std::string withCrOnlyLineEndsAsLineFeeds(std::string text) {
    // Only a file without any line feed: "\r\r\n" (Python's csv module on Windows) is one line end,
    // whose carriage returns the readers trim, not a line and a blank one.
    if (text.find('\n') != std::string::npos) return text;
    for (char& c : text)
        if (c == '\r') c = '\n';
    return text;
}

}  // namespace sylva
