# Writes OUTPUT, a header naming the commit the build is made from (git describe, "-dirty" when the
# work tree has changes; "unknown" outside a git clone), rewritten only when that changes so that a
# build with nothing new compiles nothing. Run at every build by the target sylvarock_build_id: the
# stores of assess and hazard record it, and a resume by another build says so.
execute_process(COMMAND git -C "${SOURCE_DIR}" describe --always --dirty --abbrev=12
                OUTPUT_VARIABLE id OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET RESULT_VARIABLE rc)
if(NOT rc EQUAL 0 OR id STREQUAL "")
  set(id "unknown")
endif()
set(text "#pragma once\n#define SYLVAROCK_BUILD_ID \"${id}\"\n")
set(old "")
if(EXISTS "${OUTPUT}")
  file(READ "${OUTPUT}" old)
endif()
if(NOT old STREQUAL text)
  file(WRITE "${OUTPUT}" "${text}")
endif()
