#include "reports/gnuplot.hpp"

#include "harness/store/output_files.hpp"

#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <fmt/format.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace rotbench {
namespace fs = std::filesystem;

namespace {

// gnuplot on the PATH, as execvp would find it.
std::string find_gnuplot() {
    const char* path = std::getenv("PATH");
    std::string dirs = path ? path : "/usr/bin:/bin";
    std::size_t start = 0;
    while (start <= dirs.size()) {
        const std::size_t colon = dirs.find(':', start);
        const std::string dir = dirs.substr(start, colon == std::string::npos ? std::string::npos : colon - start);
        const fs::path candidate = fs::path(dir.empty() ? "." : dir) / "gnuplot";
        if (::access(candidate.c_str(), X_OK) == 0) return candidate.string();
        if (colon == std::string::npos) break;
        start = colon + 1;
    }
    return "";
}

// A whole SVG ends with its closing tag.
bool whole_svg(const fs::path& file) {
    const auto text = read_file(file);
    if (!text || text->size() < 6) return false;
    const auto end = text->find_last_not_of(" \n\r\t");
    return end != std::string::npos && text->compare(end + 1 >= 6 ? end + 1 - 6 : 0, 6, "</svg>") == 0;
}

}  // namespace

std::string gnuplot_output(const std::string& svg_name) {
    return "if (!exists('out')) out = '" + svg_name + "'\nset output out\n";
}

Drawn draw_with_gnuplot(const OutputDir& dir, const std::string& relative_script, const std::string& script,
                        const std::string& relative_svg) {
    dir.write(relative_script, script);
    static const std::string gnuplot = find_gnuplot();
    if (gnuplot.empty()) return {false, "gnuplot is not installed"};
    const fs::path svg = dir.claim(relative_svg);
    static std::atomic<unsigned long> serial{0};
    const fs::path temporary = svg.parent_path() / fmt::format(".{}.{}.{}.tmp", svg.filename().string(), ::getpid(), serial++);
    const fs::path script_file = dir.path() / relative_script;

    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addchdir_np(&actions, script_file.parent_path().c_str());
    posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
    // The output name is the script's string: quotes in it are escaped for gnuplot's '...'.
    std::string out_name;
    for (char c : fs::absolute(temporary).string()) out_name += c == '\'' ? std::string("''") : std::string(1, c);
    std::string assignment = "out='" + out_name + "'", name = script_file.filename().string();
    std::string program = gnuplot, flag = "-e";
    char* argv[] = {program.data(), flag.data(), assignment.data(), name.data(), nullptr};
    pid_t pid = 0;
    const int spawned = posix_spawn(&pid, gnuplot.c_str(), &actions, nullptr, argv, environ);
    posix_spawn_file_actions_destroy(&actions);
    if (spawned != 0) return {false, fmt::format("gnuplot could not be started: {}", std::strerror(spawned))};
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    std::error_code ec;
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || !whole_svg(temporary)) {
        fs::remove(temporary, ec);
        return {false, fmt::format("gnuplot failed on {} ({})", relative_script,
                                   WIFEXITED(status) ? fmt::format("exit status {}", WEXITSTATUS(status))
                                                     : fmt::format("signal {}", WTERMSIG(status)))};
    }
    fs::rename(temporary, svg, ec);
    if (ec) {
        fs::remove(temporary, ec);
        throw OutputError("cannot write " + svg.string() + ": " + ec.message());
    }
    return {true, ""};
}

}  // namespace rotbench
