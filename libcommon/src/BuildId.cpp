#include "libcommon/BuildId.hpp"

#include "sylvarock_build_id.hpp"

namespace sylva {
const char* buildId() { return SYLVAROCK_BUILD_ID; }
}  // namespace sylva
