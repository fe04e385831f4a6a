# Writes OUTPUT, a header naming the commit the build is made from, rewritten only when that changes
# so that a build with nothing new compiles nothing. Run at every build by the target
# sylvarock_build_id: the stores of assess and hazard record it, and a resume by another build says so.
# - `git describe --always --abbrev=12`; a work tree with changes adds "-dirty-" and a hash of
#   `git diff HEAD`, so that two builds of different edits are two ids;
# - GIT_OPTIONAL_LOCKS=0: the build never takes the index's lock (a `git commit` running meanwhile
#   would fail on it);
# - outside a clone of its own (a tarball, even one unpacked inside another repository): "unknown".
set(ENV{GIT_OPTIONAL_LOCKS} 0)
set(id "unknown")
execute_process(COMMAND git -C "${SOURCE_DIR}" rev-parse --show-toplevel
                OUTPUT_VARIABLE top OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET RESULT_VARIABLE rc)
get_filename_component(source_real "${SOURCE_DIR}" REALPATH)
if(rc EQUAL 0 AND NOT top STREQUAL "")
  get_filename_component(top_real "${top}" REALPATH)
endif()
if(rc EQUAL 0 AND top_real STREQUAL source_real)
  execute_process(COMMAND git -C "${SOURCE_DIR}" describe --always --abbrev=12
                  OUTPUT_VARIABLE commit OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET RESULT_VARIABLE rc)
  if(rc EQUAL 0 AND NOT commit STREQUAL "")
    set(id "${commit}")
    execute_process(COMMAND git -C "${SOURCE_DIR}" diff HEAD
                    OUTPUT_VARIABLE changes ERROR_QUIET RESULT_VARIABLE rc)
    if(rc EQUAL 0 AND NOT changes STREQUAL "")
      string(SHA1 changes_hash "${changes}")
      string(SUBSTRING "${changes_hash}" 0 8 changes_hash)
      set(id "${commit}-dirty-${changes_hash}")
    endif()
  endif()
endif()
set(text "#pragma once\n#define SYLVAROCK_BUILD_ID \"${id}\"\n")
set(old "")
if(EXISTS "${OUTPUT}")
  file(READ "${OUTPUT}" old)
endif()
if(NOT old STREQUAL text)
  file(WRITE "${OUTPUT}" "${text}")
endif()
