#pragma once
// The text of a Boost.Program_options error, safe to ask for. Boost builds it by replacing
// placeholders such as %value% or %canonical_option% in a loop that never ends when the replacement
// holds a placeholder again: `--runs %value%` or a scene key with '%canonical_option%' hung the
// program (found by tests/fuzz/fuzz_scene). Here every '%' the user typed shows as "(%)".
#include <boost/program_options/errors.hpp>
#include <string>

namespace sylva {

std::string optionErrorMessage(const boost::program_options::error& e);

}  // namespace sylva
