#include "harness/io/csv.hpp"

#include "harness/io/output_files.hpp"
#include "harness/io/parse.hpp"

#include <charconv>
#include <fmt/format.h>
#include <sstream>

namespace rotbench {

std::vector<std::vector<std::string>> read_csv(const std::string& text, const std::string& name, const std::string& header) {
    std::istringstream in(text);
    std::string line;
    if (!std::getline(in, line) || line != header) throw InputError(name + ":1: expected the header '" + header + "'");
    std::vector<std::vector<std::string>> rows;
    for (int number = 2; std::getline(in, line); ++number) {
        auto fields = split_commas(line);
        if (fields.size() != split_commas(header).size())
            throw InputError(fmt::format("{}:{}: expected {} fields", name, number, split_commas(header).size()));
        rows.push_back(std::move(fields));
    }
    return rows;
}

std::vector<std::vector<std::string>> read_csv(const std::filesystem::path& path, const std::string& header) {
    const auto text = read_file(path);
    if (!text) throw InputError("cannot read " + path.string());
    return read_csv(*text, path.string(), header);
}

double csv_number(const std::string& text, const std::string& name) {
    double v = 0;
    const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc() || ptr != text.data() + text.size()) throw InputError(name + ": '" + text + "' is not a number");
    return v;
}

}  // namespace rotbench
