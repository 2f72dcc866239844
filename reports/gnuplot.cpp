#include "reports/gnuplot.hpp"

#include "harness/io/output_files.hpp"

#include <cstdlib>
#include <fmt/format.h>

namespace rotbench {

bool draw_with_gnuplot(const std::filesystem::path& path, const std::string& script) {
    write_file_atomically(path, script);
    const std::string command = fmt::format("cd '{}' && gnuplot '{}' > /dev/null 2>&1", path.parent_path().string(),
                                            path.filename().string());
    return std::system(command.c_str()) == 0;
}

}  // namespace rotbench
