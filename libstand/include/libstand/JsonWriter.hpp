#pragma once
// A small streaming JSON writer: enough for results files, with numbers printed so they read
// back to the same double (%.17g) and non-finite values written as null.
#include <cmath>
#include <cstdio>
#include <ostream>
#include <string>
#include <vector>

namespace sylva {

class JsonWriter {
public:
    explicit JsonWriter(std::ostream& os) : os_(os) {}

    JsonWriter& beginObject() { return open('{'); }
    JsonWriter& endObject() { return close('}'); }
    JsonWriter& beginArray() { return open('['); }
    JsonWriter& endArray() { return close(']'); }

    JsonWriter& key(const std::string& k) {
        separate();
        string(k);
        os_ << ": ";
        afterKey_ = true;
        return *this;
    }
    JsonWriter& value(double v) {
        separate();
        if (!std::isfinite(v)) {
            os_ << "null";
        } else {
            char buf[32];
            std::snprintf(buf, sizeof buf, "%.17g", v);
            os_ << buf;
        }
        return *this;
    }
    JsonWriter& value(int v) { return raw(std::to_string(v)); }
    JsonWriter& value(long v) { return raw(std::to_string(v)); }
    JsonWriter& value(unsigned long v) { return raw(std::to_string(v)); }
    JsonWriter& value(unsigned long long v) { return raw(std::to_string(v)); }
    JsonWriter& value(bool v) { return raw(v ? "true" : "false"); }
    JsonWriter& value(const std::string& v) {
        separate();
        string(v);
        return *this;
    }
    JsonWriter& value(const char* v) { return value(std::string(v)); }
    JsonWriter& null() { return raw("null"); }
    template <class T>
    JsonWriter& field(const std::string& k, const T& v) {
        key(k);
        return value(v);
    }
    JsonWriter& numbers(const std::string& k, const std::vector<double>& v) {
        key(k).beginArray();
        for (double x : v) value(x);
        return endArray();
    }

private:
    JsonWriter& raw(const std::string& text) {
        separate();
        os_ << text;
        return *this;
    }
    JsonWriter& open(char c) {
        separate();
        os_ << c;
        first_.push_back(true);
        return *this;
    }
    JsonWriter& close(char c) {
        first_.pop_back();
        os_ << '\n' << std::string(2 * first_.size(), ' ') << c;
        return *this;
    }
    void separate() {
        if (afterKey_) {
            afterKey_ = false;
            return;
        }
        if (first_.empty()) return;
        if (!first_.back()) os_ << ',';
        os_ << '\n' << std::string(2 * first_.size(), ' ');
        first_.back() = false;
    }
    void string(const std::string& s) {
        os_ << '"';
        for (char c : s) {
            switch (c) {
                case '"': os_ << "\\\""; break;
                case '\\': os_ << "\\\\"; break;
                case '\n': os_ << "\\n"; break;
                case '\t': os_ << "\\t"; break;
                default:
                    if (static_cast<unsigned char>(c) < 0x20) {
                        char buf[8];
                        std::snprintf(buf, sizeof buf, "\\u%04x", c);
                        os_ << buf;
                    } else {
                        os_ << c;
                    }
            }
        }
        os_ << '"';
    }
    std::ostream& os_;
    std::vector<bool> first_;
    bool afterKey_ = false;
};

}  // namespace sylva
