#include "libdem/OptionErrorMessage.hpp"

namespace sylva {

namespace {

// A copy of the error whose substitutions (the option's name, the user's value) hold no '%'.
class Defused : public boost::program_options::error_with_option_name {
public:
    explicit Defused(const boost::program_options::error_with_option_name& e) : error_with_option_name(e) {
        for (auto& [placeholder, value] : m_substitutions) {
            std::string safe;
            for (char c : value) safe += c == '%' ? std::string("(%)") : std::string(1, c);
            value = safe;
        }
    }
};

}  // namespace

std::string optionErrorMessage(const boost::program_options::error& e) {
    if (const auto* named = dynamic_cast<const boost::program_options::error_with_option_name*>(&e)) return Defused(*named).what();
    return e.what();
}

}  // namespace sylva
