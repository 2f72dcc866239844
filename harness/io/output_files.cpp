#include "harness/io/output_files.hpp"

#include "schemes/registry.hpp"

#include <atomic>
#include <cmath>
#include <fmt/format.h>
#include <fstream>
#include <iterator>
#include <unistd.h>

namespace rotbench {

void write_file_atomically(const std::filesystem::path& path, const std::string& content) {
    // The temporary name is unique to the process and the call: two processes or threads
    // writing the same file (a shared cache) each rename a complete file.
    static std::atomic<unsigned long> serial{0};
    const auto temporary =
        path.parent_path() / fmt::format(".{}.{}.{}.tmp", path.filename().string(), ::getpid(), serial++);
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        out << content;
        out.flush();
        if (!out) throw InputError("cannot write " + temporary.string());
    }
    std::error_code ec;
    std::filesystem::rename(temporary, path, ec);
    if (ec) throw InputError("cannot write " + path.string() + ": " + ec.message());
}

std::optional<std::string> read_file(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return std::nullopt;
    return std::string{std::istreambuf_iterator<char>(in), {}};
}

std::string format_number(double value) {
    if (std::isnan(value)) return "nan";
    if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
    return fmt::format("{}", value);  // shortest representation that round-trips
}

}  // namespace rotbench
