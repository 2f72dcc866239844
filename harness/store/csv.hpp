// The CSV files rotbench writes and reads back, as RFC 4180 has them: fields separated by
// commas, a field quoted ("...", with "" for a quote) when it holds a comma, a quote, a
// carriage return or a line break; records end with a line break. One writer and one reader,
// so that whatever a field holds comes back as it was written.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace rotbench {

// One record, line break included.
std::string csv_record(const std::vector<std::string>& fields);

// One record and the line it starts on (from 1).
struct CsvRow {
    std::size_t line = 0;
    std::vector<std::string> fields;
    const std::string& operator[](std::size_t i) const { return fields[i]; }
    std::size_t size() const { return fields.size(); }
};

// The records of `text`; `name` stands for the file in errors (InputError name:line: ...,
// for an unterminated quote or text after a closing quote).
std::vector<CsvRow> parse_csv(const std::string& text, const std::string& name);

// The records after the header, which must be exactly `header`; every record must have as
// many fields as the header. The text must end with a line break (a file cut short does not).
// Errors name the file and the line.
std::vector<CsvRow> read_csv(const std::string& text, const std::string& name, const std::string& header);
std::vector<CsvRow> read_csv(const std::filesystem::path& path, const std::string& header);

// "name:line" of a row, for messages.
std::string where(const std::string& name, const CsvRow& row);

// A number field, the whole text consumed ("nan", "inf" and "-inf" included).
double csv_number(const std::string& text, const std::string& where);

}  // namespace rotbench
