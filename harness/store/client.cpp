#include "harness/store/client.hpp"

#include "harness/core/fnv1a.hpp"
#include "harness/scenes/scene.hpp"
#include "harness/store/output_files.hpp"
#include "harness/store/plugin.hpp"
#include "harness/store/program_path.hpp"
#include "harness/store/toml_input.hpp"
#include "schemes/scheme.hpp"

#include "harness/store/parse.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <stdexcept>
#include <unistd.h>

namespace rotbench {
namespace {

std::vector<LoadedClient>& clients() {
    static std::vector<LoadedClient> list;
    return list;
}

// What the registry makes for a client: nothing that can step in this process.
class ProgramOnly final : public RotationScheme {
public:
    explicit ProgramOnly(std::string id) : id_(std::move(id)) {}
    void start(const Bodies&) override { refuse(); }
    void predict(Bodies&, double) override { refuse(); }
    void correct(Bodies&, double) override { refuse(); }

private:
    [[noreturn]] void refuse() const { throw std::runtime_error("client '" + id_ + "' is run by its program, not in rotbench"); }
    std::string id_;
};

bool flag(const std::string& path, const std::string& key, const toml::node& node) {
    const auto v = node.value<bool>();
    if (!v || !node.is_boolean()) toml_error(path, node, "'" + key + "' must be true or false");
    return *v;
}

int order(const std::string& path, const std::string& key, const toml::node& node) {
    const auto v = node.value<std::int64_t>();
    if (!v || !node.is_integer() || *v < 0 || *v > 8) toml_error(path, node, "'" + key + "' must be an order from 0 to 8");
    return static_cast<int>(*v);
}

SchemeClaims claims_of(const std::string& path, const toml::node& node) {
    const std::string origin = "claimed by the client file " + path;
    if (node.is_string()) {
        const std::string id = text(path, "claims", node);
        if (!SchemeRegistry::instance().contains(id) || client_of(id))
            toml_error(path, node, "claims = '" + id + "': not a built-in scheme; valid schemes: " + join(SchemeRegistry::instance().ids(), ", "));
        SchemeClaims claims = SchemeRegistry::instance().at(id, "scheme").extra;
        claims.time_reversible = false;  // a client is never run backwards
        claims.family.clear();
        for (OrderClaim* c : {&claims.without_torque, &claims.with_torque})
            if (c->order > 0) c->reason = "the claims of " + id + ": " + c->reason;
        return claims;
    }
    const toml::table* table = node.as_table();
    if (!table) toml_error(path, node, "'claims' must be a built-in scheme's id or a table");
    SchemeClaims claims;
    for (const auto& [k, v] : *table) {
        const std::string key(k.str());
        if (key == "order_without_torque") claims.without_torque = {order(path, key, v), origin};
        else if (key == "order_with_torque") claims.with_torque = {order(path, key, v), origin};
        else if (key == "exact_without_torque") claims.exact_without_torque = flag(path, key, v);
        else if (key == "conserves_momentum") claims.conserves_momentum = flag(path, key, v);
        else if (key == "bounded_energy") claims.bounded_energy = flag(path, key, v);
        else
            toml_error(path, v, "unknown key '" + key + "' in [claims]; valid keys: order_without_torque, order_with_torque, "
                                "exact_without_torque, conserves_momentum, bounded_energy");
    }
    return claims;
}


}  // namespace

const std::vector<LoadedClient>& loaded_clients() { return clients(); }

const LoadedClient* client_of(const std::string& scheme) {
    for (const auto& c : clients())
        if (c.id == scheme) return &c;
    return nullptr;
}

std::string why_not_taken(const std::string& scheme, const std::string& scene) {
    const LoadedClient* c = client_of(scheme);
    if (!c || std::find(c->scenes.begin(), c->scenes.end(), scene) != c->scenes.end()) return "";
    return "client " + scheme + " does not take scene " + scene + " (its client file lists " + join(c->scenes, ", ") + ")";
}

// The program as the run will start it, checked now: a path with a slash is taken from the working
// directory (a run starts in its scratch folder), a bare name is looked up on PATH; one that
// cannot be executed refuses the client file, naming the path, before any run.
static std::string executable(const std::string& path, const toml::node& where, const std::string& program) {
    if (program.find('/') != std::string::npos) {
        const std::string absolute = std::filesystem::absolute(program).lexically_normal().string();
        if (::access(absolute.c_str(), X_OK) != 0 || std::filesystem::is_directory(absolute))
            toml_error(path, where, "program '" + absolute + "' cannot be executed: " +
                                        (std::filesystem::exists(absolute) ? "not an executable file" : "no such file"));
        return absolute;
    }
    if (find_on_path(program).empty()) toml_error(path, where, "program '" + program + "' is not found on PATH");
    return program;
}

std::string load_client(const std::string& path) {
    const std::string bytes = read_input_file(path, "--client");
    // Symlinks resolved: the same file reached another way is loaded once, and {dir} is its real folder.
    const std::string absolute = std::filesystem::weakly_canonical(std::filesystem::absolute(path)).string(), hash = Fnv1a().feed(bytes).hex();
    for (const auto& c : clients())
        if (c.path == absolute && c.hash == hash) return c.id;  // the same file again
    const toml::table file = parse_toml_text(bytes, path);
    const toml::node* id_node = file.get("id");
    const toml::node* program_node = file.get("program");
    const toml::node* scenes_node = file.get("scenes");
    const toml::node* claims_node = file.get("claims");
    for (const auto& [key, node] : std::initializer_list<std::pair<const char*, const toml::node*>>{
             {"id", id_node}, {"program", program_node}, {"scenes", scenes_node}, {"claims", claims_node}})
        if (!node) toml_error(path, file, std::string("the client file has no '") + key + "'");
    LoadedClient client;
    client.path = absolute;
    client.hash = hash;
    client.id = text(path, "id", *id_node);
    if (!is_id(client.id)) toml_error(path, *id_node, "id '" + client.id + "' is not 1 to " + std::to_string(max_id_length) + " letters, digits and underscores");
    if (SchemeRegistry::instance().contains(client.id))
        toml_error(path, *id_node, "scheme '" + client.id + "' is already registered; give the client another id");
    const std::string dir = std::filesystem::path(absolute).parent_path().string();
    for (std::string argument : strings(path, "program", *program_node)) {
        // From after each replacement: a folder whose path holds "{dir}" is not substituted again.
        for (std::size_t at = 0; (at = argument.find("{dir}", at)) != std::string::npos; at += dir.size()) argument.replace(at, 5, dir);
        client.program.push_back(argument);
    }
    if (client.program.empty() || client.program.front().empty()) toml_error(path, *program_node, "'program' names no program");
    client.program.front() = executable(path, *program_node, client.program.front());
    // What the program is made of, so that `compare` can say when it changed: every argument that
    // names a regular file (an interpreter, an adapter script), its bytes in turn.
    Fnv1a program_hash;
    for (const auto& argument : client.program)
        feed_file(argument, program_hash);  // regular files only
    client.program_hash = program_hash.hex();
    client.scenes = ids(path, "scenes", *scenes_node, SceneRegistry::instance(), "scene");
    SchemeClaims claims = claims_of(path, *claims_node);
    std::string summary = "client (" + path + ")", notes;
    for (const auto& [k, v] : file) {
        const std::string key(k.str());
        if (key == "id" || key == "program" || key == "scenes" || key == "claims") continue;
        if (key == "summary") summary = text(path, key, v);
        else if (key == "sound") claims.sound = flag(path, key, v);
        else if (key == "unsound_reason") notes = text(path, key, v);
        else if (key == "counterpart") {
            client.counterpart = text(path, key, v);
            // A built-in runs in this process beside the client's replay; a client (another version of
            // the same code) has its program run on the same scene.json. Never a plug-in.
            if (!SchemeRegistry::instance().contains(client.counterpart) || plugin_of(client.counterpart))
                toml_error(path, v, "counterpart '" + client.counterpart + "' is neither a built-in scheme nor a client loaded before this one (--client order)");
        } else if (key == "counterpart_note") {
            client.counterpart_note = text(path, key, v);
        } else {
            toml_error(path, v, "unknown key '" + key + "'; valid keys: id, summary, program, scenes, claims, sound, unsound_reason, "
                                "counterpart, counterpart_note");
        }
    }
    if (!claims.sound && notes.empty()) toml_error(path, file, "sound = false needs an unsound_reason");
    if (!client.counterpart_note.empty() && client.counterpart.empty())
        toml_error(path, *file.get("counterpart_note"), "counterpart_note is given without a counterpart");
    if (claims.sound && !notes.empty()) toml_error(path, *file.get("unsound_reason"), "unsound_reason is given but sound is not false");
    const std::string id = client.id;
    SchemeRegistry::instance().add({id, summary, "a program outside rotbench: " + join(client.program, " "), notes,
                                    [id] { return std::make_unique<ProgramOnly>(id); }, claims});
    clients().push_back(std::move(client));
    return id;
}

}  // namespace rotbench
