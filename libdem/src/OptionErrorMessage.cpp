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

    std::string value() const {
        const auto v = m_substitutions.find("value");
        return v == m_substitutions.end() ? std::string() : v->second;
    }
};

bool isWholeNumber(const std::string& s) {
    const std::size_t sign = !s.empty() && (s[0] == '-' || s[0] == '+') ? 1 : 0;
    return s.size() > sign && s.find_first_not_of("0123456789", sign) == std::string::npos;
}

}  // namespace

std::string optionErrorMessage(const boost::program_options::error& e) {
    if (const auto* named = dynamic_cast<const boost::program_options::error_with_option_name*>(&e)) {
        const Defused defused(*named);
        // A whole number refused by a whole-number option can only be out of its range; "is invalid"
        // alone left the user looking for a typo.
        if (dynamic_cast<const boost::program_options::invalid_option_value*>(&e) && isWholeNumber(defused.value()))
            return std::string(defused.what()) + ": out of the range this option takes";
        return defused.what();
    }
    return e.what();
}

}  // namespace sylva
