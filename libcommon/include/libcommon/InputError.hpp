#pragma once
// An error in something a user gave us (a file, an option, a scene key). It names where the
// problem is, so the CLI can print "FILE:LINE: what" and exit non-zero instead of crashing.
#include <sstream>
#include <stdexcept>
#include <string>

namespace sylva {

class InputError : public std::runtime_error {
public:
    InputError(std::string file, long line, const std::string& what)
        : std::runtime_error(format(file, line, what)), file_(std::move(file)), line_(line) {}
    explicit InputError(const std::string& what) : std::runtime_error(what), line_(0) {}

    const std::string& file() const { return file_; }
    long line() const { return line_; }

private:
    static std::string format(const std::string& file, long line, const std::string& what) {
        if (file.empty()) return what;
        return line > 0 ? file + ":" + std::to_string(line) + ": " + what : file + ": " + what;
    }
    std::string file_;
    long line_;
};

// A number as a message shows it: the shortest readable form (0.7, 1e+308), not to_string's 0.700000.
// Ten significant digits, so that a projected coordinate names its metre (6460100, where the stream's
// default six gave 6.4601e+06, a 100 m strip).
inline std::string readableNumber(double v) {
    std::ostringstream os;
    os.precision(10);
    os << v;
    return os.str();
}

// Why `path` could not be opened for writing, called right after the failed open (it reads errno):
// a folder given for a file, a folder that does not exist, or the system's reason ("cannot open file
// for writing" alone left the user to guess).
InputError cannotWrite(const std::string& path);

}  // namespace sylva
