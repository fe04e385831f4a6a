#include "libcommon/LineEnds.hpp"

namespace sylva {

std::string withLoneCarriageReturnsAsLineFeeds(std::string text) {
    for (std::size_t i = 0; i < text.size(); ++i)
        if (text[i] == '\r' && (i + 1 == text.size() || text[i + 1] != '\n')) text[i] = '\n';
    return text;
}

}  // namespace sylva
