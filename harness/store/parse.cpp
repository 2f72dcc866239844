#include "harness/store/parse.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace rotbench {

std::vector<std::string> split_commas(const std::string& text) { return split_on(text, ','); }

std::vector<std::string> split_on(const std::string& text, char separator) {
    std::vector<std::string> parts;
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = text.find(separator, start);
        parts.push_back(text.substr(start, comma - start));
        if (comma == std::string::npos) return parts;
        start = comma + 1;
    }
}

namespace {

double parse_number(const std::string& text, const std::string& option) {
    double value = 0.0;
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, value);
    if (text.empty() || ec != std::errc() || ptr != end) throw InputError(option + ": '" + text + "' is not a number");
    return value;
}

}  // namespace

double parse_finite(const std::string& text, const std::string& option) {
    const double value = parse_number(text, option);
    if (!std::isfinite(value)) throw InputError(option + ": '" + text + "' must be a finite number");
    return value;
}

double parse_positive(const std::string& text, const std::string& option) {
    const double value = parse_number(text, option);
    if (!std::isfinite(value) || value <= 0.0)
        throw InputError(option + ": '" + text + "' must be a finite number greater than 0");
    return value;
}

namespace {

template <class ParseOne>
std::vector<double> parse_list(const std::string& text, const std::string& option, ParseOne parse_one) {
    std::vector<double> values;
    for (const std::string& part : split_commas(text)) {
        const double v = parse_one(part, option);
        if (std::find(values.begin(), values.end(), v) != values.end())
            throw InputError(option + ": " + part + " is given twice");
        values.push_back(v);
    }
    return values;
}

}  // namespace

std::vector<double> parse_positive_list(const std::string& text, const std::string& option) {
    return parse_list(text, option, parse_positive);
}

std::vector<double> parse_nonnegative_list(const std::string& text, const std::string& option) {
    return parse_list(text, option, [](const std::string& part, const std::string& opt) {
        const double v = parse_finite(part, opt);
        if (v < 0) throw InputError(opt + ": '" + part + "' must not be negative");
        return v;
    });
}

bool is_id(const std::string& text) {
    return !text.empty() && text.size() <= max_id_length &&
           std::all_of(text.begin(), text.end(), [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
}

}  // namespace rotbench
