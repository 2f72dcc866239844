#include "harness/store/csv.hpp"

#include "harness/store/output_files.hpp"
#include "harness/store/parse.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fmt/format.h>
#include <limits>

namespace rotbench {

std::string csv_record(const std::vector<std::string>& fields) {
    std::string out;
    for (std::size_t i = 0; i < fields.size(); ++i) {
        const std::string& f = fields[i];
        if (i) out += ',';
        if (f.find_first_of(",\"\r\n") == std::string::npos) {
            out += f;
            continue;
        }
        out += '"';
        for (char c : f) out += c == '"' ? std::string("\"\"") : std::string(1, c);
        out += '"';
    }
    return out + "\n";
}

std::vector<CsvRow> parse_csv(const std::string& text, const std::string& name) {
    std::vector<CsvRow> records;
    std::vector<std::string> record;
    std::string field;
    std::size_t line = 1, i = 0, start = 1;
    const auto fail = [&](const std::string& what) { throw InputError(fmt::format("{}:{}: {}", name, line, what)); };
    while (i < text.size()) {
        if (text[i] == '"') {  // a quoted field, to its closing quote
            ++i;
            for (;; ++i) {
                if (i >= text.size()) throw InputError(fmt::format("{}:{}: a quoted field is not closed", name, start));
                if (text[i] == '"') {
                    if (i + 1 < text.size() && text[i + 1] == '"') {
                        field += '"';
                        ++i;
                        continue;
                    }
                    ++i;
                    break;
                }
                if (text[i] == '\n') ++line;
                field += text[i];
            }
            if (i < text.size() && text[i] != ',' && text[i] != '\n' && text[i] != '\r') fail("text after a closing quote");
        }
        while (i < text.size() && text[i] != ',' && text[i] != '\n' && text[i] != '\r') {
            if (text[i] == '"') fail("a quote inside an unquoted field");
            field += text[i++];
        }
        if (i < text.size() && text[i] == '\r') {
            if (i + 1 >= text.size() || text[i + 1] != '\n') fail("a carriage return outside a quoted field");
            ++i;
        }
        record.push_back(std::move(field));
        field.clear();
        if (i < text.size() && text[i] == ',') {
            ++i;
            if (i == text.size()) record.push_back("");
            continue;
        }
        records.push_back({start, std::move(record)});
        record.clear();
        ++line;
        ++i;  // the line break
        start = line;
    }
    if (!record.empty()) records.push_back({start, std::move(record)});
    return records;
}

std::string where(const std::string& name, const CsvRow& row) { return fmt::format("{}:{}", name, row.line); }

std::vector<CsvRow> read_csv(const std::string& text, const std::string& name, const std::string& header) {
    if (text.empty()) throw InputError(name + ": the file is empty; expected the header '" + header + "'");
    auto records = parse_csv(text, name);
    const auto expected = parse_csv(header + "\n", "header");
    if (records.empty() || records.front().fields != expected.front().fields)
        throw InputError(name + ":1: expected the header '" + header + "'");
    if (text.back() != '\n')
        throw InputError(fmt::format("{}:{}: the file ends in the middle of a record (cut short?)", name, records.back().line));
    const std::size_t width = expected.front().size();
    for (const auto& r : records)
        if (r.size() != width) throw InputError(fmt::format("{}: expected {} fields, found {}", where(name, r), width, r.size()));
    records.erase(records.begin());
    return records;
}

std::vector<CsvRow> read_csv(const std::filesystem::path& path, const std::string& header) {
    return read_csv(read_input_file(path, "cannot read"), path.string(), header);
}

double csv_number(const std::string& text, const std::string& where) {
    if (text == "nan") return std::numeric_limits<double>::quiet_NaN();
    if (text == "inf") return std::numeric_limits<double>::infinity();
    if (text == "-inf") return -std::numeric_limits<double>::infinity();
    double v = 0;
    const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (text.empty() || ec != std::errc() || ptr != text.data() + text.size())
        throw InputError(where + ": '" + text + "' is not a number");
    return v;
}

}  // namespace rotbench
